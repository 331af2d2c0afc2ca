#!/bin/sh
# Runs every suite of the kit's own tests and adds up their counts.
# Each suite prints "N passed, N failed" as its last line; so does this,
# with the failing checks' names and then how long it took just above it,
# so that a failure in a long log is found at once.
#
# The suites run in lanes: a lane runs its suites one after the other.
# Suites that build the same thing share a lane (student_kit.sh and
# classroom.sh both make the student kit), and so do the unit tests.  As
# many workers as the machine has cores take lanes in a set order (below)
# until none is left.  (Starting all twelve lanes at once on 2 cores took 163 s
# and 311 CPU-seconds, against 151 s and 284 with two workers.)  Each
# suite's output is kept apart and shown whole, in a fixed order, once all
# have finished.
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

# Builds in the suites compile each distinct file once, and link each
# distinct program once (tests/tools/ccmemo_main.c): four suites build a
# packaged kit from the same sources.  The memo is kept
# from one run to the next while the compiler is the same one (its
# --version and the size and time of its files); a run of every suite
# then drops the entries it did not use (tests/tools/ccmemo_keep.sh).
# The grader's own builds (its compiles of stage files and links of
# programs, in the hundreds of gradings of the suites) are kept the same
# way, by the grader itself (GRADE_KEEP_BUILDS,
# tests/grader/memo.h; used as root only, in a directory no one else may
# write in), for the same compiler.
# NO_CC_MEMO=1: every compile is compiled (the memos are left as they are).
memo=$PWD/out/tests/cc-memo
gmemo=$PWD/out/tests/grade-memo
# (Both are opened before the stand-in goes on PATH: the compiler they
# are kept for is the real one.)
if [ -x out/build/ccmemo/cc ] && [ -z "${NO_CC_MEMO:-}" ]; then
    if sh tests/tools/ccmemo_keep.sh open "$gmemo" && chmod 700 "$gmemo"; then
        GRADE_KEEP_BUILDS=$gmemo
        export GRADE_KEEP_BUILDS
    fi
    if sh tests/tools/ccmemo_keep.sh open "$memo"; then
        PATH=$PWD/out/build/ccmemo:$PATH
        CC_MEMO=$memo
        export PATH CC_MEMO
    fi
fi

: >"$dir/started"

# The items, in the order they are shown: "name|command".
items=$dir/items
: >"$items"
for t in out/build/tests/test_*; do
    [ -x "$t" ] && printf 'unit: %s|%s\n' "${t##*/}" "$t" >>"$items"
done
for t in out/asan/tests/test_*; do
    [ -x "$t" ] && printf 'unit, sanitizers: %s|%s\n' "${t##*/}" "$t" >>"$items"
done
for s in tests/suites/*.sh; do
    [ -f "$s" ] && printf '%s|sh %s\n' "${s##*/}" "$s" >>"$items"
done
every_suite=yes
if [ $# -gt 0 ]; then
    every_suite=no
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
    student_kit.sh | classroom.sh) lane=kit ;;
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
# compile memo's real compiles, the second compiler's build, the renders)
# rather than the other lanes that mostly start processes (the kit lane,
# PrairieLearn, the report pages): on a 2-core virtual machine, making
# and ending processes on both cores at once runs little faster than on
# one (README, "Building").  Six runs each way, taken in turn: 59-74 s,
# median 62.9, against 61-74 s, median 66.0, with grader.sh beside the kit
# lane, as it was.
queue=$dir/queue
first="grader.sh unit bench.sh cc_memo.sh portability.sh render_cli.sh kit prairielearn.sh report.sh gradescope.sh"
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
if [ -n "${CC_MEMO:-}" ] && [ -f "$memo/log" ]; then
    made=$(grep -c '^compiled ' "$memo/log")
    used=$(grep -c -e '^used ' -e '^used-direct ' "$memo/log")
    direct=$(grep -c '^used-direct ' "$memo/log")
    [ $((made + used)) -gt 0 ] &&
        echo "compiles in the suites: $made compiled, $used served from the memo ($direct without preprocessing)"
    linked=$(grep -c '^linked ' "$memo/log")
    served=$(grep -c '^used-link ' "$memo/log")
    [ $((linked + served)) -gt 0 ] &&
        echo "links in the suites: $linked linked, $served served from the memo"
    # Every suite ran: what none of them used (nor compiled) goes.
    [ "$every_suite" = yes ] && sh tests/tools/ccmemo_keep.sh prune "$memo" "$dir/started"
fi
if [ -n "${GRADE_KEEP_BUILDS:-}" ]; then
    # An entry's file "uses" is written whenever what it keeps is made or
    # used, its file "source" (its key) whenever it is made, even for a
    # build that failed.
    find "$gmemo/." \( -name 'uses' -o -name 'source' \) -newer "$dir/started" |
        awk -F/ '{ entry = $0; sub("/[^/]*$", "", entry); has[entry] = has[entry] " " $NF }
            END {
                for (e in has)
                    if (has[e] ~ /uses/) { if (has[e] ~ /source/) made++; else used++ }
                if (made + used)
                    printf "the grader'"'"'s builds (stage files compiled, programs linked): " \
                           "%d made, %d kept from an earlier run\n", made, used
            }'
    [ "$every_suite" = yes ] && sh tests/tools/ccmemo_keep.sh prune "$gmemo" "$dir/started"
fi
plural() { [ "$1" -eq 1 ] && echo "$1 $2" || echo "$1 ${2}s"; }
echo "took $(($(date +%s) - start)) s ($(plural "$n" suite): $(plural "$lanes" lane) shared by $(plural "$workers" worker))"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
