#!/bin/sh
# `make fuzz`: builds the fuzz targets (tests/fuzz/fuzz_*.c) with clang's
# libFuzzer and the address and undefined-behaviour sanitizers, then runs
# each for FUZZ_SECONDS seconds (30 unless set), starting from seeds made of
# the kit's own files and from what earlier runs found (FUZZ_OUT/corpus).
# An input that crashes a target, or does anything the sanitizers report,
# is saved in FUZZ_OUT/crashes; replay one with
#     out/fuzz/fuzz_NAME out/fuzz/crashes/NAME-crash-...
# The last line reads "fuzzed N targets, R runs: C failed"; the exit status
# is 1 if any failed, 2 if the targets could not be built.
# Usage: sh tests/fuzz/run.sh [NAME...]   (from the kit's top directory;
#        names as in fuzz_NAME.c; all of them by default)
set -u
cc=${FUZZ_CC:-clang}
out=${FUZZ_OUT:-out/fuzz}
seconds=${FUZZ_SECONDS:-30}
case $seconds in '' | *[!0-9]* | 0) echo "FUZZ_SECONDS must be a whole number of seconds above 0" >&2; exit 2 ;; esac
if [ $# -eq 0 ]; then
    set -- scene obj png ppm inflate answers figures tests weights
fi
for name in "$@"; do
    if [ ! -f "tests/fuzz/fuzz_$name.c" ]; then
        echo "no fuzz target '$name' (tests/fuzz/fuzz_$name.c)" >&2
        exit 2
    fi
done
mkdir -p "$out/seeds" "$out/corpus" "$out/crashes" "$out/logs"

# Can this compiler build a fuzzer at all?
probe=$out/probe
printf '%s\n' '#include <stddef.h>' '#include <stdint.h>' \
    'int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n);' \
    'int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; (void)n; return 0; }' >"$probe.c"
if ! "$cc" -fsanitize=fuzzer,address,undefined "$probe.c" -o "$probe" >"$probe.log" 2>&1; then
    echo "make fuzz needs clang with its libFuzzer: '$cc -fsanitize=fuzzer' could not link a target"
    echo "(on Debian and Ubuntu: apt install clang; or FUZZ_CC=clang-N)"
    sed -n '1,5s/^/    | /p' "$probe.log"
    exit 2
fi

# The seeds: the kit's own files of each kind, and a few made here.
seed() {    # seed NAME FILE...: copies the files into NAME's seeds
    dir=$out/seeds/$1
    shift
    for f in "$@"; do
        [ -f "$f" ] && cp "$f" "$dir/"
    done
}
for name in "$@"; do
    rm -rf "$out/seeds/$name"
    mkdir -p "$out/seeds/$name" "$out/corpus/$name"
    dir=$out/seeds/$name
    case $name in
    scene) seed scene labs/scenes/*.scene ;;
    obj)
        seed obj labs/scenes/*.obj
        printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf -1 -2 -3\nf 1/1/1 2//2 4 3\n' >"$dir/quad.obj"
        ;;
    png)
        # The handouts' figures, the small ones (libFuzzer's inputs stay short).
        for f in handouts/figures/*.png; do
            [ -f "$f" ] && [ "$(wc -c <"$f")" -lt 16384 ] && cp "$f" "$dir/"
        done
        ;;
    ppm)
        printf 'P6\n2 2\n255\nABCDEFGHIJKL' >"$dir/binary.ppm"
        printf 'P3\n# a comment\n2 1\n255\n0 128 255 1 2 3\n' >"$dir/text.ppm"
        ;;
    inflate)
        printf '\001\005\000\372\377hello' >"$dir/stored"
        printf '\113\114\112\116\004\043\000' >"$dir/fixed"   # "abcabcabc": fixed codes, a match
        ;;
    answers)
        printf '\000\000%s\n%s\n' '0x1p+1 0x1p+2' 'end 1' >"$dir/part1"
        printf '\040\000%s\n%s\n%s\n' '0x1p+0 0x1.8p+1' 'nan inf' 'end 2' >"$dir/other"
        ;;
    figures)
        # Three bytes pick a test and a case; then doubles, little-endian:
        # 2, 4, 1 (Part 1's worked example), and NaN, inf, -0, 1e308.
        two='\000\000\000\000\000\000\000\100' four='\000\000\000\000\000\000\020\100'
        one='\000\000\000\000\000\000\360\077' nan='\000\000\000\000\000\000\370\177'
        inf='\000\000\000\000\000\000\360\177' zero='\000\000\000\000\000\000\000\200'
        big='\240\310\353\205\363\314\341\177'
        # shellcheck disable=SC2059
        printf "\000\000\000$four$two$one" >"$dir/worked"
        # shellcheck disable=SC2059
        printf "\100\000\001$nan$inf$zero$big$one$two" >"$dir/odd"
        # shellcheck disable=SC2059
        printf "\220\000\000$one$two$four$one$zero$one" >"$dir/other"
        ;;
    tests)
        for f in tests/public/*.tests; do
            dd if="$f" of="$dir/${f##*/}" bs=4000 count=1 2>/dev/null
        done
        ;;
    weights) seed weights tests/weights.conf ;;
    esac
done

# Build, then run each.
targets=""
for name in "$@"; do
    targets="$targets $out/fuzz_$name"
done
# shellcheck disable=SC2086
if ! ${MAKE:-make} -s FUZZ_CC="$cc" $targets; then
    echo "make fuzz: the targets did not build"
    exit 2
fi
runs=0
failed=0
for name in "$@"; do
    log=$out/logs/$name.log
    # The targets that read files write them under TMPDIR: here, cleared after.
    rm -rf "$out/tmp" && mkdir -p "$out/tmp"
    case $out in /*) tmp=$out/tmp ;; *) tmp=$PWD/$out/tmp ;; esac
    TMPDIR=$tmp "$out/fuzz_$name" -max_total_time="$seconds" -max_len=16384 -print_final_stats=1 \
        -artifact_prefix="$out/crashes/$name-" "$out/corpus/$name" "$out/seeds/$name" >"$log" 2>&1
    status=$?
    rm -rf "$out/tmp"
    n=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    runs=$((runs + ${n:-0}))
    if [ "$status" -eq 0 ]; then
        echo "  $name: ${n:-0} runs in $seconds s, nothing wrong ($(find "$out/corpus/$name" -type f | wc -l | tr -d ' ') inputs kept)"
    else
        failed=$((failed + 1))
        echo "FAIL $name: exit $status after ${n:-?} runs; see $log"
        grep -E 'ERROR:|runtime error:|SUMMARY:|Test unit written' "$log" | head -n 5 | sed 's/^/    | /'
    fi
done
echo "fuzzed $# targets, $runs runs: $failed failed"
[ "$failed" -eq 0 ]
