#!/bin/sh
# The builds the grader keeps from one run to the next for the kit's own
# tests (GRADE_KEEP_BUILDS, tests/grader/memo.h; tests/run.sh sets it):
# - a second grading of the same file is served from the store, with the
#   same grades;
# - what it serves is what gets graded (an object planted there is);
# - the compiler's dependency list kept with an object is checked again
#   when it is served (a kept file that includes a file of the kit is
#   refused);
# - a program linked whole (as on macOS, or for the report page's render)
#   is kept too, and what is kept is what runs;
# - another compiler makes another entry;
# - nothing is kept where someone else may write in the store, with
#   GRADE_NO_MEMO=1, or when the grader is not root.
set -u
. tests/lib/checks.sh
grade=${GRADE:-out/build/bin/grade}   # make sanitize-grader: the sanitized one
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rtgstore.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
chmod 755 "$tmp"
mkdir "$tmp/ref" "$tmp/bad"
cp solutions/part1_image_plane.c "$tmp/ref/"
cp tests/selftest/p1-no-factor-2/part1_image_plane.c "$tmp/bad/"
chmod -R a+rX "$tmp/ref" "$tmp/bad"

# grade1 STORE SUB NAME: grades Part 1 of SUB, results in NAME.json.
grade1() {
    GRADE_KEEP_BUILDS=$1 $grade --submission "$2" --part 1 --results "$tmp/$3.json" --quiet \
        >"$tmp/$3.out" 2>&1
}
entries() { ls "$1" | grep -c '^part1_image_plane-'; }
score() { sed -n 's/^  "score": \([0-9.]*\),$/\1/p' "$tmp/$1.json"; }

mkdir -m 700 "$tmp/store"
if [ "$(id -u)" != 0 ]; then
    grade1 "$tmp/store" "$tmp/ref" user
    check "not root: the grader keeps nothing ($(ls "$tmp/store" | wc -l | tr -d ' ') entries)" \
        [ -z "$(ls "$tmp/store")" ]
    echo "   not root: the store is used as root only, so the rest is not checked"
    finish
fi

grade1 "$tmp/store" "$tmp/ref" first
check "a first grading keeps its build ($(entries "$tmp/store") entry)" [ "$(entries "$tmp/store")" -eq 1 ]
entry=$(ls -d "$tmp/store"/part1_image_plane-* | head -n 1)
check "... with its object and dependency list" [ -s "$entry/object.o" -a -s "$entry/depends" ]
grade1 "$tmp/store" "$tmp/ref" second
check "a second grading uses its entry (uses: $(cat "$entry/uses"))" [ "$(cat "$entry/uses")" = "++" ]
check "... and grades the same ($(score first) and $(score second))" \
    [ -n "$(score first)" ] && [ "$(score first)" = "$(score second)" ]
check "... test by test" \
    sh -c "[ \"\$(grep -v execution_time '$tmp/first.json')\" = \"\$(grep -v execution_time '$tmp/second.json')\" ]"

# Plant the faulty file's object in the reference's entry: if the store is
# really served, the reference's bytes are graded with the faulty object.
# Its shared object (where the grader loads one, on Linux) goes, so that it
# is linked again from the planted object; then the same with the faulty
# shared object alone.
mkdir -m 700 "$tmp/other"
grade1 "$tmp/other" "$tmp/bad" bad
bad_entry=$(ls -d "$tmp/other"/part1_image_plane-* | head -n 1)
cp "$bad_entry/object.o" "$entry/object.o"
rm -f "$entry/student.so"
grade1 "$tmp/store" "$tmp/ref" planted
check "the object the store serves is what is graded (planted: $(score planted), faulty file: $(score bad))" \
    [ "$(score planted)" = "$(score bad)" ] && [ "$(score planted)" != "$(score first)" ]
if [ -f "$bad_entry/student.so" ]; then
    rm -rf "$tmp/store"/*
    grade1 "$tmp/store" "$tmp/ref" again
    entry=$(ls -d "$tmp/store"/part1_image_plane-* | head -n 1)
    cp "$bad_entry/student.so" "$entry/student.so"
    grade1 "$tmp/store" "$tmp/ref" planted_so
    check "... and so is the shared object (planted: $(score planted_so))" \
        [ "$(score planted_so)" = "$(score bad)" ]
fi

# Linked whole (GRADE_NO_LOAD=1, as on macOS): the program is kept, and a
# planted program is what runs.
rm -rf "$tmp/store"/* "$tmp/other"/*
whole() { (GRADE_NO_LOAD=1 && export GRADE_NO_LOAD && grade1 "$@"); }
programs() { ls "$1" | grep -c '^program-'; }
whole "$tmp/store" "$tmp/ref" whole1
check "a program linked whole is kept ($(programs "$tmp/store") entry)" [ "$(programs "$tmp/store")" -eq 1 ]
whole "$tmp/other" "$tmp/bad" whole_bad
cp "$(ls -d "$tmp/other"/program-* | head -n 1)/runner" "$(ls -d "$tmp/store"/program-* | head -n 1)/runner"
whole "$tmp/store" "$tmp/ref" whole2
check "the program the store serves is what runs (planted: $(score whole2), faulty file: $(score whole_bad))" \
    [ "$(score whole2)" = "$(score whole_bad)" ] && [ "$(score whole1)" = "$(score first)" ]

# A dependency list naming a file of the kit, as a macro include would.
rm -rf "$tmp/store"/*
grade1 "$tmp/store" "$tmp/ref" kept
entry=$(ls -d "$tmp/store"/part1_image_plane-* | head -n 1)
printf ' %s/solutions/part1_image_plane.c\n' "$PWD" >>"$entry/depends"
grade1 "$tmp/store" "$tmp/ref" refused
check "a kept dependency on a file of the kit is refused when served" \
    grep -q "includes a file of the grader" "$tmp/refused.json"

rm -rf "$tmp/store"/*
mkdir "$tmp/bin"
ln -s "$(command -v cc)" "$tmp/bin/cc"
grade1 "$tmp/store" "$tmp/ref" cc1
(CC=$tmp/bin/cc && export CC && grade1 "$tmp/store" "$tmp/ref" cc2)
check "another compiler's path makes another entry ($(entries "$tmp/store") entries)" \
    [ "$(entries "$tmp/store")" -eq 2 ]

mkdir -m 770 "$tmp/shared"
grade1 "$tmp/shared" "$tmp/ref" shared
check "a store others may write in is not used ($(ls "$tmp/shared" | wc -l | tr -d ' ') entries)" \
    [ -z "$(ls "$tmp/shared")" ]
mkdir -m 700 "$tmp/off"
(GRADE_NO_MEMO=1 && export GRADE_NO_MEMO && grade1 "$tmp/off" "$tmp/ref" off)
check "GRADE_NO_MEMO=1: nothing is kept ($(ls "$tmp/off" | wc -l | tr -d ' ') entries)" [ -z "$(ls "$tmp/off")" ]
check "... and the grade is the same ($(score off))" [ "$(score off)" = "$(score first)" ]

finish
