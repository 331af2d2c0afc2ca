#!/bin/sh
# The Gradescope bundle, tried locally through AUTOGRADER_ROOT: build the
# zip, unpack it as Gradescope does, run setup.sh, then run_autograder on a
# correct submission tucked in a folder, on an empty one, and with a grader
# that cannot run.  Each must leave a valid results.json.
set -u
. tests/lib/checks.sh
temp_dir rtgradescope
chmod 755 "$tmp"

make -s gradescope >"$tmp/make.log" 2>&1
check "make gradescope" [ -f out/gradescope/autograder.zip ]
out/build/bin/pack list out/gradescope/autograder.zip >"$tmp/list" 2>&1
check "setup.sh at the zip's root" grep -q ' setup.sh$' "$tmp/list"
check "run_autograder at the zip's root" grep -q ' run_autograder$' "$tmp/list"

ag="$tmp/ag"
mkdir -p "$ag/source" "$ag/submission/my work/lab" "$ag/results"
out/build/bin/pack unzip out/gradescope/autograder.zip "$ag/source" >/dev/null
check "run_autograder is executable after unzipping" [ -x "$ag/source/run_autograder" ]
cp "$ag/source/run_autograder" "$ag/run_autograder"
(cd "$ag/source" && AUTOGRADER_ROOT="$ag" sh ./setup.sh) >"$tmp/setup.log" 2>&1
check "setup.sh builds the grader" [ -x "$ag/source/out/build/bin/grade" ]
[ -x "$ag/source/out/build/bin/grade" ] || tail -n 20 "$tmp/setup.log"

# A correct submission, uploaded inside folders.
cp solutions/*.c "$ag/submission/my work/lab/"
AUTOGRADER_ROOT="$ag" "$ag/run_autograder" >"$tmp/run1.log" 2>&1
check "run_autograder exits 0" [ $? -eq 0 ]
check "results.json for a correct submission" grep -q '"score": 1[01][0-9]' "$ag/results/results.json"
check "every test passed" sh -c "! grep -q '\"status\": \"failed\"' '$ag/results/results.json'"
check "hidden tests are after_published" grep -q '"visibility": "after_published"' "$ag/results/results.json"
check "hard tests are tagged" grep -q '"hard"' "$ag/results/results.json"
check "the summary the student reads starts with the score, and names no temporary folder" \
    sh -c "grep -m 1 '\"output\": ' '$ag/results/results.json' | grep -q '\"output\": \"Score: 1[01][0-9] / ' &&
           ! grep -q 'submission\.' '$ag/results/results.json'"
check "Parts 4 and 5 are not graded by default" sh -c "! grep -q '\"Part [45]: ' '$ag/results/results.json'"

# With Parts 4 and 5 turned on in the bundle's weights.conf, they are graded
# too, from the same upload.
sed 's/^parts .*/parts 1 2 3a 3b 4 5/' "$ag/source/tests/weights.conf" >"$tmp/weights.conf"
chmod u+w "$ag/source/tests/weights.conf" 2>/dev/null
cp "$ag/source/tests/weights.conf" "$tmp/weights.default"
cp "$tmp/weights.conf" "$ag/source/tests/weights.conf"
rm -f "$ag/results/results.json"
AUTOGRADER_ROOT="$ag" "$ag/run_autograder" >"$tmp/run45.log" 2>&1
check_has "Parts 4 and 5 graded when turned on" "$ag/results/results.json" '"Part 4: ' '"Part 5: '
check "every test passed with Parts 4 and 5" sh -c "! grep -q '\"status\": \"failed\"' '$ag/results/results.json'"
cp "$tmp/weights.default" "$ag/source/tests/weights.conf"

# A repository made from the student kit, uploaded whole: its labs/ holds
# the work, and a stale copy elsewhere (first by name) is not taken; a
# file at the top is taken before either; a link is never followed.
rm -rf "$ag/submission"/* "$ag/results/results.json"
mkdir -p "$ag/submission/backup" "$ag/submission/labs"
cp labs/part*.c "$ag/submission/backup/"
cp solutions/part*.c "$ag/submission/labs/"
cp labs/part2_pixel_coordinates.c "$ag/submission/"
ln -s "$PWD/solutions/part1_image_plane.c" "$ag/submission/part1_image_plane.c"
AUTOGRADER_ROOT="$ag" "$ag/run_autograder" >"$tmp/run-repo.log" 2>&1
check "a repository uploaded whole: labs/ is graded, not a stale copy elsewhere" \
    grep -q '^found: labs/part1_image_plane.c part2_pixel_coordinates.c labs/part3a' "$tmp/run-repo.log"
check_has "... with its scores (Part 1 from labs/, Part 2 the skeleton's at the top)" "$ag/results/results.json" \
    'Part 1: 20 / 20' 'Part 2: 0 / 20'
[ "$failed" -eq 0 ] || cat "$tmp/run-repo.log"

# An upload whose labs is a link to the kit's reference gets nothing from it.
rm -rf "$ag/submission"/* "$ag/results/results.json"
ln -s "$ag/source/solutions" "$ag/submission/labs"
AUTOGRADER_ROOT="$ag" "$ag/run_autograder" >"$tmp/run-link.log" 2>&1
check "an upload whose labs is a link to the reference: nothing taken from it" \
    sh -c "grep -q '^found: none of the stage files' '$tmp/run-link.log' && grep -q '\"score\": 0' '$ag/results/results.json'"
rm -f "$ag/submission/labs"

# A folder whose name ends in a newline splits find's line in two, the
# second a path of the folders below it: one named as the kit's reference,
# shallower than the file itself, was copied in its place.  Such a path is
# not taken.
rm -rf "$ag/submission"/* "$ag/results/results.json"
nl='
'
fake="$ag/submission/a/b/c/d/e/f/g/h/x$nl$ag/source/solutions"
mkdir -p "$fake"
echo 'not a stage file' >"$fake/part1_image_plane.c"
AUTOGRADER_ROOT="$ag" "$ag/run_autograder" >"$tmp/run-newline.log" 2>&1
check "a folder named with a newline cannot make the kit's reference the student's Part 1" \
    sh -c "grep -q '^found: none of the stage files' '$tmp/run-newline.log' && grep -q '\"score\": 0' '$ag/results/results.json'"

# Files under another name, as a browser names a second download and as
# editors capitalise: 0 for those parts, and the message names the files.
rm -rf "$ag/submission"/* "$ag/results/results.json"
mkdir -p "$ag/submission/work"
cp solutions/part1_image_plane.c "$ag/submission/part1_image_plane (1).c"
cp solutions/part2_pixel_coordinates.c "$ag/submission/work/Part2_Pixel_Coordinates.c"
AUTOGRADER_ROOT="$ag" "$ag/run_autograder" >"$tmp/run-names.log" 2>&1
check "a stage file under another name is named in the message: 'it has part1_image_plane (1).c'" \
    grep -q 'the submission has no part1_image_plane.c; it has part1_image_plane (1).c: hand it in as part1_image_plane.c' \
    "$ag/results/results.json"
check "... from a folder too, whatever its letters' case" \
    grep -q 'it has Part2_Pixel_Coordinates.c: hand it in as part2_pixel_coordinates.c' "$ag/results/results.json"
check "... and such files are not graded" grep -q '"score": 0' "$ag/results/results.json"
# A C file named for its part alone: named too; a part10 file is not Part 1's.
rm -rf "$ag/submission"/* "$ag/results/results.json"
mkdir -p "$ag/submission/lab"
cp solutions/part1_image_plane.c "$ag/submission/lab/Part1.c"
cp solutions/part3a_sphere_intersect.c "$ag/submission/part3a.C"
cp solutions/part1_image_plane.c "$ag/submission/part10.c"
echo notes >"$ag/submission/part2_notes.txt"
AUTOGRADER_ROOT="$ag" "$ag/run_autograder" >"$tmp/run-parts.log" 2>&1
check_has "a C file named for its part alone is named in the message: 'it has Part1.c', 'it has part3a.C'" \
    "$ag/results/results.json" \
    'the submission has no part1_image_plane.c; it has Part1.c: hand it in as part1_image_plane.c' \
    'it has part3a.C: hand it in as part3a_sphere_intersect.c'
check "... but not a part10 file, nor a file that is not C" \
    sh -c "! grep -q 'it has part10.c' '$ag/results/results.json' && ! grep -q 'part2_notes' '$ag/results/results.json'"

# An empty submission: every part missing, score 0, still a valid file.
rm -rf "$ag/submission"/* "$ag/results/results.json"
AUTOGRADER_ROOT="$ag" "$ag/run_autograder" >"$tmp/run2.log" 2>&1
check "results.json for an empty submission" grep -q '"score": 0' "$ag/results/results.json"
check "it says the files are missing" grep -q 'missing' "$ag/results/results.json"

# A grader that cannot run still leaves results.json.
broken="$tmp/broken"
mkdir -p "$broken/source" "$broken/submission" "$broken/results"
cp "$ag/run_autograder" "$broken/"
AUTOGRADER_ROOT="$broken" "$broken/run_autograder" >"$tmp/run3.log" 2>&1
check "results.json when the grader cannot run" grep -q 'could not grade' "$broken/results/results.json"

finish
