#!/bin/sh
# make sort-submissions: a class's download from Canvas, Moodle or Blackboard (one zip,
# or folder, of every student's files, each named for its student), sorted
# into one folder per submission, then graded by make grade-all.  The
# downloads are made here in the platforms' own naming (lmsname.h): Canvas's
# NAME_USERID_FILEID_FILE with LATE_ and "-1" (and anonymous grading's
# anon_ANONID_FILEID_FILE), Blackboard's attempts, Moodle's folders and
# its flat form.  Then what must be refused, with nothing written: a TO that
# is not new, a download with no such names; and what grade-all says when
# it is given the download itself.
set -u
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES
. tests/lib/checks.sh
temp_dir rtsort
pack=out/build/bin/pack
sortsubs=${SORTSUBS:-out/build/bin/sortsubs}   # make sanitize-grader: the sanitized one
grade=${GRADE:-out/build/bin/grade}
need_built "$sortsubs" "$pack" "$grade"
selftest=$tmp/selftest
need_selftests "$selftest"
sort_subs() {   # sort_subs FROM TO: the sorter, its output in $tmp/out, its exit in status
    "$sortsubs" "$1" "$2" >"$tmp/out" 2>&1
    status=$?
}
make_sort() {   # make_sort VAR=VALUE...: make sort-submissions, as sort_subs
    make -s --no-print-directory sort-submissions "$@" >"$tmp/out" 2>&1
    status=$?
}
folders() {     # folders DIR: the names of DIR's folders, each followed by a space
    (cd "$1" && ls -d */ | tr -d / | tr '\n' ' ')
}

# ---- Canvas: a reference, a late one uploaded again, a stray file ------------
dl=$tmp/canvas
mkdir "$dl"
for f in solutions/part1_image_plane.c solutions/part2_pixel_coordinates.c \
         solutions/part3a_sphere_intersect.c solutions/part3b_ray_color.c; do
    b=${f##*/}
    cp "$f" "$dl/smithbob_340934_208490284_$b"
    cp "$f" "$dl/wellslane_LATE_334244_394803489_$b"
done
# wellslane uploaded Part 1 again: the skeleton first, the reference after it
cp labs/part1_image_plane.c "$dl/wellslane_LATE_334244_394803489_part1_image_plane.c"
cp solutions/part1_image_plane.c "$dl/wellslane_LATE_334244_394803489_part1_image_plane-1.c"
cp "$selftest"/p2-no-half/part2_pixel_coordinates.c "$dl/leeann_77_88_part2_pixel_coordinates.c"
echo notes >"$dl/leeann_77_88_notes-2.txt"
echo stray >"$dl/README.txt"
mkdir "$dl/__MACOSX" && echo x >"$dl/__MACOSX/._smithbob_340934_208490284_part1_image_plane.c"
echo x >"$dl/.DS_Store"
$pack zip "$tmp/canvas.zip" "$dl" >/dev/null 2>&1

make_sort FROM="$tmp/canvas.zip" TO="$tmp/sorted"
check "a Canvas zip, through make sort-submissions: sorted (exit 0)" [ "$status" -eq 0 ]
check "each submission in a folder of its own, named for the student and the user id" \
    [ "$(folders "$tmp/sorted")" = 'leeann_77 smithbob_340934 wellslane_334244 ' ]
check "the files get their own names back" \
    sh -c "cmp -s solutions/part3a_sphere_intersect.c '$tmp/sorted/smithbob_340934/part3a_sphere_intersect.c' &&
           [ -f '$tmp/sorted/leeann_77/notes-2.txt' ] && [ \$(ls '$tmp/sorted/smithbob_340934' | wc -l) -eq 4 ]"
check "a file uploaded again: the later upload (\"-1\") is kept, and the run says so" \
    sh -c "cmp -s solutions/part1_image_plane.c '$tmp/sorted/wellslane_334244/part1_image_plane.c' &&
           grep -q 'wellslane_334244/part1_image_plane.c: kept the later upload, wellslane_LATE_334244_394803489_part1_image_plane-1.c; left out wellslane_LATE_334244_394803489_part1_image_plane.c' '$tmp/out'"
check "the late submission is counted" grep -q '1 of them late' "$tmp/out"
check "a file not named as a download names them is named, and not sorted" \
    sh -c "grep -q 'not sorted.*: README.txt\$' '$tmp/out' && [ ! -e '$tmp/sorted/README.txt' ]"
check "the system's own files are left out" \
    sh -c "grep -q 'left out 2 files of the system' '$tmp/out' && ! grep -rq . '$tmp/sorted/__MACOSX' 2>/dev/null"
check_has "sorted.txt says where each file came from" "$tmp/sorted/sorted.txt" \
    '^smithbob_340934/part2_pixel_coordinates.c	smithbob_340934_208490284_part2_pixel_coordinates.c$' \
    '^(left out)	wellslane_LATE_334244_394803489_part1_image_plane.c	(late)	(an earlier upload' \
    '^(not sorted)	README.txt$'
check "it ends with the next step, the command that grades them" \
    sh -c "tail -n 1 '$tmp/out' | grep -qx 'to grade them: make grade-all SUBMISSIONS=$tmp/sorted'"
check "no temporary folder is left beside it" sh -c "! ls -d '$tmp'/sorted.sorting.* >/dev/null 2>&1"

# The same download unpacked into a folder: the same folders and files.
sort_subs "$dl" "$tmp/sorted-dir"
check "a Canvas download's folder: the same as its zip" \
    sh -c "[ $status -eq 0 ] && cd '$tmp' && [ \"\$(find sorted -type f | sed 's|^sorted/||' | grep -v sorted.txt | sort)\" = \"\$(find sorted-dir -type f | sed 's|^sorted-dir/||' | grep -v sorted.txt | sort)\" ]"

# With anonymous grading Canvas writes anon_ and the submission's
# anonymous id where the name and user id were (LATE_ first when late).
a=$tmp/canvas-anonymous
mkdir "$a"
cp solutions/part1_image_plane.c "$a/anon_Xy3Ab_208490284_part1_image_plane.c"
cp solutions/part2_pixel_coordinates.c "$a/anon_Xy3Ab_208490285_part2_pixel_coordinates.c"
cp solutions/part1_image_plane.c "$a/LATE_anon_9kPqR_394803489_part1_image_plane.c"
sort_subs "$a" "$tmp/sorted-anon"
check "a Canvas download graded anonymously: a folder per anonymous id, the files under their own names" \
    sh -c "[ $status -eq 0 ] && [ '$(folders "$tmp/sorted-anon")' = 'anon_9kPqR anon_Xy3Ab ' ] &&
           cmp -s solutions/part2_pixel_coordinates.c '$tmp/sorted-anon/anon_Xy3Ab/part2_pixel_coordinates.c' &&
           grep -q '1 of them late' '$tmp/out'"

# Graded as a class.
make -s --no-print-directory grade-all SUBMISSIONS="$tmp/sorted" OUT="$tmp/grades" >"$tmp/grade.out" 2>&1
book=$tmp/grades/gradebook.csv
check_has "grade-all grades the sorted folders: the reference and the later upload keep full marks" "$book" \
    '^smithbob_340934,20,20,30,30,.*full marks$' '^wellslane_334244,20,20,30,30,.*full marks$'
check "grade-all grades the sorted folders: a Part 2 mistake loses Part 2 alone, the missing parts theirs" \
    sh -c "grep -q '^leeann_77,0,[0-9.]*,0,0,' '$book' && ! grep -q '^leeann_77,0,20,' '$book'"

# ---- Moodle: folders (the default) and the flat form ------------------------
m=$tmp/moodle
mkdir -p "$m/Ann Lee_123456_assignsubmission_file_" "$m/Bo Chen_654321_assignsubmission_file_"
cp solutions/part1_image_plane.c "$m/Ann Lee_123456_assignsubmission_file_/"
cp solutions/part2_pixel_coordinates.c "$m/Bo Chen_654321_assignsubmission_file_/"
cp solutions/part3a_sphere_intersect.c "$m/Cy Diaz_111_assignsubmission_file_part3a_sphere_intersect.c"
$pack zip "$tmp/moodle.zip" "$m" >/dev/null 2>&1
sort_subs "$tmp/moodle.zip" "$tmp/msorted"
check "a Moodle zip, with folders and without: sorted (exit 0)" [ "$status" -eq 0 ]
check "Moodle: a folder per submission, named for the student and the participant id" \
    sh -c "[ -f '$tmp/msorted/Ann Lee_123456/part1_image_plane.c' ] && [ -f '$tmp/msorted/Bo Chen_654321/part2_pixel_coordinates.c' ] &&
           [ -f '$tmp/msorted/Cy Diaz_111/part3a_sphere_intersect.c' ] && grep -q 'of a Moodle download into 3 submission folders' '$tmp/out'"

# ---- Blackboard: every attempt downloaded, each with its text file ----------
b=$tmp/blackboard
mkdir "$b"
early=2024-03-15-10-30-00 late=2024-03-16-09-05-59
for f in solutions/part1_image_plane.c solutions/part2_pixel_coordinates.c; do
    cp "$f" "$b/Ray Tracing Lab_jsmith_attempt_${late}_${f##*/}"
done
# jsmith's first attempt: the skeleton's Part 1 and a file the second lacks
cp labs/part1_image_plane.c "$b/Ray Tracing Lab_jsmith_attempt_${early}_part1_image_plane.c"
echo draft >"$b/Ray Tracing Lab_jsmith_attempt_${early}_notes.txt"
cp solutions/part3a_sphere_intersect.c "$b/Ray Tracing Lab_20103940_attempt_${early}_part3a_sphere_intersect.c"
for a in "jsmith_attempt_$early" "jsmith_attempt_$late" "20103940_attempt_$early"; do
    printf 'Name: A Student (%s)\nAssignment: Ray Tracing Lab\n' "${a%%_*}" >"$b/Ray Tracing Lab_$a.txt"
done
$pack zip "$tmp/blackboard.zip" "$b" >/dev/null 2>&1
sort_subs "$tmp/blackboard.zip" "$tmp/bsorted"
check "a Blackboard zip: a folder per username, the files under their own names" \
    sh -c "[ $status -eq 0 ] && [ '$(folders "$tmp/bsorted")' = '20103940 jsmith ' ] &&
           cmp -s solutions/part2_pixel_coordinates.c '$tmp/bsorted/jsmith/part2_pixel_coordinates.c' &&
           grep -q 'of a Blackboard download into 2 submission folders' '$tmp/out'"
check "Blackboard, every attempt: the latest attempt's files are kept, the earlier's left out, and the run says so" \
    sh -c "cmp -s solutions/part1_image_plane.c '$tmp/bsorted/jsmith/part1_image_plane.c' && [ ! -e '$tmp/bsorted/jsmith/notes.txt' ] &&
           grep -q 'jsmith: kept the latest attempt, $late; left out 3 files of earlier attempts' '$tmp/out' &&
           grep -q '^(left out)	Ray Tracing Lab_jsmith_attempt_${early}_notes.txt	(of an earlier attempt)\$' '$tmp/bsorted/sorted.txt'"
check "Blackboard: each attempt's own text file is kept beside its files, named for its date" \
    sh -c "[ -f '$tmp/bsorted/jsmith/attempt_$late.txt' ] && [ ! -e '$tmp/bsorted/jsmith/attempt_$early.txt' ] &&
           [ -f '$tmp/bsorted/20103940/attempt_$early.txt' ]"

# Usernames with "_" in them, of an assignment with "_" in its name: two
# students' files are not taken for one student's attempts.
u=$tmp/underscores
mkdir "$u"
cp labs/part1_image_plane.c "$u/Ray_Tracing Lab_j_smith_attempt_${early}_part1_image_plane.c"
cp solutions/part1_image_plane.c "$u/Ray_Tracing Lab_k_smith_attempt_${late}_part1_image_plane.c"
sort_subs "$u" "$tmp/usorted"
check "Blackboard usernames j_smith and k_smith: a folder each, with its own file" \
    sh -c "[ $status -eq 0 ] && [ '$(folders "$tmp/usorted")' = 'j_smith k_smith ' ] &&
           cmp -s labs/part1_image_plane.c '$tmp/usorted/j_smith/part1_image_plane.c' &&
           cmp -s solutions/part1_image_plane.c '$tmp/usorted/k_smith/part1_image_plane.c'"

# Names are the students' to choose, escape sequences and all: the run shows
# them (ESC as ^[, BEL as ^G) and passes none of them to the terminal.
e=$tmp/escapes
mkdir "$e"
cp solutions/part1_image_plane.c "$e/$(printf 'Di\033[2JEck')_7_assignsubmission_file_part1_image_plane.c"
echo x >"$e/$(printf 'x\033]0;title\007y.txt')"
sort_subs "$e" "$tmp/esorted"
check "names with escape sequences: sorted, shown as ^[ and ^G, and no ESC or BEL printed" \
    sh -c "[ $status -eq 0 ] && grep -qF 'Di^[[2JEck_7' '$tmp/out' && grep -qF 'x^[]0;title^Gy.txt' '$tmp/out' &&
           ! grep -q \"\$(printf '[\\033\\007]')\" '$tmp/out'"

# A newline or a tab in a name would forge a line of the run's output and a
# record of sorted.txt: they are shown as ^J and ^I in both.
mkdir "$tmp/lines"
cp solutions/part1_image_plane.c "$tmp/lines/smithbob_340934_208490284_part1_image_plane.c"
echo x >"$tmp/lines/$(printf 'y.txt\n(not sorted)\tforged.txt')"
sort_subs "$tmp/lines" "$tmp/lsorted"
check "a name with a newline and a tab: one line of the output and of sorted.txt, shown as ^J and ^I" \
    sh -c "[ $status -eq 0 ] && grep -qF 'y.txt^J(not sorted)^Iforged.txt' '$tmp/out' &&
           grep -qF '(not sorted)	y.txt^J(not sorted)^Iforged.txt' '$tmp/lsorted/sorted.txt' &&
           ! grep -q '^(not sorted)' '$tmp/out' && ! grep -q '^(not sorted)	forged' '$tmp/lsorted/sorted.txt'"

# ---- refused, nothing written ------------------------------------------------
mkdir "$tmp/full" && echo x >"$tmp/full/keep.txt"
sort_subs "$tmp/canvas.zip" "$tmp/full"
check "TO not empty: refused (exit 1), its files untouched" \
    sh -c "[ $status -eq 1 ] && grep -q 'it is not empty' '$tmp/out' && [ \"\$(ls '$tmp/full')\" = keep.txt ]"
mkdir "$tmp/empty"
sort_subs "$tmp/canvas.zip" "$tmp/empty"
check "TO an empty folder: sorted into it" sh -c "[ $status -eq 0 ] && [ -d '$tmp/empty/smithbob_340934' ]"
# TO as a shell completes a folder's name, with a "/" after it: the same
# as without (its temporary folder went inside it, then was not empty).
mkdir "$tmp/slash"
sort_subs "$tmp/canvas.zip" "$tmp/slash/"
check "TO an empty folder, given with a \"/\" after it: sorted into it" \
    sh -c "[ $status -eq 0 ] && [ -d '$tmp/slash/smithbob_340934' ] && [ \"\$(ls -a '$tmp/slash' | grep -c sorting)\" -eq 0 ]"
sort_subs "$tmp/canvas.zip" "$tmp/new-slash//"
check "TO a new folder, given with \"/\" after it: made, and sorted into it" \
    sh -c "[ $status -eq 0 ] && [ -d '$tmp/new-slash/smithbob_340934' ]"
mkdir "$tmp/plain" && cp solutions/part1_image_plane.c "$tmp/plain/"
sort_subs "$tmp/plain" "$tmp/none"
check "no file named as a download names them: refused (exit 1), nothing written" \
    sh -c "[ $status -eq 1 ] && grep -q 'holds no file named as Canvas, Moodle or Blackboard' '$tmp/out' && [ ! -e '$tmp/none' ] &&
           ! ls -d '$tmp'/none.sorting.* >/dev/null 2>&1"
sort_subs "$tmp/no-such.zip" "$tmp/none"
check "a download that is not there: refused (exit 1)" sh -c "[ $status -eq 1 ] && [ ! -e '$tmp/none' ]"
printf 'PK not a zip' >"$tmp/bad.zip"
sort_subs "$tmp/bad.zip" "$tmp/none"
check "a zip that is not one: refused (exit 1), nothing written" \
    sh -c "[ $status -eq 1 ] && grep -q 'could not be read' '$tmp/out' && [ ! -e '$tmp/none' ]"
make_sort FROM="$tmp/canvas.zip"
check "make sort-submissions without TO: its usage (exit 2)" sh -c "[ $status -eq 2 ] && grep -q 'usage: make sort-submissions' '$tmp/out'"

# ---- a download that would unpack to too much: refused before it is unpacked ----
# A zip bomb of 8 MiB of zeros (a few KiB packed): its ratio is refused at
# the default limits; with the ratio allowed, a total over MAX_MB is refused;
# with both allowed, it is sorted.
bomb=$tmp/bomb
mkdir "$bomb"
dd if=/dev/zero of="$bomb/smithbob_340934_208490284_part1_image_plane.c" bs=1048576 count=8 2>/dev/null
$pack zip "$tmp/bomb.zip" "$bomb" >/dev/null 2>&1
sort_subs "$tmp/bomb.zip" "$tmp/none"
check "a zip whose file unpacks to over 100 times its size: refused (exit 1), nothing written" \
    sh -c "[ $status -eq 1 ] && grep -q 'more than 100 times as many (a zip bomb?); nothing written' '$tmp/out' && [ ! -e '$tmp/none' ]"
make_sort FROM="$tmp/bomb.zip" TO="$tmp/none" MAX_RATIO=100000 MAX_MB=4
check "with MAX_RATIO raised, a zip over MAX_MB=4: refused (make fails), nothing written" \
    sh -c "[ $status -ne 0 ] && grep -q 'unpacks to more than 4 MiB' '$tmp/out' && [ ! -e '$tmp/none' ]"
make_sort FROM="$tmp/bomb.zip" TO="$tmp/none" MAX_RATIO=100000 MAX_MB=16
check "with both raised, the same zip is sorted (exit $status, want 0)" \
    sh -c "[ $status -eq 0 ] && [ \$(wc -c <'$tmp/none/smithbob_340934/part1_image_plane.c') -eq 8388608 ]"
rm -rf "$tmp/none"
make_sort FROM="$tmp/bomb.zip" TO="$tmp/none" MAX_MB=lots
check "MAX_MB that is not a number: the usage (make fails)" sh -c "[ $status -ne 0 ] && grep -q 'max-mb' '$tmp/out' && [ ! -e '$tmp/none' ]"

# ---- grade-all given the download itself names the sorter ------------------
$grade --all "$dl" --out "$tmp/g2" >"$tmp/out" 2>&1
check "grade-all on a Canvas download's folder (its __MACOSX left out, not graded): names make sort-submissions" \
    grep -q "named as a Canvas, Moodle or Blackboard download names a class.s files: make sort-submissions FROM=$dl TO=new-folder" "$tmp/out"
$grade --all "$tmp/canvas.zip" --out "$tmp/g2" >"$tmp/out" 2>&1
check "grade-all on the download's zip: names make sort-submissions" \
    grep -q 'canvas.zip is a file, not a folder of submissions: .*make sort-submissions FROM=' "$tmp/out"
finish
