#!/bin/sh
# The grader within a small container's means (Gradescope's default has
# 768 MB): a file that makes the compiler read a device is stopped by the
# compiler's limits and costs its own part alone, quickly; a compiler or a
# test killed from outside (as by the system's out-of-memory killer) is
# reported as such and grading goes on; on Linux the compiler and the tests
# ask the out-of-memory killer to take them, not the grader.  The include
# scan's refusals themselves are unit-tested (tests/unit/test_include_scan.c);
# tests/selftest/hostile-include-dev-zero is graded by tests/suites/grader.sh.
set -u
grade=${GRADE:-out/build/bin/grade}   # make sanitize-grader: the sanitized one
. tests/lib/checks.sh
temp_dir rtlimits
chmod 755 "$tmp"

# submission NAME PART-FILE LINE...: the reference with one stage file
# replaced by the lines given.
submission() {
    dir=$tmp/$1 file=$2
    shift 2
    mkdir -p "$dir"
    cp solutions/*.c "$dir/"
    printf '%s\n' "$@" >"$dir/$file.c"
    chmod -R a+rX "$dir"
}
# The jail the runs get (tests/grader/jail.h): in the namespace jail there
# is no /proc, so the limits the runs set there are seen from outside, by
# tests/unit/test_sandbox.c.
case $($grade --jail) in namespaces*) jailed=yes ;; *) jailed=no ;; esac
# Parts 1 and 2 alone: enough to see that one part's loss stays its own.
sed 's/^parts .*/parts 1 2/' tests/weights.conf >"$tmp/parts12.conf"
part2_body='Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{ return vec3((2.0 * i + 1 - nx) * (w / (2.0 * nx)), (ny - 1 - 2.0 * j) * (h / (2.0 * ny)), -d); }'

# -- a device named through a macro: past the scan, stopped by the limits ----
submission macro-dev-zero part2_pixel_coordinates '#include "raytracer.h"' \
    '#define DEVICE "/dev/zero"' '#include DEVICE' "$part2_body"
start=$(date +%s)
$grade --submission "$tmp/macro-dev-zero" --weights "$tmp/parts12.conf" --summary >"$tmp/macro.out" 2>&1
status=$?
took=$(( $(date +%s) - start ))
check "a macro include of /dev/zero: graded (exit $status, want 1)" [ "$status" -eq 1 ]
# clang reads a device as empty (the file then compiles); gcc reads until its memory limit.
if grep -q 'did not build' "$tmp/macro.out"; then
    check "a macro include of /dev/zero loses Part 2 alone" grep -q '^summary 20 0 0 0 ' "$tmp/macro.out"
    check "the compiler's own message is shown" grep -q -i -e memory -e stopped "$tmp/macro.out"
else
    check "a macro include of /dev/zero read as empty keeps every part" grep -q '^summary 20 20 0 0 ' "$tmp/macro.out"
fi
check "a macro include of /dev/zero is over in ${took} s (want under 15)" [ "$took" -lt 15 ]
echo "   graded the macro include of /dev/zero in ${took} s"

# -- a compiler killed from outside -------------------------------------------
# A stand-in compiler that says what the out-of-memory killer would think of
# it, then is killed by SIGKILL.  It runs as the compiler does (as "nobody"
# when the grader is root), so it must be readable by all.
cat >"$tmp/killed-cc" <<'EOF'
#!/bin/sh
if [ -r /proc/self/oom_score_adj ]; then     # portable: Linux only, guarded
    read adj </proc/self/oom_score_adj        # portable: guarded
    echo "oom_score_adj $adj"
fi
kill -9 $$
EOF
chmod 755 "$tmp/killed-cc"
CC=$tmp/killed-cc $grade --submission solutions --part 1 --results "$tmp/killed-cc.json" >"$tmp/killed-cc.out" 2>&1
status=$?
check "a killed compiler: graded (exit $status, want 1)" [ "$status" -eq 1 ]
check "a killed compiler: results.json written" grep -q '"tests"' "$tmp/killed-cc.json"
check "a killed compiler is reported as killed" grep -q 'the compiler was killed (signal 9)' "$tmp/killed-cc.out"
if [ "$jailed" = yes ]; then
    check "in the namespace jail the compiler sees no /proc (its oom_score_adj: test_sandbox)" \
        sh -c "! grep -q 'oom_score_adj' '$tmp/killed-cc.out'"
elif [ -r /proc/self/oom_score_adj ]; then     # portable: Linux only, guarded
    check "the compiler asks the out-of-memory killer to take it (oom_score_adj 1000)" \
        grep -q 'oom_score_adj 1000' "$tmp/killed-cc.out"
else
    echo "   skipped oom_score_adj: no /proc/self/oom_score_adj on this system"   # portable: a message
fi

# -- a test killed from outside -------------------------------------------------
# Part 1's test program prints its own oom_score_adj, then is killed by
# SIGKILL; Part 2 is graded after it, as always.
submission killed-test part1_image_plane
cat >"$tmp/killed-test/part1_image_plane.c" <<'EOF'
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"
#include <signal.h>
#include <stdio.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    char adj[16] = "none";
    FILE *f = fopen("/proc/self/oom_score_adj", "r");      /* portable: "none" elsewhere */
    if (f) {
        if (!fgets(adj, sizeof adj, f))
            adj[0] = '\0';
        fclose(f);
    }
    printf("oom_score_adj %s\n", adj);
    fflush(stdout);
    raise(SIGKILL);
    *w = *h = fov_degrees + aspect + d;
}
EOF
$grade --submission "$tmp/killed-test" --weights "$tmp/parts12.conf" --summary >"$tmp/killed-test.out" 2>&1
status=$?
check "a killed test: graded (exit $status, want 1)" [ "$status" -eq 1 ]
check "a killed test is reported as killed from outside" grep -q 'signal 9 (SIGKILL: killed from outside' "$tmp/killed-test.out"
if [ "$jailed" = yes ]; then
    check "in the namespace jail the test sees no /proc (its oom_score_adj: test_sandbox)" \
        grep -q 'oom_score_adj none' "$tmp/killed-test.out"
elif [ -r /proc/self/oom_score_adj ]; then     # portable: Linux only, guarded
    check "the test program asks the out-of-memory killer to take it (oom_score_adj 1000)" \
        grep -q 'oom_score_adj 1000' "$tmp/killed-test.out"
fi
check "a killed test loses Part 1 alone, and Part 2 is graded after it" \
    grep -q '^summary 0 20 0 0 ' "$tmp/killed-test.out"

# -- wherever TMPDIR puts the compile folders ---------------------------------
# Each part is compiled in a folder under TMPDIR that holds copies of the
# kit's headers: they are the build's own wherever that folder is.  Inside
# the kit, and under /dev (TMPDIR=/dev/shm), both once refused raytracer.h
# in every part (0 for the reference).  A file of the kit named by its path
# stays refused.
submission include-kit part1_image_plane "#include \"$PWD/solutions/part1_image_plane.c\""
mkdir -p out/tests/tmpdir-in-kit
for where in "$PWD/out/tests/tmpdir-in-kit" /dev/shm; do
    if [ ! -d "$where" ] || [ ! -w "$where" ]; then
        echo "   skipped: no $where to write in"
        continue
    fi
    t=$(mktemp -d "$where/rtlimits.XXXXXX") || { fail "cannot make a folder in $where"; continue; }
    chmod 755 "$t"
    TMPDIR=$t $grade --submission solutions --part 1 --summary >"$tmp/where.out" 2>&1
    check "TMPDIR in $where: the reference keeps Part 1's marks" grep -q '^summary 20 0 0 0 ' "$tmp/where.out"
    TMPDIR=$t $grade --submission "$tmp/include-kit" --part 1 --summary >"$tmp/where.out" 2>&1
    check "TMPDIR in $where: a file of the kit named by its path is still refused" \
        grep -q 'which is part of the grader' "$tmp/where.out"
    rm -rf "$t"
done

# -- a compiler the jail cannot start --------------------------------------------
# A compiler inside the kit: the jail shows it none of the kit (and, in the
# fallback, the kit is private), so it cannot be started.  That is the
# kit's error, not the student's: the grader says so, with the command and
# its exit status, exits 2, and the results file scores nothing as the
# submission's fault.
mkdir -p out/tests/cc-in-kit
printf '#!/bin/sh\nexec cc "$@"\n' >out/tests/cc-in-kit/cc
chmod 755 out/tests/cc-in-kit/cc
CC=$PWD/out/tests/cc-in-kit/cc $grade --submission solutions --part 1 --results "$tmp/no-cc.json" \
    >"$tmp/no-cc.out" 2>&1
status=$?
check "a compiler that cannot be started: the grader's error (exit $status, want 2)" [ "$status" -eq 2 ]
check "... named with the command and its exit status, as the kit's error" \
    grep -q "the compiler could not be started ($PWD/out/tests/cc-in-kit/cc, exit status 12[5-7].*the kit's error, not the submission's" "$tmp/no-cc.out"
check_has "... and the results file says so, with no test failed as the student's" "$tmp/no-cc.json" \
    'the compiler could not be started' '"tests": \[\]'

finish
