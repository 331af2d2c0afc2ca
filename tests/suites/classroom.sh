#!/bin/sh
# GitHub Classroom in the instructor's kit: the runners `make grade
# CLASSROOM=file` appends for a full-marks, a partial and a zero
# submission, and one with a part that does not compile (hidden tests among
# the runners, points such as 30/14), straight from the file, totalled by
# the reporter's rules (tests/lib/classroom.sh): both of its totals are
# the kit's core score.  The student kit's workflow and runners are checked
# in the kit tests/suites/student_kit.sh builds.
#
# Usage: sh tests/suites/classroom.sh   (from the kit's top directory, after
# make).  KEEP=1 keeps the temporary directory.
set -u
. tests/lib/checks.sh
temp_dir rtclassroom
# The self-test submissions, a folder each.
selftest=$tmp/selftest
need_selftests "$selftest"
. tests/lib/classroom.sh

# ---- the instructor's kit: hidden tests, a part that does not build --------
# The runners are those the file holds (the workflow is the student kit's).
for case in full partial broken zero; do
    sub=$tmp/$case
    [ "$case" = zero ] && sub=labs
    : >"$tmp/i-$case.outputs"
    out/build/bin/grade --submission "$sub" --classroom "$tmp/i-$case.outputs" >"$tmp/i-$case.kit" 2>&1
    ids=$(cut -d= -f1 "$tmp/i-$case.outputs" | paste -s -d, -)
    awk -F= '{ id = $1; sub(/^[^=]*=/, ""); print toupper(id) "_RESULTS=" $0 }' \
        "$tmp/i-$case.outputs" >"$tmp/i-$case.env"
    want=fail
    [ "$case" = full ] && want=pass
    totals "instructor's kit, $case" "$tmp/i-$case.kit" "$ids" "$tmp/i-$case.env" "$want"
    cp "$tmp/totals.out" "$tmp/i-$case.totals"
done
# The partial submission (p1-aspect-inverted with p3a-tangent-miss): each
# runner's points as committed (Part 1 at 2.5 / 20, Part 3a at 28.33 / 30).
check_output "instructor's kit, partial: the reporter's view is tests/classroom/expected/partial.totals" \
    diff tests/classroom/expected/partial.totals "$tmp/i-partial.totals"
decode "$(cut -d= -f1 "$tmp/i-full.outputs" | paste -s -d, -)" "$tmp/i-full.env" >"$tmp/i-full.dump"
check "instructor's kit: hidden tests are among the runners" grep -q '"name":"Part 3a: hidden: ' "$tmp/i-full.dump"
decode part2test1 "$tmp/i-broken.env" >"$tmp/broken.json"
check_has "a part that does not build: its runners are errors that say so" "$tmp/broken.json" \
    '"status":"error"' 'did not build'

# ---- bad input ---------------------------------------------------------------
out/build/bin/grade --submission "$tmp/full" --classroom "$tmp/no/such/dir/file" --quiet >"$tmp/bad.out" 2>&1
status=$?
check "an unwritable CLASSROOM file: status 2 (got $status)" [ "$status" -eq 2 ]
check "an unwritable CLASSROOM file: the error names it" grep -q 'no/such/dir/file' "$tmp/bad.out"

js_checks
finish
