#!/bin/sh
# Keeps the suites' compile memo (tests/tools/ccmemo_main.c), and the
# grader's kept builds (GRADE_KEEP_BUILDS), from one run of the kit's tests
# to the next, for as long as the compiler is the same one.
#
#   sh tests/tools/ccmemo_keep.sh open DIR
#       Readies DIR for a run: kept if the compiler `cc` on PATH is the one
#       that filled it (its --version, and the size and time of the driver,
#       cc1, the linker and crt1.o), else emptied; its log emptied, and
#       what an interrupted run left (locks, half-made entries, messages)
#       removed.  Fails if DIR cannot be made.
#   sh tests/tools/ccmemo_keep.sh prune DIR STAMP
#       Removes the entries of DIR neither made nor used since the file
#       STAMP was written (the stand-in sets an entry's time when it serves
#       it): after a run of every suite, those that no suite needs now.
set -u
compiler_identity() {
    cc --version 2>&1
    # The linker and the C library's start file too: the grader's kept
    # builds (GRADE_KEEP_BUILDS) hold linked programs.
    ld=$(cc -print-prog-name=ld 2>/dev/null)
    case $ld in */*) ;; *) ld=$(command -v "$ld") ;; esac
    for f in "$(command -v cc)" "$(cc -print-prog-name=cc1 2>/dev/null)" "$ld" \
             "$(cc -print-file-name=crt1.o 2>/dev/null)"; do
        [ -f "$f" ] && ls -lLn "$f"
    done
}
case ${1:-} in
open)
    [ $# -eq 2 ] || { echo "usage: ccmemo_keep.sh open DIR" >&2; exit 2; }
    dir=$2
    now=$(compiler_identity)
    if [ ! -f "$dir/compiler" ] || [ "$(cat "$dir/compiler")" != "$now" ]; then
        rm -rf "$dir"
    fi
    mkdir -p "$dir" && printf '%s\n' "$now" >"$dir/compiler" && : >"$dir/log" &&
        find "$dir/." ! -name . -prune \( -name '*.lock' -o -name '*.new' -o -name '*.old' -o -name 'messages.*' \) \
            -exec rm -rf {} +
    ;;
prune)
    [ $# -eq 3 ] || { echo "usage: ccmemo_keep.sh prune DIR STAMP" >&2; exit 2; }
    find "$2/." ! -name . -prune ! -name compiler ! -name log ! -newer "$3" -exec rm -rf {} +
    ;;
*)
    echo "usage: ccmemo_keep.sh open DIR | prune DIR STAMP" >&2
    exit 2
    ;;
esac
