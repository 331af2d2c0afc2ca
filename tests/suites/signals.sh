#!/bin/sh
# Code that signals every process it may, graded as root.  As root every
# submission's code runs as the same unprivileged user, so grade --all
# grades one submission at a time unless told otherwise: code that calls
# kill(-1, SIGKILL) would stop a classmate's tests.  Graded beside the
# reference, that code must cost the reference nothing.
#
# It would stop any other suite's tests running as that user at the same
# time too, so tests/run.sh runs this suite alone, after the others.  (Not
# as another user: there it would stop this suite too.)
set -u
grade=out/build/bin/grade
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rtsignals.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
chmod 755 "$tmp"
. tests/lib/checks.sh

if [ "$(id -u)" = 0 ]; then
    mkdir -p "$tmp/killers/a-reference" "$tmp/killers/b-kill-all"
    cp solutions/part*.c "$tmp/killers/a-reference/"
    cp solutions/part*.c "$tmp/killers/b-kill-all/"
    cat >"$tmp/killers/b-kill-all/part1_image_plane.c" <<'EOF'
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"
#include <signal.h>
#include <time.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    (void)fov_degrees, (void)aspect, (void)d;
    *w = *h = 0;
    /* Every process of this user, every millisecond for 20 ms, on the
     * first call in each process: a classmate's tests running meanwhile
     * would die.  Then wrong answers, rather than looping until the time
     * limit, which would cost this suite (it runs alone) seconds for each
     * of the part's tests. */
    static int calls;
    for (int k = 0; k < 20 && calls == 0; k++) {
        kill(-1, SIGKILL);
        nanosleep(&(struct timespec){ 0, 1000000 }, NULL);
    }
    calls++;
}
EOF
    chmod -R a+rX "$tmp/killers"
    $grade --all "$tmp/killers" --out "$tmp/grades-killers" >"$tmp/killers.out" 2>&1
    check "as root, grade --all says it grades one submission at a time" \
        grep -q "one submission at a time" "$tmp/killers.out"
    check "code that signals every process costs the submission beside it nothing" \
        grep -q "^a-reference,20,20,30,30," "$tmp/grades-killers/gradebook.csv"
    check "and loses its own Part 1" grep -q "^b-kill-all,0," "$tmp/grades-killers/gradebook.csv"
else
    echo "   not root: the children run as this user; the check of signalling code was skipped"
fi

finish
