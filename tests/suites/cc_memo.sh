#!/bin/sh
# The compile memo the suites build with (tests/tools/ccmemo_main.c):
# - a second compile of the same file is served from the memo, and gives
#   the object a direct compile gives, byte for byte, with its warnings;
# - served the direct way (tests/tools/ccmemo_direct.h), without running
#   the preprocessor, when the files read and the places looked at are as
#   they were;
# - a change to a header the file includes, or to the flags, compiles again;
#   so does a new header that shadows the old one, a file that changes
#   what __has_include says, and a file that uses __DATE__;
# - a compile that fails is not kept, and says why as the compiler does;
# - a link of objects and archives is kept the same way: served, it gives
#   the direct link's program, byte for byte, executable; an object with
#   other bytes, other flags or another LIBRARY_PATH link again; an
#   argument of a kind it does not know, or a link that fails, keeps
#   nothing;
# - compiles and links without CC_MEMO (the grader's sandbox passes only
#   PATH) run the compiler itself;
# - a lock whose maker has died is taken over, one whose maker lives is
#   waited for;
# - kept from run to run (tests/tools/ccmemo_keep.sh): an entry stays for
#   the same compiler, all go for another, and what an interrupted run left
#   goes; after a run, the entries it neither made nor used go and those it
#   used stay.
set -u
. tests/lib/checks.sh
if [ ! -x out/build/ccmemo/cc ]; then
    echo "FAIL: out/build/ccmemo/cc is not built (make test-build)"
    echo "0 passed, 1 failed"
    exit 1
fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rtccmemo.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
memo_cc=$PWD/out/build/ccmemo/cc
real_cc=$(PATH=$(echo "$PATH" | sed "s|$PWD/out/build/ccmemo:||g") command -v cc)
mkdir "$tmp/memo" "$tmp/src"
cat >"$tmp/src/shape.h" <<'EOF'
#define SCALE 2.0
EOF
cat >"$tmp/src/area.c" <<'EOF'
#include "shape.h"
double area(double r) { int unused; return SCALE * 3.14159 * r * r; }
EOF
count() { c=$(grep -c "^$1 " "$tmp/memo/log" 2>/dev/null); echo "${c:-0}"; }
served() { echo $(($(count used) + $(count used-direct))); }
memo() { (cd "$tmp/src" && PATH=${memo_cc%/cc}:$PATH CC_MEMO=$tmp/memo cc "$@"); }
flags="-std=c11 -O2 -Wall -c area.c"

memo $flags -o a1.o 2>"$tmp/err1"
check "a first compile through the memo compiles (log: $(count compiled) compiled)" [ "$(count compiled)" -eq 1 ]
memo $flags -o a2.o 2>"$tmp/err2"
check "the same compile again is served from the memo, the direct way (log: $(count used-direct) used-direct)" \
    [ "$(count used-direct)" -eq 1 -a "$(served)" -eq 1 ]
(cd "$tmp/src" && "$real_cc" $flags -o direct.o 2>"$tmp/err-direct")
check "the served object is the direct compile's, byte for byte" cmp -s "$tmp/src/a2.o" "$tmp/src/direct.o"
check "the served compile repeats the compiler's warning" grep -q "unused" "$tmp/err2"
check "the warnings are the direct compile's" cmp -s "$tmp/err2" "$tmp/err-direct"

echo '#define SCALE 3.0' >"$tmp/src/shape.h"
memo $flags -o a3.o 2>/dev/null
check "a changed header compiles again" [ "$(count compiled)" -eq 2 ]
(cd "$tmp/src" && "$real_cc" $flags -o direct3.o 2>/dev/null)
check "... to the changed header's object" cmp -s "$tmp/src/a3.o" "$tmp/src/direct3.o"
memo -std=c11 -O1 -Wall -c area.c -o a4.o 2>/dev/null
check "other flags compile again" [ "$(count compiled)" -eq 3 ]

echo 'int broken(void) { return }' >"$tmp/src/bad.c"
memo -std=c11 -c bad.c -o bad.o 2>"$tmp/err-bad"
status=$?
check "a failing compile fails (exit $status)" [ "$status" -ne 0 ]
check "... saying why, as the compiler does" grep -q "error" "$tmp/err-bad"
memo -std=c11 -c bad.c -o bad.o 2>/dev/null
check "... and is not kept (log: $(served) served)" [ "$(served)" -eq 1 ]

echo 'double area(double); int main(void) { return area(1) > 0 ? 0 : 1; }' >"$tmp/src/main.c"
memo -std=c11 -c main.c -o main.o 2>/dev/null
memo -O2 main.o a1.o -o prog -lm
check "a link through the memo links (log: $(count linked) linked)" \
    [ "$(count linked)" -eq 1 -a -x "$tmp/src/prog" ]
check "... and counts as no compile ($(count compiled) compiled, $(served) served)" \
    [ "$(count compiled)" -eq 4 -a "$(served)" -eq 1 ]
memo -O2 main.o a1.o -o prog2 -lm
check "the same link again is served from the memo (log: $(count used-link) used-link)" \
    [ "$(count used-link)" -eq 1 -a "$(count linked)" -eq 1 ]
(cd "$tmp/src" && "$real_cc" -O2 main.o a1.o -o direct-prog -lm)
check "the served program is the direct link's, byte for byte" \
    cmp -s "$tmp/src/prog2" "$tmp/src/direct-prog"
check "... with the mode a new program gets, and it runs" \
    sh -c "[ \"\$(ls -l '$tmp/src/prog2' | cut -c1-10)\" = \"\$(ls -l '$tmp/src/direct-prog' | cut -c1-10)\" ] && '$tmp/src/prog2'"
cp "$tmp/src/a3.o" "$tmp/src/a1.o"
memo -O2 main.o a1.o -o prog3 -lm
(cd "$tmp/src" && "$real_cc" -O2 main.o a1.o -o direct-prog3 -lm)
check "an object with other bytes under the same name links again (log: $(count linked) linked)" \
    [ "$(count linked)" -eq 2 -a "$(count used-link)" -eq 1 ]
check "... to the direct link's program" cmp -s "$tmp/src/prog3" "$tmp/src/direct-prog3"
memo -O1 main.o a1.o -o prog4 -lm
check "other flags link again (log: $(count linked) linked)" [ "$(count linked)" -eq 3 ]
memo -O2 main.o a1.o -o prog5 -L. -lm
check "a link with an argument of a kind the memo does not know links, keeping nothing" \
    [ -x "$tmp/src/prog5" -a "$(count linked)" -eq 3 -a "$(count used-link)" -eq 1 ]
echo 'double nowhere(double); int main(void) { return nowhere(1) > 0; }' >"$tmp/src/lost.c"
(cd "$tmp/src" && "$real_cc" -std=c11 -c lost.c -o lost.o)
memo lost.o -o lost 2>"$tmp/err-link"
status=$?
check "a failing link fails (exit $status)" [ "$status" -ne 0 ]
check "... saying why, as the linker does" grep -q "nowhere" "$tmp/err-link"
memo lost.o -o lost 2>/dev/null
check "... and is not kept (log: $(count linked) linked, $(count used-link) used-link)" \
    [ "$(count linked)" -eq 3 -a "$(count used-link)" -eq 1 ]
(cd "$tmp/src" && LIBRARY_PATH=$tmp/src PATH=${memo_cc%/cc}:$PATH CC_MEMO=$tmp/memo cc -O2 main.o a1.o -o prog6 -lm)
check "a LIBRARY_PATH of another value links again (log: $(count linked) linked)" \
    [ -x "$tmp/src/prog6" -a "$(count linked)" -eq 4 -a "$(count used-link)" -eq 1 ]
(unset CC_MEMO; cd "$tmp/src" && PATH=${memo_cc%/cc}:$PATH cc $flags -o nomemo.o 2>/dev/null)
check "without CC_MEMO it compiles, keeping nothing" \
    [ -f "$tmp/src/nomemo.o" -a "$(count compiled)" -eq 4 -a "$(served)" -eq 1 ]

# The direct way.  Each case: a first compile through the memo, a change,
# then the same compile again, which must give the object a direct compile
# gives after the change.
# direct_case NAME FLAGS: compiles twice through the memo (NAME.1.o,
# NAME.2.o), and once directly (NAME.d.o) after the caller's change, read
# from $tmp/change.
direct_case() {
    memo $2 -o "$1.1.o" 2>/dev/null
    d=$(count used-direct)
    memo $2 -o "$1.1b.o" 2>/dev/null
    d=$(($(count used-direct) - d))
    sh "$tmp/change"
    memo $2 -o "$1.2.o" 2>/dev/null
    (cd "$tmp/src" && "$real_cc" $2 -o "$1.d.o" 2>/dev/null)
    check "$1: served the direct way before the change ($d of 1 used-direct)" [ "$d" -eq 1 ]
    check "$1: after the change, the object is the direct compile's" cmp -s "$tmp/src/$1.2.o" "$tmp/src/$1.d.o"
    check "$1: ... not the object from before the change" sh -c "! cmp -s '$tmp/src/$1.1.o' '$tmp/src/$1.2.o'"
}
mkdir "$tmp/src/inc1" "$tmp/src/inc2"
echo '#define SIDE 2.0' >"$tmp/src/inc1/side.h"
printf '#include <side.h>\ndouble side(void) { return SIDE; }\n' >"$tmp/src/side.c"
echo "echo '#define SIDE 5.0' >'$tmp/src/inc2/side.h'" >"$tmp/change"
: >"$tmp/memo/log"
direct_case shadowed "-std=c11 -O2 -Iinc2 -Iinc1 -c side.c"
printf '#include "inc1/side.h"\ndouble quoted(void) { return SIDE; }\n' >"$tmp/src/inc2/quoted.c"
echo "mkdir -p '$tmp/src/inc2/inc1' && echo '#define SIDE 7.0' >'$tmp/src/inc2/inc1/side.h'" >"$tmp/change"
direct_case quoted-shadowed "-std=c11 -O2 -I. -c inc2/quoted.c"
printf '#if __has_include("extra.h")\ndouble asked(void) { return 1; }\n#else\ndouble asked(void) { return 2; }\n#endif\n' \
    >"$tmp/src/asked.c"
echo "echo '/* here now */' >'$tmp/src/extra.h'" >"$tmp/change"
direct_case has-include "-std=c11 -O2 -c asked.c"
# twice NAME: compiles NAME.c through the memo twice, the log emptied first.
twice() {
    : >"$tmp/memo/log"
    memo -std=c11 -c "$1.c" -o "${1}1.o" 2>/dev/null
    memo -std=c11 -c "$1.c" -o "${1}2.o" 2>/dev/null
}
printf '/* as <limits.h> says:\n   #include'"'"'s protect themselves */\nint x;\n' >"$tmp/src/comment.c"
twice comment
check "\"#include's\" in a comment is no directive: served the direct way ($(count used-direct) used-direct)" \
    [ "$(count used-direct)" -eq 1 ]
printf 'const char *when(void) { return __TIME__; }\n' >"$tmp/src/when.c"
twice when
check "a file that uses __TIME__ is never served the direct way (log: $(count used-direct) used-direct)" \
    [ "$(count used-direct)" -eq 0 ]

# Locks.  An entry made with -O3 is removed and its lock made by hand.
ls "$tmp/memo" >"$tmp/before"
memo -std=c11 -O3 -c area.c -o l1.o 2>/dev/null
h=$(ls "$tmp/memo" | grep -v -x -F -f "$tmp/before" | grep '^[0-9a-f]*$')
rm -rf "${tmp:?}/memo/$h" "$tmp/memo"/direct-*          # the preprocessed way, to its lock
mkdir "$tmp/memo/$h.lock"
dead=$(sh -c 'echo $$')
echo "$dead" >"$tmp/memo/$h.lock/pid"
start=$(date +%s)
memo -std=c11 -O3 -c area.c -o l2.o 2>/dev/null
took=$(($(date +%s) - start))
check "a lock whose maker has died is taken over at once ($took s; the wait is 120 s)" \
    [ -n "$h" -a "$took" -le 10 -a -f "$tmp/src/l2.o" ]
check "... the compile is kept, and the lock is gone" [ -d "$tmp/memo/$h" -a ! -d "$tmp/memo/$h.lock" ]
rm -rf "${tmp:?}/memo/$h" "$tmp/memo"/direct-*
mkdir "$tmp/memo/$h.lock"
echo $$ >"$tmp/memo/$h.lock/pid"
memo -std=c11 -O3 -c area.c -o l3.o 2>/dev/null &
waiter=$!
sleep 1
check "a lock whose maker lives is waited for" sh -c "kill -0 $waiter && [ ! -f '$tmp/src/l3.o' ]"
rm -rf "${tmp:?}/memo/$h.lock"
wait "$waiter"
check "... until it goes" [ -f "$tmp/src/l3.o" ]

# Kept from run to run.
keep=tests/tools/ccmemo_keep.sh
entries() { ls "$tmp/memo" | grep -c '^[0-9a-f]*$'; }
directs() { ls "$tmp/memo" | grep -c '^direct-[0-9a-f]*$'; }
before=$(entries)
sh "$keep" open "$tmp/memo"
check "a memo with no record of its compiler is emptied ($before entries, now $(entries) and $(directs))" \
    [ "$before" -ge 4 -a "$(entries)" -eq 0 -a "$(directs)" -eq 0 -a -f "$tmp/memo/compiler" ]
memo $flags -o b1.o 2>/dev/null
memo -std=c11 -O1 -Wall -c area.c -o b2.o 2>/dev/null
mkdir "$tmp/memo/0123456789abcdef.lock" "$tmp/memo/0123456789abcdef.77.new" \
      "$tmp/memo/direct-0123456789abcdef.77.new" "$tmp/memo/direct-0123456789abcdef.77.old"
: >"$tmp/memo/messages.77"
sh "$keep" open "$tmp/memo"
check "opened again with the same compiler, its entries stay ($(entries) and $(directs) of 2 each)" \
    [ "$(entries)" -eq 2 -a "$(directs)" -eq 2 ]
check "... and its log starts empty" [ ! -s "$tmp/memo/log" ]
check "... and what an interrupted run left is gone: $(ls "$tmp/memo" | grep -v '^[0-9a-f]*$' | tr '\n' ' ')" \
    [ "$(ls "$tmp/memo" | grep -v -c -e '^[0-9a-f]*$' -e '^direct-[0-9a-f]*$' -e '^compiler$' -e '^log$')" -eq 0 ]
# The entries and then the stamp dated in the past, the stamp a minute
# later: an entry served now is newer than the stamp, the others are not
# (no waiting for the clock, whatever the file system's grain of time).
touch -t 200001010000 "$tmp/memo"/*
touch -t 200001010001 "$tmp/stamp"
memo -std=c11 -O1 -Wall -c area.c -o a5.o 2>/dev/null       # b2.o's entry, used
check "an entry kept from an earlier run is served (log: $(served) served)" [ "$(served)" -eq 1 ]
sh "$keep" prune "$tmp/memo" "$tmp/stamp"
check "pruned after a run, only the entry it used stays ($(directs) of 2 direct, $(entries) of 2 others)" \
    [ "$(directs)" -eq 1 -a "$(entries)" -eq 0 ]
check "... and the memo's compiler and log stay" [ -f "$tmp/memo/compiler" -a -f "$tmp/memo/log" ]
memo -std=c11 -O1 -Wall -c area.c -o a6.o 2>/dev/null
check "... and is served again (log: $(served) served)" [ "$(served)" -eq 2 ]
mkdir "$tmp/other"
printf '#!/bin/sh\necho "another cc 1.0"\n' >"$tmp/other/cc"
chmod +x "$tmp/other/cc"
PATH=$tmp/other:$PATH sh "$keep" open "$tmp/memo"
check "opened for another compiler, the memo is emptied ($(entries) and $(directs) entries)" \
    [ "$(entries)" -eq 0 -a "$(directs)" -eq 0 -a -f "$tmp/memo/compiler" ]
sh "$keep" open "$tmp/memo"
memo -std=c11 -O1 -Wall -c area.c -o a7.o 2>/dev/null
check "... so that compile is compiled again (log: $(count compiled) compiled)" [ "$(count compiled)" -eq 1 ]

finish
