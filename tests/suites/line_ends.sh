#!/bin/sh
# Windows line ends (CRLF), as Git for Windows writes them where
# core.autocrlf is set (its installer's default):
# - a clone of the kit made that way is the kit, byte for byte: every text
#   file keeps LF and every picture its bytes (.gitattributes);
# - a copy of the kit with CRLF all the same (a template made without the
#   .gitattributes) is refused by make at once, with a message that names
#   the cause; and the commands the message gives, run as written in such
#   a clone, leave it with LF and keep the student's committed work.
# The clone and the mend need git; without it they are skipped, and the
# suite says so.
#
# Usage: sh tests/suites/line_ends.sh   (from the kit's top directory;
# tests/run.sh runs it).  The last line is "N passed, N failed".
set -u
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES
. tests/lib/checks.sh
top=$(pwd)
temp_dir line_ends
cr=$(printf '\r')

# The refusal needs no git: a copy whose tests/run.sh has CRLF.
mkdir -p "$tmp/copy/tests"
printf 'set -eu\r\necho hello\r\n' >"$tmp/copy/tests/run.sh"
(cd "$tmp/copy" && make -f "$top/Makefile" help) >"$tmp/out" 2>&1 </dev/null
status=$?
check "make refuses a copy of the kit with CRLF, even for make help (status $status)" [ "$status" -ne 0 ]
check "make names the cause: Windows line ends" grep -q "Windows line ends (CRLF)" "$tmp/out"
printf 'set -eu\necho hello\n' >"$tmp/copy/tests/run.sh"
(cd "$tmp/copy" && make -f "$top/Makefile" help) >"$tmp/out" 2>&1 </dev/null
check "make does not refuse the same copy with LF" [ $? -eq 0 ]

if ! command -v git >/dev/null 2>&1; then
    echo "skipped: git is not installed (a clone with core.autocrlf, and the mend make advises)"
    finish
fi
# git, as on a fresh machine: no one's own configuration.
g() {
    HOME=$tmp GIT_CONFIG_NOSYSTEM=1 GIT_CONFIG_GLOBAL=/dev/null \
        git -c user.name=student -c user.email=student@example.invalid -c init.defaultBranch=main "$@"
}
# repo DIR FILES...: a repository in DIR of the kit's FILES, committed with
# LF, as the kit's own repository holds them.
repo() {
    d=$1
    shift
    mkdir -p "$d" && tar cf - "$@" | (cd "$d" && tar xf -) &&
        (cd "$d" && g init -q && g -c core.autocrlf=false add -A && g commit -qm kit)
}

# Every file of the kit but its builds, in a repository, cloned the
# Windows way.  Any file that differs is named.
files=$(find . -path ./out -prune -o -path ./.git -prune -o -type f -print | sed 's|^\./||' | sort)
if repo "$tmp/kit" $files >"$tmp/out" 2>&1 &&
    g -c core.autocrlf=true clone -q "$tmp/kit" "$tmp/win" >"$tmp/out" 2>&1; then
    differ=0
    for f in $files; do
        cmp -s "$f" "$tmp/win/$f" || { differ=$((differ + 1)); [ "$differ" -le 5 ] && echo "    differs: $f"; }
    done
    n=$(echo "$files" | wc -l | tr -d ' ')
    check "a clone made with core.autocrlf is the kit byte for byte ($differ of $n files differ)" \
        [ "$differ" -eq 0 ]
    npng=$(echo "$files" | grep -c '\.png$')
    check "the clone's files include pictures ($npng)" [ "$npng" -gt 0 ]
else
    fail "the kit as a repository, cloned with core.autocrlf"
    sed 's/^/    | /' "$tmp/out"
fi

# A template made without .gitattributes: the clone has CRLF, make says
# so, and its commands, run as written after the student commits, mend it.
repo "$tmp/old" tests/run.sh labs/part1_image_plane.c >"$tmp/out" 2>&1
g -c core.autocrlf=true clone -q "$tmp/old" "$tmp/stu" >>"$tmp/out" 2>&1
check "without .gitattributes, a clone made with core.autocrlf has CRLF" grep -q "$cr" "$tmp/stu/tests/run.sh"
(cd "$tmp/stu" && make -f "$top/Makefile" render) >"$tmp/out" 2>&1 </dev/null
check "make refuses that clone" grep -q "Windows line ends (CRLF)" "$tmp/out"
sed -n 's/^    //p' "$tmp/out" >"$tmp/mend"
check "make's message gives two commands to mend it" [ "$(wc -l <"$tmp/mend" | tr -d ' ')" -eq 2 ]
(
    cd "$tmp/stu" && g config core.autocrlf true && echo "/* my work */" >>labs/part1_image_plane.c &&
        g commit -qam "my work" && HOME=$tmp GIT_CONFIG_NOSYSTEM=1 GIT_CONFIG_GLOBAL=/dev/null sh "$tmp/mend"
) >"$tmp/out" 2>&1
check "the commands ran" [ $? -eq 0 ]
check "after them, tests/run.sh has LF" cmp -s "$top/tests/run.sh" "$tmp/stu/tests/run.sh"
check "after them, the student's committed work is there" grep -q "my work" "$tmp/stu/labs/part1_image_plane.c"
check "after them, nothing has CRLF" sh -c "! grep -rq '$cr' '$tmp/stu/labs' '$tmp/stu/tests'"
(cd "$tmp/stu" && make -n -f "$top/Makefile" help) >"$tmp/out" 2>&1 </dev/null
check "make no longer refuses it" [ $? -eq 0 ]
finish
