# checks.sh - the counting every suite of tests/suites shares.  A suite
# sources it, from the kit's top directory, before its first check:
#     . tests/lib/checks.sh
# and may define its own fail afterwards (to show more of what went wrong).
#   pass                     counts a check that passed
#   fail WHAT                counts one that failed and says so: "FAIL: WHAT"
#   check WHAT COMMAND...    pass if COMMAND succeeds, else fail WHAT (and
#                            return 1: `check ... || continue`)
#   check_has WHAT FILE PATTERN...
#                            pass if FILE has a line that matches each
#                            PATTERN (grep's), else fail WHAT, naming the
#                            first PATTERN that none matches
#   check_output WHAT COMMAND...
#                            check WHAT COMMAND, its output kept in
#                            $tmp/output and, when it fails, its first 20
#                            lines shown: `check_output WHAT diff WANT GOT`
#   finish                   prints "N passed, N failed", the last line that
#                            tests/run.sh reads, and exits 0 if none failed
#   need_built PROGRAM...    ends the suite as one failed check, naming the
#                            first PROGRAM that is not built
#   temp_dir NAME [MORE]     sets tmp to a new directory NAME.XXXXXX under
#                            $TMPDIR (or /tmp), removed on exit with MORE
#                            (shell words, read then: other paths the suite
#                            made; KEEP=1 keeps both and says where tmp is),
#                            or ends the suite as one failed check
#   fail_showing FILE N PREFIX WHAT
#                            counts a failure as fail does, then shows the
#                            first N lines of FILE (if not empty), each after
#                            PREFIX: a suite's own fail, showing its output
#   need_selftests DIR       writes the grader's self-test submissions into
#                            DIR, a folder each (tests/lib/selftests.sh), or
#                            ends the suite as one failed check, with why
#                            (as where there is no solutions/ to make them)
# (Not in tests/suites itself: tests/run.sh runs every file there.)
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
check() { what=$1; shift; if "$@"; then pass; else fail "$what"; return 1; fi; }
check_has() {
    _what=$1 _file=$2
    shift 2
    for _pattern in "$@"; do
        grep -q -e "$_pattern" "$_file" || { fail "$_what (no line matches '$_pattern')"; return 1; }
    done
    pass
}
check_output() {
    _what=$1
    shift
    "$@" >"$tmp/output" 2>&1 && pass && return
    fail_showing "$tmp/output" 20 '    | ' "$_what"
    return 1
}
finish() {
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ] && exit 0
    exit 1
}
temp_dir() {
    tmp=$(mktemp -d "${TMPDIR:-/tmp}/$1.XXXXXX") || {
        echo "cannot make a temporary directory"
        echo "0 passed, 1 failed"
        exit 1
    }
    temp_more=${2:-}
    trap 'if [ -n "${KEEP:-}" ]; then echo "kept $tmp"; else eval "rm -rf \"\$tmp\" $temp_more"; fi' EXIT
    trap 'exit 1' HUP INT TERM
}
fail_showing() {
    _show_file=$1 _show_lines=$2 _show_prefix=$3
    shift 3
    failed=$((failed + 1))
    echo "FAIL: $*"
    if [ -s "$_show_file" ]; then
        sed -n "1,${_show_lines}s/^/${_show_prefix}/p" "$_show_file"
    fi
}
need_built() {
    for f in "$@"; do
        if [ ! -x "$f" ]; then
            echo "FAIL: $f is missing: run make first"
            echo "0 passed, 1 failed"
            exit 1
        fi
    done
}
need_selftests() {
    if [ ! -d solutions ]; then
        echo "FAIL: no solutions/ here: run this from the instructor's kit"
        echo "$passed passed, $((failed + 1)) failed"
        exit 1
    fi
    if ! selftests_said=$(sh tests/lib/selftests.sh "$1" 2>&1); then
        printf '%s\n' "$selftests_said"
        echo "FAIL: the self-tests of tests/selftest could not be written out (tests/lib/selftests.sh)"
        echo "$passed passed, $((failed + 1)) failed"
        exit 1
    fi
}
