#!/bin/sh
# The grader's self-test: the reference scores full marks, the untouched
# skeleton 0 on every part, and every faulty or hostile submission under
# tests/selftest loses its own part's points and no other's, with the hint
# or message its expect file names.  Also the Gradescope bundle, run locally.
set -u
root=$(pwd)
grade=out/build/bin/grade
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rtselftest.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
chmod 755 "$tmp"
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
# check NAME CONDITION...: pass if the command succeeds
check() { name=$1; shift; if "$@"; then pass; else fail "$name"; fi; }

max1=20; max2=20; max3a=30; max3b=30     # tests/weights.conf

# -- the reference and the skeleton ------------------------------------------
$grade --submission solutions --results "$tmp/ref.json" --summary >"$tmp/ref.out" 2>&1
status=$?
check "the reference scores full marks (exit $status)" [ "$status" -eq 0 ]
check "the reference's summary" grep -q "^summary $max1 $max2 $max3a $max3b " "$tmp/ref.out"
check "results.json written for the reference" grep -q '"tests"' "$tmp/ref.json"
[ "$status" -eq 0 ] || tail -n 30 "$tmp/ref.out"

$grade --submission labs --summary >"$tmp/labs.out" 2>&1
status=$?
check "the skeleton loses points (exit $status, want 1)" [ "$status" -eq 1 ]
check "the skeleton scores 0 on every part" grep -q "^summary 0 0 0 0 0 0 1" "$tmp/labs.out"

# -- faulty and hostile submissions, graded as a class -----------------------
mkdir "$tmp/subs"
for dir in tests/selftest/*/; do
    name=$(basename "$dir")
    sub="$tmp/subs/$name"
    mkdir "$sub"
    cp solutions/part*.c "$sub/"
    for f in "$dir"part*.c; do [ -f "$f" ] && cp "$f" "$sub/"; done
    [ -f "$dir/MISSING" ] && rm -f "$sub/$(cat "$dir/MISSING")"
done
# A file that includes the reference by its absolute path must be refused.
mkdir "$tmp/subs/hostile-include-reference"
cp solutions/part*.c "$tmp/subs/hostile-include-reference/"
printf '#include "%s/solutions/part1_image_plane.c"\n' "$root" \
    >"$tmp/subs/hostile-include-reference/part1_image_plane.c"
mkdir -p "$tmp/expect/hostile-include-reference"
printf 'part 1\noutput refused\n' >"$tmp/expect/hostile-include-reference/expect"
chmod -R a+rX "$tmp/subs"

start=$(date +%s)
$grade --all "$tmp/subs" --out "$tmp/grades" >"$tmp/all.out" 2>&1
status=$?
elapsed=$(( $(date +%s) - start ))
check "grade --all ran (exit $status)" [ "$status" -le 1 ]
check "gradebook.csv written" [ -f "$tmp/grades/gradebook.csv" ]
echo "   graded $(ls "$tmp/subs" | wc -l | tr -d ' ') submissions in ${elapsed} s"

score() {   # score NAME COLUMN: a cell of the gradebook
    awk -F, -v n="$1" -v c="$2" '$1 == n { print $c }' "$tmp/grades/gradebook.csv"
}
for sub in "$tmp/subs"/*/; do
    name=$(basename "$sub")
    expect="tests/selftest/$name/expect"
    [ -f "$expect" ] || expect="$tmp/expect/$name/expect"
    json="$tmp/grades/$name.json"
    p1=$(score "$name" 2); p2=$(score "$name" 3); p3a=$(score "$name" 4); p3b=$(score "$name" 5)
    if grep -q '^core full' "$expect"; then
        check "$name: full core marks ($p1 $p2 $p3a $p3b)" \
            [ "$p1 $p2 $p3a $p3b" = "$max1 $max2 $max3a $max3b" ]
    fi
    part=$(sed -n 's/^part //p' "$expect")
    if [ -n "$part" ]; then
        for p in 1 2 3a 3b; do
            case $p in 1) got=$p1 max=$max1;; 2) got=$p2 max=$max2;; 3a) got=$p3a max=$max3a;; 3b) got=$p3b max=$max3b;; esac
            if [ "$p" = "$part" ]; then
                check "$name: Part $p loses points (got $got of $max)" [ -n "$got" -a "$got" != "$max" ]
            else
                check "$name: Part $p keeps full marks (got $got of $max)" [ "$got" = "$max" ]
            fi
        done
    fi
    want=$(sed -n 's/^output //p' "$expect")
    if [ -n "$want" ]; then
        check "$name: the report says '$want'" grep -q "$want" "$json"
    fi
    hardpart=$(sed -n 's/^hard lost //p' "$expect")
    if [ -n "$hardpart" ]; then
        $grade --submission "$sub" --part "$hardpart" >"$tmp/$name.table" 2>&1
        check "$name: some Part $hardpart hard cases fail" \
            grep -q "FAIL  Part $hardpart: .*\[hard\]" "$tmp/$name.table"
    fi
done
check "forged results: the grader's own score stands" \
    grep -q '"score": *[0-9.]*,' "$tmp/grades/hostile-forge-results.json"
check "forged results: no score of 1000 anywhere" sh -c "! grep -rq '\"score\": 1000' '$tmp/grades'"
check "forged results: nothing written beside the submissions" \
    sh -c "[ \$(ls '$tmp/grades' | wc -l) -eq \$(( \$(ls '$tmp/subs' | wc -l) + 1 )) ]"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
