#!/bin/sh
# Runs every suite of the kit's own tests and adds up their counts.
# Each suite prints "N passed, N failed" as its last line; so does this,
# with the failing checks' names and then how long it took just above it,
# so that a failure in a long log is found at once.
#
# The suites run in lanes: a lane runs its suites one after the other.
# The unit tests share a lane; each suite is a lane of its own.  As
# many workers as the machine has cores take lanes in a set order (below)
# until none is left (more at once would only share the cores).  Each
# suite's output is kept apart and shown whole, in a fixed order, once
# all have finished.
# Usage: sh tests/run.sh            (after make; `make test` does both)
#        sh tests/run.sh SUITE...    only these (names as shown, e.g. grader.sh)
#        TEST_WORKERS=n              n workers instead of one per core
set -u
dir=out/tests/run
log=out/tests/log
failures=out/tests/failures
mkdir -p out/tests
rm -rf "$dir"
mkdir -p "$dir"
: >"$log"
: >"$failures"
start=$(date +%s)

# The items, in the order they are shown: "name|command".
items=$dir/items
: >"$items"
# The unit tests are those of tests/unit (a program left in out/ by a test
# since deleted is not one).
units=$(for c in tests/unit/test_*.c; do n=${c##*/}; echo "${n%.c}"; done)
for n in $units; do
    [ -x "out/build/tests/$n" ] && printf 'unit: %s|%s\n' "$n" "out/build/tests/$n" >>"$items"
done
# The sandbox's test again in the jail's fallback (jail.h), as where the
# system refuses namespaces.
[ -x out/build/tests/test_sandbox ] &&
    printf 'unit: test_sandbox, fallback|GRADE_JAIL=fallback out/build/tests/test_sandbox\n' >>"$items"
for n in $units; do
    [ -x "out/asan/tests/$n" ] && printf 'unit, sanitizers: %s|%s\n' "$n" "out/asan/tests/$n" >>"$items"
done
for s in tests/suites/*.sh; do
    [ -f "$s" ] && printf '%s|sh %s\n' "${s##*/}" "$s" >>"$items"
done
if [ $# -gt 0 ]; then
    for want in "$@"; do
        grep "^$want|" "$items"
    done >"$items.only"
    mv "$items.only" "$items"
fi

# lane_of NAME: sets lane to the lane a suite runs in (a variable, not
# output, so that no subshell is started per item).  A lane is a file
# name: characters other than letters, digits, "_" and "." become "_".
lane_of() {
    case $1 in
    unit*) lane=unit ;;
    *) lane=$1 ;;
    esac
    case $lane in
    *[!a-zA-Z0-9_.]*) lane=$(printf '%s\n' "$lane" | tr -c 'a-zA-Z0-9_.\n' _) ;;
    esac
}

# run_item N NAME COMMAND: runs one, keeping its output, status and seconds.
run_item() {
    t0=$(date +%s)
    sh -c "$3" </dev/null >"$dir/$1.out" 2>&1
    echo $? >"$dir/$1.status"
    echo $(($(date +%s) - t0)) >"$dir/$1.seconds"
}

# Number the items, group them by lane, start each lane in the background.
n=0
while IFS='|' read -r name cmd; do
    n=$((n + 1))
    lane_of "$name"
    printf '%s|%s|%s\n' "$n" "$name" "$cmd" >>"$dir/lane.$lane"
done <"$items"

# The lanes in the order the workers take them, then the rest as listed.
# A worker takes the first lane no other worker has claimed (mkdir claims
# a lane at most once).  The longest, grader.sh, starts first; beside it
# go the lanes that mostly compute (the unit tests, the benchmark, the
# second compiler's build, the renders) rather than the other lanes that
# mostly start processes (the student kit, PrairieLearn, the report pages):
# on a 2-core virtual machine, making and ending processes on both cores
# at once runs little faster than on one.
queue=$dir/queue
first="grader.sh unit bench.sh portability.sh render_cli.sh student_kit.sh prairielearn.sh report.sh gradescope.sh"
for lane in $first; do
    [ -f "$dir/lane.$lane" ] && echo "$dir/lane.$lane"
done >"$queue"
for path in "$dir"/lane.*; do
    lane=${path##*/lane.}
    case " $first " in *" $lane "*) continue ;; esac
    [ -f "$path" ] && echo "$path"
done >>"$queue"
workers=${TEST_WORKERS:-$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 2)}
case $workers in '' | *[!0-9]* | 0) workers=2 ;; esac
w=0
while [ "$w" -lt "$workers" ]; do
    w=$((w + 1))
    (
        while read -r lane; do
            mkdir "$lane.claimed" 2>/dev/null || continue
            while IFS='|' read -r k name cmd; do
                run_item "$k" "$name" "$cmd"
            done <"$lane"
        done <"$queue"
    ) &
done
wait

# One awk shows every item's output in order, with its name and seconds,
# appends it to the log, collects the failing checks' lines and adds up
# the counts, which it leaves in $dir/counts (one process, not ten an item
# at the end of the run).  An item's count is the last "N passed, N
# failed" of its last line; one that printed none, or that exited non-zero
# with no failure counted, counts as 1 failed.
awk -F'|' -v dir="$dir" -v logfile="$log" -v failures="$failures" '
    function first_line(file,   line) {
        line = ""
        if ((getline line <file) <= 0)
            line = ""
        close(file)
        return line
    }
    function note(text) {
        print text
        print text >>failures
    }
    {
        k++
        name = $1
        status = first_line(dir "/" k ".status")
        if (status == "")
            status = 127
        seconds = first_line(dir "/" k ".seconds")
        if (seconds == "")
            seconds = "?"
        printf "== %s (%s s)\n", name, seconds
        out = dir "/" k ".out"
        last = ""
        while ((getline line <out) > 0) {
            print line
            print line >>logfile
            if (line ~ /^FAIL/)
                print "   " name ": " line >>failures
            last = line
        }
        close(out)
        p = f = ""
        rest = last
        while (match(rest, /[0-9]+ passed, [0-9]+ failed/)) {
            if (RSTART == 1 || substr(rest, RSTART - 1, 1) !~ /[0-9]/) {
                split(substr(rest, RSTART, RLENGTH), w, " ")
                p = w[1]
                f = w[3]
            }
            rest = substr(rest, RSTART + RLENGTH)
        }
        if (p == "") {
            note("   " name " printed no count (exit " status "): counted as 1 failed")
            failed++
            next
        }
        passed += p
        failed += f
        if (status != 0 && f == 0) {
            note("   " name " exited " status " with no failure counted: counted as 1 failed")
            failed++
        }
    }
    END { print passed + 0, failed + 0 >dir "/counts" }' "$items"
read -r passed failed <"$dir/counts"

if [ -s "$failures" ]; then
    echo
    echo "Failed:"
    cat "$failures"
fi
lanes=$(wc -l <"$queue" | tr -d ' ')
plural() { [ "$1" -eq 1 ] && echo "$1 $2" || echo "$1 ${2}s"; }
echo "took $(($(date +%s) - start)) s ($(plural "$n" suite): $(plural "$lanes" lane) shared by $(plural "$workers" worker))"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
