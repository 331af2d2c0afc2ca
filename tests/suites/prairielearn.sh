#!/bin/sh
# The PrairieLearn question, tried locally as tests/prairielearn/README.md
# says (GRADE_ROOT, and GRADE_WORK kept between runs so that the grader is
# built once).  Each run must exit 0 and leave results/results.json alone
# in results/, with what PrairieLearn reads:
#   - the reference: gradable, score 1, every test at full points;
#   - a partial submission (two self-test mistakes): byte for byte
#     expected/partial.json (Part 1 at 2.5 / 20, Part 3a at 28.33 / 30),
#     its score the kit's core score / core total, as `grade` prints them;
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
temp_dir rtprairielearn
chmod 755 "$tmp"
# The self-test submissions, a folder each.
selftest=$tmp/selftest
need_selftests "$selftest"

expected=tests/prairielearn/expected
# same FILE EXPECTED: FILE is the committed EXPECTED, or the difference is shown.
# same GOT WANT: the files are equal but for the numbers a submission's
# code returned ("got: ..." up to the line's end): those come from the
# system's maths library (tan in Part 1), whose last digit may differ
# between systems.
same() {
    sed 's/\(got: *\)[^\\"]*/\1.../g' "$1" >"$tmp/got.masked"
    sed 's/\(got: *\)[^\\"]*/\1.../g' "$2" >"$tmp/want.masked"
    cmp -s "$tmp/got.masked" "$tmp/want.masked" && return 0
    diff "$tmp/want.masked" "$tmp/got.masked" | head -n 20 | sed 's/^/    | /' >&2
    return 1
}

# ---- the question folder ----------------------------------------------------
make -s prairielearn >"$tmp/make.log" 2>&1
q=out/prairielearn/raytracer-lab
check "make prairielearn writes $q" [ -f "$q/info.json" ]
[ -f "$q/info.json" ] || { cat "$tmp/make.log"; finish; }
check "info.json: external grading with the C image, as $expected/info.json" same "$q/info.json" "$expected/info.json"
entry=$(sed -n 's/^ *"entrypoint": "\/grade\/\([^"]*\)",*$/\1/p' "$q/info.json")
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
# kept in $tmp/LABEL.json.
run() {
    label=$1
    rm -rf "$job/results"
    GRADE_ROOT="$job" GRADE_WORK="$tmp/work" sh "$job/$entry" >"$tmp/$label.log" 2>&1
    status=$?
    check "$label: the entrypoint exits 0 (got $status)" [ "$status" -eq 0 ]
    check "$label: results/ holds results.json alone ($(ls "$job/results" 2>/dev/null | tr '\n' ' '))" \
        [ "$(ls -A "$job/results" 2>/dev/null)" = "results.json" ]
    cp "$job/results/results.json" "$tmp/$label.json" 2>/dev/null || : >"$tmp/$label.json"
    check "$label: results.json is under 1 MB (PrairieLearn refuses more)" \
        [ "$(wc -c <"$tmp/$label.json")" -lt 1048576 ]
    check "$label: no 'succeeded' (PrairieLearn's grader host sets it)" \
        sh -c "! grep -q '^  \"succeeded\"' '$tmp/$label.json'"
}
# field NAME LABEL: the top-level member NAME of LABEL's results.json.
# (A member of its own line, or the first of a one-line file.)
field() { sed -n "s/^[{ ]*\"$1\": \([^,}]*\).*/\1/p" "$tmp/$2.json" | head -n 1; }

# The reference, in a folder.
mkdir -p "$job/student/my lab"
cp solutions/*.c "$job/student/my lab/"
run reference
check "reference: gradable, score 1, core points 100 / 100" \
    sh -c "[ '$(field gradable reference)' = true ] && [ '$(field score reference)' = 1 ] &&
           grep -q '\"message\": \"Core points: 100 / 100\.' '$tmp/reference.json'"
check "reference: every one of its $(grep -c '\"max_points\"' "$tmp/reference.json") tests at full points" \
    awk '/"points": / { p = $2 } /"max_points": / { n++; if (p != $2) bad = 1 } END { exit bad || n < 100 }' "$tmp/reference.json"
check "reference: the files in a folder were found" grep -q 'found: part1_image_plane.c' "$tmp/reference.log"

# A partial submission: the kit's own grader on the same files says what
# the score must be.
rm -rf "$job/student"/*
cp solutions/*.c "$job/student/"
cp "$selftest"/p1-aspect-inverted/*.c "$selftest"/p3a-tangent-miss/*.c "$job/student/"
mkdir "$tmp/partial" && cp "$job/student"/*.c "$tmp/partial/" && chmod -R a+rX "$tmp/partial"
run partial
check "partial: results.json is $expected/partial.json" same "$tmp/partial.json" "$expected/partial.json"
out/build/bin/grade --submission "$tmp/partial" >"$tmp/partial.kit" 2>&1
core=$(sed -n 's/^Score: \([^ ]*\) \/ \([^ ]*\).*/\1 \2/p' "$tmp/partial.kit")
score=$(field score partial)
# The kit prints points rounded to two decimals, without trailing zeros.
got=$(awk -v s="$score" -v c="$core" 'function pts(x,   t) { t = sprintf("%.2f", x); sub(/0+$/, "", t)
                                          sub(/[.]$/, "", t); return t }
                                      BEGIN { split(c, a, " "); printf "%s %s", pts(s * a[2]), pts(a[2]) }')
check "partial: score $score is the kit's core score over the core total ($core)" [ "$got" = "$core" ]
check "partial: partial credit" sh -c "[ '$score' != 0 ] && [ '$score' != 1 ]"
check "partial: the message gives the core points" grep -q "\"message\": \"Core points: ${core% *} / ${core#* }\." \
    "$tmp/partial.json"
check "partial: what went wrong reaches the student" grep -q 'What went wrong (probes run on your code confirmed it)' "$tmp/partial.json"

# The untouched skeleton.
rm -rf "$job/student"/*
cp labs/part*.c "$job/student/"
run skeleton
check "skeleton: gradable, score 0" sh -c "[ '$(field gradable skeleton)' = true ] && [ '$(field score skeleton)' = 0 ]"

# A folder named "x", a newline and ".." splits find's line in two, the
# second "../" and the folders below it, sorted first: named as the way
# from here to the kit's reference, it was copied as the student's file.
# Such a path is not taken.
rm -rf "$job/student"/*
fake="$job/student/x
../${PWD##*/}/solutions"
mkdir -p "$fake"
echo 'not a stage file' >"$fake/part1_image_plane.c"
run newline
check "newline: a folder named with a newline cannot make the kit's reference the student's Part 1" \
    sh -c "grep -q '^found: none of the stage files' '$tmp/newline.log' && [ '$(field gradable newline)' = false ]"

# Nothing uploaded.
rm -rf "$job/student"/*
run empty
check "empty: not gradable" [ "$(field gradable empty)" = false ]
check "empty: format_errors says the files are missing" grep -q '"format_errors": ".*missing' "$tmp/empty.json"

# Every graded part's file fails to compile.
rm -rf "$job/student"/*
for p in $parts; do
    printf 'this is not C\n' >"$job/student/$(basename labs/part${p}_*.c)"
done
run "no-compile"
check "no-compile: not gradable" [ "$(field gradable no-compile)" = false ]
check "no-compile: format_errors shows the compiler's message" grep -q '"format_errors": ".*error' "$tmp/no-compile.json"

# One part compiles: graded, that part's points only.
cp solutions/part2_pixel_coordinates.c "$job/student/"
run "one-part"
check "one-part: gradable, score 20/100" \
    sh -c "[ '$(field gradable one-part)' = true ] && [ '$(field score one-part)' = 0.2 ]"
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
cp "$broken/results/results.json" "$tmp/no-kit.json" 2>/dev/null || : >"$tmp/no-kit.json"
check "no kit: not gradable, telling the student to ask the staff" \
    sh -c "[ '$(field gradable no-kit)' = false ] &&
           grep -q 'could not grade' '$broken/results/results.json'"
check "no kit: its temporary build directory is gone" \
    [ -z "$(ls -A "$tmp/t")" ]

finish
