#!/bin/sh
# Writes the PrairieLearn question folder DIR (`make prairielearn`):
#   info.json       external grading with prairielearn/grader-c, entrypoint
#                   /grade/tests/grade.sh (tests/prairielearn/info.json)
#   question.html   one pl-file-upload of the stage files of the parts of
#                   tests/weights.conf's "parts" line (each one required)
#   tests/grade.sh  the entrypoint (tests/prairielearn/grade.sh)
#   tests/kit/      what the grader needs to be built and run: the Makefile,
#                   labs/, solutions/ (the other parts' reference), and
#                   tests/ grader, public, hidden, oracle, tools, weights.conf
# PrairieLearn copies a question's tests/ folder to /grade/tests for each
# submission and never shows it to students.
#
# Usage: sh tests/prairielearn/question.sh DIR   (from the kit's top directory)
set -eu
dir=${1:?usage: question.sh DIR}
parts=$(awk '$1 == "parts" { for (k = 2; k <= NF; k++) printf "%s ", $k }' tests/weights.conf)
[ -n "$parts" ] || { echo "question.sh: tests/weights.conf has no parts line" >&2; exit 2; }
files=""
labels=""
for p in 1 2 3a 3b 4 5; do
    case " $parts " in *" $p "*) ;; *) continue ;; esac
    files="$files, $(basename "$(ls labs/part${p}_*.c | head -n 1)")"
    labels="$labels $p"
done
files=${files#, }
# "Part 1", "Parts 1 and 2", "Parts 1, 2, 3a and 3b"
title=$(echo $labels | awk '{ if (NF == 1) { print "Part " $1; exit }
                               s = "Parts " $1; for (k = 2; k < NF; k++) s = s ", " $k
                               print s " and " $NF }')

rm -rf "$dir"
mkdir -p "$dir/tests/kit/tests"
sed "s/@TITLE@/$title/" tests/prairielearn/info.json >"$dir/info.json"
sed "s/@FILES@/$files/; s/@PARTLIST@/$title/" tests/prairielearn/question.html >"$dir/question.html"
cp tests/prairielearn/grade.sh "$dir/tests/grade.sh"
chmod 755 "$dir/tests/grade.sh"
cp -R Makefile labs solutions "$dir/tests/kit/"
for t in grader public hidden oracle tools weights.conf; do
    cp -R "tests/$t" "$dir/tests/kit/tests/"
done
echo "wrote $dir"
