#!/bin/sh
# Code that signals every process it may, graded as root beside a
# classmate's: as root each submission graded at once runs its code as an
# id of its own (tests/grader/README.md, "Whose code runs as whom"), so
# kill(-1, SIGKILL) reaches only its own processes.  Here the code does so
# for 0.6 s, in the first call of its Part 1 batch (its answers are right:
# it passes), while the classmate's Part 1 batch sleeps 0.9 s in its own
# first call: graded two at once, they overlap, and the classmate must keep
# every part.  At the same time the two are graded again, as two classes
# of one, by two more runs of grade --all, and alone, by two runs of
# grade --submission, which as root also take an id of their own.
#
# So it runs beside the other suites, which grade as ids they hold
# themselves (or as nobody, where the system gives none).  Where the system gives no spare ids it is skipped, and
# the code never signals as nobody, whose processes may be the other
# suites' tests.  (Nor as another user: there it would stop this suite
# too.)
set -u
grade=${GRADE:-out/build/bin/grade}   # make sanitize-grader: the sanitized one
. tests/lib/checks.sh
temp_dir rtsignals
chmod 755 "$tmp"

# As root, the code runs only where grade --all gives each submission an
# id of its own and holds it against the other suites' gradings: two empty
# submissions, graded first, show it.  (Where the system gives no spare
# ids, grade --all grades one at a time as nobody: nothing would be tested,
# and the code would signal the other suites' tests.)
if [ "$(id -u)" = 0 ]; then
    mkdir -p "$tmp/empty/a" "$tmp/empty/b"
    chmod -R a+rX "$tmp/empty"
    $grade --all "$tmp/empty" --out "$tmp/grades-empty" --jobs 2 >"$tmp/empty.out" 2>&1
fi
if [ "$(id -u)" != 0 ]; then
    echo "   not root: the children run as this user; the check of signalling code was skipped"
elif grep -q "^grade: 1 submission at a time, not 2: " "$tmp/empty.out"; then
    echo "   this system gives no spare user ids: grade --all grades one at a time, as nobody; the check of signalling code was skipped"
elif grep -q "may be given the same users" "$tmp/empty.out"; then
    sed 's/^/   /' "$tmp/empty.out" | grep "may be given"
    echo "   the ids are not held against other gradings here: the check of signalling code was skipped"
else
    # Each: the reference's Part 1, renamed, behind a first call that
    # sleeps or signals; the reference's other parts.
    nobody=$(id -u nobody 2>/dev/null || echo 65534)
    for who in a-sleeper b-kill-all; do
        mkdir -p "$tmp/killers/$who"
        cp solutions/part*.c "$tmp/killers/$who/"
        sed 's/^void image_plane_size(/static void reference_image_plane_size(/' \
            solutions/part1_image_plane.c >"$tmp/killers/$who/part1_image_plane.c"
    done
    cat >>"$tmp/killers/a-sleeper/part1_image_plane.c" <<'EOF'

#include <time.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    static int calls;
    if (calls++ == 0)
        nanosleep(&(struct timespec){ 0, 900000000 }, NULL);
    reference_image_plane_size(fov_degrees, aspect, d, w, h);
}
EOF
    cat >>"$tmp/killers/b-kill-all/part1_image_plane.c" <<'EOF'

#include <signal.h>
#include <time.h>
#include <unistd.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    /* Every process of this user, every millisecond for 0.6 s; not as
     * nobody, whose processes may be other suites' tests. */
    static int calls;
    for (int k = 0; k < 600 && calls == 0 && getuid() != NOBODY; k++) {
        kill(-1, SIGKILL);
        nanosleep(&(struct timespec){ 0, 1000000 }, NULL);
    }
    calls++;
    reference_image_plane_size(fov_degrees, aspect, d, w, h);
}
EOF
    sed "s/NOBODY/$nobody/" "$tmp/killers/b-kill-all/part1_image_plane.c" >"$tmp/kill.c" &&
        mv "$tmp/kill.c" "$tmp/killers/b-kill-all/part1_image_plane.c"
    # The same two also as two classes of one, graded by two more runs of
    # grade --all at the same time: each run holds its ids against the
    # others.
    for who in a-sleeper b-kill-all; do
        mkdir "$tmp/class-$who"
        cp -R "$tmp/killers/$who" "$tmp/class-$who/"
    done
    # A submission graded alone, as root, runs its code as a user of its
    # own too: this one's Part 1 is right only when its code does not run
    # as nobody.
    mkdir -p "$tmp/not-nobody"
    cp solutions/part*.c "$tmp/not-nobody/"
    sed 's/^void image_plane_size(/static void reference_image_plane_size(/' \
        solutions/part1_image_plane.c >"$tmp/not-nobody/part1_image_plane.c"
    cat >>"$tmp/not-nobody/part1_image_plane.c" <<EOF

#include <unistd.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    reference_image_plane_size(fov_degrees, aspect, d, w, h);
    if (getuid() == $nobody)
        *w = *h = 0;
}
EOF
    chmod -R a+rX "$tmp/killers" "$tmp"/class-* "$tmp/not-nobody"
    $grade --all "$tmp/class-b-kill-all" --out "$tmp/grades-b" --jobs 1 >"$tmp/b.out" 2>&1 &
    $grade --all "$tmp/class-a-sleeper" --out "$tmp/grades-a" --jobs 1 >"$tmp/a.out" 2>&1 &
    # And the two graded alone, by two more gradings at the same time.
    $grade --submission "$tmp/killers/b-kill-all" --quiet --summary >"$tmp/b-alone.out" 2>&1 &
    $grade --submission "$tmp/killers/a-sleeper" --quiet --summary >"$tmp/a-alone.out" 2>&1 &
    $grade --all "$tmp/killers" --out "$tmp/grades-killers" --jobs 2 >"$tmp/killers.out" 2>&1
    wait
    $grade --submission "$tmp/not-nobody" --part 1 --quiet --summary >"$tmp/not-nobody.out" 2>&1
    check "as root, a submission graded alone runs its code as a user of its own, not nobody" \
        grep -q "^summary 20 " "$tmp/not-nobody.out"
    check "code that signals every process costs a submission graded alone at the same time nothing" \
        grep -q "^summary 20 20 30 30 " "$tmp/a-alone.out"
    check "and, graded alone, keeps its own marks" grep -q "^summary 20 20 30 30 " "$tmp/b-alone.out"
    check "as root, grade --all --jobs 2 runs each submission's code as a user of its own" \
        grep -q "^graded 2 at a time, as root: each one's code ran as an unprivileged user of its own$" \
        "$tmp/killers.out"
    check "code that signals every process costs the submission graded beside it nothing" \
        grep -q "^a-sleeper,20,20,30,30,.*,full marks$" "$tmp/grades-killers/gradebook.csv"
    check "and, its answers right, keeps its own marks" \
        grep -q "^b-kill-all,20,20,30,30,.*,full marks$" "$tmp/grades-killers/gradebook.csv"
    check "code that signals every process costs a class graded by another run at the same time nothing" \
        grep -q "^a-sleeper,20,20,30,30,.*,full marks$" "$tmp/grades-a/gradebook.csv"
    check "and, graded by its own run, keeps its own marks" \
        grep -q "^b-kill-all,20,20,30,30,.*,full marks$" "$tmp/grades-b/gradebook.csv"
    [ "$failed" -eq 0 ] || sed 's/^/    | /' "$tmp/killers.out" "$tmp/grades-killers/gradebook.csv" \
        "$tmp/a.out" "$tmp/grades-a/gradebook.csv" "$tmp/b.out" "$tmp/grades-b/gradebook.csv" \
        "$tmp/a-alone.out" "$tmp/b-alone.out" "$tmp/not-nobody.out"
fi

finish
