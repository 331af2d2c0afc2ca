#!/bin/sh
# Writes the GitHub Classroom workflow for the kit in the current directory
# to stdout: tests/classroom/classroom.yml with its two placeholders filled
# in from the runners that `make grade CLASSROOM=file` writes there (see
# tests/grader/report_classroom.h): part<P>test<k> for the k-th core test
# of each part of tests/weights.conf's "parts" line, in part order and the
# order of tests/public/part<P>.tests, then "hard".  The student kit has
# no hidden tests, so these are all its runners; tests/suites/student_kit.sh
# checks them against what its grader writes.
#
# Usage: sh tests/classroom/workflow.sh [TEMPLATE] > classroom.yml
set -eu
template=${1:-tests/classroom/classroom.yml}
parts=$(awk '$1 == "parts" { for (k = 2; k <= NF; k++) printf "%s ", $k }' tests/weights.conf)
if [ -z "$parts" ]; then
    echo "workflow.sh: tests/weights.conf has no parts line" >&2
    exit 2
fi
runners=""
for p in 1 2 3a 3b 4 5; do
    case " $parts " in *" $p "*) ;; *) continue ;; esac
    file=tests/public/part$p.tests
    if [ ! -f "$file" ]; then
        echo "workflow.sh: $file is missing" >&2
        exit 2
    fi
    n=$(awk -v p="$p" '$1 == "test" && $2 == p && $4 == "core" { n++ } END { print n + 0 }' "$file")
    k=1
    while [ "$k" -le "$n" ]; do
        runners="$runners part${p}test$k"
        k=$((k + 1))
    done
done
runners="${runners# } hard"
awk -v runners="$runners" '
    /@RUNNER_ENV@/ {
        indent = substr($0, 1, index($0, "@") - 1)
        n = split(runners, r, " ")
        for (k = 1; k <= n; k++)
            printf "%s%s_RESULTS: \"${{ steps.grade.outputs.%s }}\"\n", indent, toupper(r[k]), r[k]
        next
    }
    /@RUNNERS@/ { gsub(/ /, ",", runners); sub(/@RUNNERS@/, runners); print; next }
    { print }' "$template"
