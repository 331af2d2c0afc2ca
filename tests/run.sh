#!/bin/sh
# Runs every suite of the kit's own tests and adds up their counts.
# Each suite prints "N passed, N failed" as its last line; so does this,
# with the failing checks' names just above it, so that a failure in a long
# log is found at once.
# Usage: sh tests/run.sh            (after make; `make test` does both)
set -u
passed=0
failed=0
log=out/tests/log
failures=out/tests/failures
mkdir -p out/tests
: >"$log"
: >"$failures"

suite() {   # suite NAME COMMAND...: run, show its output, add its counts
    name=$1
    shift
    printf '== %s\n' "$name"
    "$@" >out/tests/suite.out 2>&1
    status=$?
    cat out/tests/suite.out
    cat out/tests/suite.out >>"$log"
    grep '^FAIL' out/tests/suite.out | sed "s|^|   $name: |" >>"$failures"
    counts=$(tail -n 1 out/tests/suite.out | sed -n 's/^\(.*[^0-9]\)\{0,1\}\([0-9][0-9]*\) passed, \([0-9][0-9]*\) failed.*$/\2 \3/p')
    if [ -z "$counts" ]; then
        echo "   $name printed no count (exit $status): counted as 1 failed" | tee -a "$failures"
        failed=$((failed + 1))
        return
    fi
    set -- $counts
    passed=$((passed + $1))
    failed=$((failed + $2))
    if [ "$status" -ne 0 ] && [ "$2" -eq 0 ]; then
        echo "   $name exited $status with no failure counted: counted as 1 failed" | tee -a "$failures"
        failed=$((failed + 1))
    fi
}

for t in out/build/tests/test_*; do
    [ -x "$t" ] && suite "unit: ${t##*/}" "$t"
done
for t in out/asan/tests/test_*; do
    [ -x "$t" ] && suite "unit, sanitizers: ${t##*/}" "$t"
done
for s in tests/suites/*.sh; do
    [ -f "$s" ] && suite "${s##*/}" sh "$s"
done

if [ -s "$failures" ]; then
    echo
    echo "Failed:"
    cat "$failures"
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
