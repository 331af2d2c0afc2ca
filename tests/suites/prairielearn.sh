#!/bin/sh
# The PrairieLearn question, tried locally as tests/suites/gradescope.sh
# tries the Gradescope bundle: make prairielearn, lay the job out as the
# grading container would see it (/grade/tests: the question's tests
# folder, /grade/student: the uploads, /grade/results) in a temporary
# directory, and run the entrypoint there with GRADE_ROOT pointing at it
# (and GRADE_WORK at a build directory kept between runs, so the grader is
# built once).  Each run must exit 0 and leave results/results.json alone
# in results/, valid JSON with what PrairieLearn reads
# (tests/prairielearn/check_results.c):
#   - the reference: gradable, score 1;
#   - a partial submission: gradable, score = the kit's core score / core
#     total, as `grade` prints them for the same files;
#   - the untouched skeleton: gradable, score 0;
#   - no files, and files that all fail to compile: not gradable (nothing
#     could be tested: PrairieLearn then counts no attempt), saying why;
#   - files uploaded in a folder are found;
#   - a question folder without its kit: not gradable, saying so.
# Also info.json (external grading, the C image, the entrypoint) and
# question.html (one upload of the graded parts' files).
#
# Usage: sh tests/suites/prairielearn.sh   (from the kit's top directory,
# after make).  KEEP=1 keeps the temporary directory.
set -u
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES
. tests/lib/checks.sh
. tests/lib/cc_build.sh
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rtprairielearn.XXXXXX") || { echo "0 passed, 1 failed"; exit 1; }
trap '[ -n "${KEEP:-}" ] && echo "kept $tmp" || rm -rf "$tmp"' EXIT
chmod 755 "$tmp"

checker="$tmp/check_results"
cc_build "$tmp" check_results "$tmp/cc.log" \
    tests/prairielearn/check_results.c tests/tools/json_read.c tests/tools/utf8.c labs/kit/numtext.c
check "tests/prairielearn/check_results.c builds without a warning" [ -x "$checker" ]
[ -x "$checker" ] || { cat "$tmp/cc.log"; finish; }

# ---- the question folder ----------------------------------------------------
make -s prairielearn >"$tmp/make.log" 2>&1
q=out/prairielearn/raytracer-lab
check "make prairielearn writes $q" [ -f "$q/info.json" ]
[ -f "$q/info.json" ] || { cat "$tmp/make.log"; finish; }
"$checker" --info "$q/info.json" >"$tmp/info.out" 2>&1
check "info.json: external grading with the C image ($(cat "$tmp/info.out"))" [ $? -eq 0 ]
entry=$(sed -n 's/^image .* entrypoint \/grade\/\([^ ]*\) timeout .*/\1/p' "$tmp/info.out")  # portable: text
check "the entrypoint /grade/$entry is in the question folder" [ -f "$q/$entry" ]
parts=$(awk '$1 == "parts" { for (k = 2; k <= NF; k++) print $k }' tests/weights.conf)
want=""
for p in $parts; do
    want="$want, $(basename labs/part${p}_*.c)"
done
want=${want#, }
check "question.html: one upload of the graded parts' files ($want)" \
    grep -q "<pl-file-upload file-names=\"$want\"></pl-file-upload>" "$q/question.html"
check "question.html: the grader's results in the submission panel" \
    grep -q '<pl-external-grader-results></pl-external-grader-results>' "$q/question.html"
for f in Makefile labs/raytracer.h solutions/part1_image_plane.c tests/grader/grade_main.c \
         tests/public/part1.tests tests/hidden/hidden.c tests/weights.conf; do
    check "the question's kit has $f" [ -f "$q/tests/kit/$f" ]
done
check "the question's kit has no self-test or bench" \
    sh -c "[ ! -e '$q/tests/kit/tests/selftest' ] && [ ! -e '$q/tests/kit/tests/bench' ]"

# ---- the job, as the container sees it ---------------------------------------
job="$tmp/grade"
mkdir -p "$job/student" "$job/data"
cp -R "$q/tests" "$job/tests"
echo '{}' >"$job/data/data.json"

# run LABEL: the entrypoint on what student/ holds now; its results are
# checked and kept in $tmp/LABEL.json, the checker's line in $tmp/LABEL.check.
run() {
    label=$1
    rm -rf "$job/results"
    GRADE_ROOT="$job" GRADE_WORK="$tmp/work" sh "$job/$entry" >"$tmp/$label.log" 2>&1
    status=$?
    check "$label: the entrypoint exits 0 (got $status)" [ "$status" -eq 0 ]
    check "$label: results/ holds results.json alone ($(ls "$job/results" 2>/dev/null | tr '\n' ' '))" \
        [ "$(ls -A "$job/results" 2>/dev/null)" = "results.json" ]
    cp "$job/results/results.json" "$tmp/$label.json" 2>/dev/null
    "$checker" "$job/results/results.json" >"$tmp/$label.check" 2>&1
    check "$label: results.json has what PrairieLearn reads ($(cat "$tmp/$label.check"))" [ $? -eq 0 ]
}
field() { sed -n "s/.* $1 \([^ ]*\).*/\1/p; s/^$1 \([^ ]*\).*/\1/p" "$2" | head -n 1; }

# The reference, in a folder.
mkdir -p "$job/student/my lab"
cp solutions/*.c "$job/student/my lab/"
run reference
check "reference: gradable, score 1" \
    sh -c "[ '$(field gradable "$tmp/reference.check")' = true ] && [ '$(field score "$tmp/reference.check")' = 1 ]"
check "reference: the files in a folder were found" grep -q 'found: part1_image_plane.c' "$tmp/reference.log"
check "reference: hard cases shown, worth 0 ($(field neutral "$tmp/reference.check") of them)" \
    [ "$(field neutral "$tmp/reference.check")" -gt 0 ]

# A partial submission: the kit's own grader on the same files says what
# the score must be.
rm -rf "$job/student"/*
cp solutions/*.c "$job/student/"
cp tests/selftest/p1-aspect-inverted/*.c tests/selftest/p3a-tangent-miss/*.c "$job/student/"
mkdir "$tmp/partial" && cp "$job/student"/*.c "$tmp/partial/" && chmod -R a+rX "$tmp/partial"
run partial
out/build/bin/grade --submission "$tmp/partial" >"$tmp/partial.kit" 2>&1
core=$(sed -n 's/^Score: \([^ ]*\) \/ \([^ ]*\).*/\1 \2/p' "$tmp/partial.kit")
score=$(field score "$tmp/partial.check")
# The kit prints points rounded to two decimals, without trailing zeros.
got=$(awk -v s="$score" -v c="$core" 'function pts(x,   t) { t = sprintf("%.2f", x); sub(/0+$/, "", t)
                                          sub(/[.]$/, "", t); return t }
                                      BEGIN { split(c, a, " "); printf "%s %s", pts(s * a[2]), pts(a[2]) }')
check "partial: gradable" [ "$(field gradable "$tmp/partial.check")" = true ]
check "partial: score $score is the kit's core score over the core total ($core)" [ "$got" = "$core" ]
check "partial: partial credit" sh -c "[ '$score' != 0 ] && [ '$score' != 1 ]"
check "partial: the message gives the core points" grep -q "\"message\": \"Core points: ${core% *} / ${core#* }\." \
    "$tmp/partial.json"
check "partial: what went wrong reaches the student" grep -q 'What went wrong (probes run on your code confirmed it)' "$tmp/partial.json"

# The untouched skeleton.
rm -rf "$job/student"/*
cp labs/part*.c "$job/student/"
run skeleton
check "skeleton: gradable, score 0" \
    sh -c "[ '$(field gradable "$tmp/skeleton.check")' = true ] && [ '$(field score "$tmp/skeleton.check")' = 0 ]"

# Nothing uploaded.
rm -rf "$job/student"/*
run empty
check "empty: not gradable" [ "$(field gradable "$tmp/empty.check")" = false ]
check "empty: format_errors says the files are missing" grep -q '"format_errors": ".*missing' "$tmp/empty.json"

# Every graded part's file fails to compile.
rm -rf "$job/student"/*
for p in $parts; do
    printf 'this is not C\n' >"$job/student/$(basename labs/part${p}_*.c)"
done
run "no-compile"
check "no-compile: not gradable" [ "$(field gradable "$tmp/no-compile.check")" = false ]
check "no-compile: format_errors shows the compiler's message" grep -q '"format_errors": ".*error' "$tmp/no-compile.json"

# One part compiles: graded, that part's points only.
cp solutions/part2_pixel_coordinates.c "$job/student/"
run "one-part"
check "one-part: gradable, score 20/100" \
    sh -c "[ '$(field gradable "$tmp/one-part.check")' = true ] && [ '$(field score "$tmp/one-part.check")' = 0.2 ]"
check "one-part: the output says which files did not build and why, under their parts" \
    sh -c "grep -q 'Your part1_image_plane.c did not build, so none of its tests could run:.u000a.*error' '$tmp/one-part.json' &&
           grep -q 'Your part3a_sphere_intersect.c did not build, so none of its tests could run:.u000a.*error' '$tmp/one-part.json' &&
           ! grep -q 'Your part2_pixel_coordinates.c did not build' '$tmp/one-part.json'"

# A question folder without its kit: the grader cannot be built.
broken="$tmp/broken"
mkdir -p "$broken/tests" "$broken/student"
cp "$job/$entry" "$broken/$entry"
cp solutions/*.c "$broken/student/"
mkdir "$tmp/t"
GRADE_ROOT="$broken" TMPDIR="$tmp/t" sh "$broken/$entry" >"$tmp/broken.log" 2>&1
status=$?
check "no kit: the entrypoint exits 0 (got $status)" [ "$status" -eq 0 ]
"$checker" "$broken/results/results.json" >"$tmp/broken.check" 2>&1
check "no kit: results.json is valid ($(cat "$tmp/broken.check"))" [ $? -eq 0 ]
check "no kit: not gradable, telling the student to ask the staff" \
    sh -c "[ '$(field gradable "$tmp/broken.check")' = false ] &&
           grep -q 'could not grade' '$broken/results/results.json'"
check "no kit: its temporary build directory is gone" \
    [ -z "$(ls -A "$tmp/t")" ]

finish
