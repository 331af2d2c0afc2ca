#!/bin/sh
# Portability: the kit must build and run on Linux and macOS (and WSL),
# with gcc or clang, GNU make 3.81 (macOS's /usr/bin/make) or newer, and a
# /bin/sh that is dash (Debian, Ubuntu, WSL) or bash 3.2 (macOS).  This
# machine has only some of them, so the suite checks what it can run and
# greps for the rest; tests/README.md ("Portability") lists each check.
# Every grep check is first run on a planted violation, so that a check
# that could never fail fails here.
set -u
top=$(pwd)
. tests/lib/checks.sh
temp_dir rtport
have() { command -v "$1" >/dev/null 2>&1; }
start=$(date +%s)

# ---- the kit's files -------------------------------------------------------
# Shell scripts: *.sh and anything whose first line runs sh, outside out/.
find . -name out -prune -o -name .git -prune -o -name selftest -prune -o -type f -print |
    sed 's|^\./||' | sort >"$tmp/all"
grep '\.sh$' "$tmp/all" >"$tmp/scripts"
# shellcheck disable=SC2046
awk 'FNR == 1 && /^#! *(\/bin\/|\/usr\/bin\/env )sh/ { print FILENAME }' \
    $(grep -v -E '\.[A-Za-z0-9]+$|(^|/)Makefile$' "$tmp/all") /dev/null >>"$tmp/scripts"
grep '\.[ch]$' "$tmp/all" >"$tmp/csrc"
check "the kit has shell scripts ($(wc -l <"$tmp/scripts" | tr -d ' '))" test -s "$tmp/scripts"

# ---- the grep checks ---------------------------------------------------------
# Each prints "file:line: text" for what it finds, and succeeds when it
# found something.  A line that ends with the comment "portable:" and a
# reason is allowed (the reason says why the use is guarded).

# findings NAME FILE...: grep -n -E pattern (in $pat) over files, minus
# comment-only lines and lines marked portable.
findings() {
    grep -n -E -e "$pat" "$@" /dev/null 2>/dev/null |
        grep -v -E '^[^:]*:[0-9]+:[[:space:]]*(#|//|/?\*)' | grep -v 'portable:'
}

# Bashisms, for /bin/sh scripts (dash, bash 3.2 in sh mode).
bashisms() {
    pat='(^|[;&|({[:space:]])\[\[[[:space:]]'  # portable: a pattern
    pat="$pat|(^|[;&|[:space:]])function[[:space:]]+[A-Za-z_][A-Za-z0-9_]*[[:space:]]*(\(\))?[[:space:]]*\{"  # portable: a pattern
    pat="$pat|(^|[;&|[:space:]])(source|let|declare|typeset|shopt|readarray|mapfile|select)[[:space:]]"  # portable: a pattern
    pat="$pat|echo[[:space:]]+-[a-zA-Z]*e"  # portable: a pattern
    pat="$pat|(\[|test)[[:space:]][^]]*[[:space:]]==[[:space:]]"  # portable: a pattern
    pat="$pat|&>|\|&|<<<|>\(|<\("  # portable: a pattern
    pat="$pat|\\\$\{[A-Za-z_][A-Za-z0-9_]*(//?|\^|,|:[0-9 ])"  # portable: a pattern
    pat="$pat|\\\$\{![A-Za-z_]|\\\$\{[A-Za-z_][A-Za-z0-9_]*\[|^[[:space:]]*[A-Za-z_][A-Za-z0-9_]*(\[[^]]*\])?\+?=\("  # portable: a pattern
    pat="$pat|pipefail|set[[:space:]]+-o[[:space:]]+(errtrace|functrace)|trap[[:space:]].*[[:space:]](ERR|DEBUG|RETURN)\$"  # portable: a pattern
    pat="$pat|^[[:space:]]*\(\(|\\\$\(<"  # portable: a pattern
    pat="$pat|\\\$\{?(RANDOM|BASH[A-Z_]*|PIPESTATUS|FUNCNAME|EUID|UID|HOSTNAME|OSTYPE|SECONDS)\b"  # portable: a pattern
    pat="$pat|read[[:space:]]+-[a-qs-z]|printf[[:space:]]+-v|wait[[:space:]]+-n|export[[:space:]]+-f"  # portable: a pattern
    pat="$pat|\{[0-9]+\.\.[0-9]+\}"  # portable: a pattern
    findings "$@"
}

# GNU-only (or Linux-only) tools and flags in shell scripts; each as macOS
# has it said in the message of the check that found it.
gnu_only() {
    pat='sed[[:space:]]([^|;]*[[:space:]])?-i([[:space:]]|$)'  # portable: a pattern
    pat="$pat|sed[[:space:]]+-r|sed[[:space:]].*\\\\[+?|]"  # portable: a pattern
    pat="$pat|grep[[:space:]]+-[a-zA-Z]*P|grep[[:space:]][^|;]*\\\\[+?|]"  # portable: a pattern
    pat="$pat|date[[:space:]]+(-d|--)|date[[:space:]].*%N"  # portable: a pattern
    pat="$pat|readlink[[:space:]]+-[a-z]*f|(^|[^A-Za-z_])realpath[[:space:]]"  # portable: a pattern
    pat="$pat|stat[[:space:]]+(-c|-f|--)|find[[:space:]].*-printf|xargs[[:space:]]+(-[a-z]*r|--)"  # portable: a pattern
    pat="$pat|head[[:space:]]+-n[[:space:]]*-[0-9]|sort[[:space:]]+-[a-zA-Z]*[Vh]|base64[[:space:]]+(-d|-w|--)"  # portable: a pattern
    pat="$pat|(^|[^A-Za-z_./-])(timeout|taskset|nproc|setsid|flock|lscpu|numactl|md5sum|sha[0-9]+sum)([[:space:]]|\)|;|\||$)"  # portable: a pattern
    pat="$pat|/proc/"  # portable: a pattern
    pat="$pat|mktemp([[:space:]]+-[a-z]+)*[[:space:]]*(\)|\$|;|&|\|)"  # portable: a pattern
    pat="$pat|\"\\\$\(wc[[:space:]][^)]*\)\"[[:space:]]*!?=[[:space:]]"  # portable: a pattern
    pat="$pat|(gensub|strftime|systime|asorti?|PROCINFO|IGNORECASE|FPAT|BEGINFILE)[[:space:]]*\("  # portable: a pattern
    pat="$pat|(^|[;&|[:space:]])(ls|cp|mv|rm|ln|mkdir|touch|date|stat|sort|head|tail|wc|cut|tr|grep|sed|find|xargs|du|tar|chmod|chown|readlink|mktemp)[[:space:]][^|;]*[[:space:]]--[a-z]"  # portable: a pattern
    findings "$@"
}

# Makefile features newer than GNU make 3.81 (what each needs is in the
# message).  Recipe lines (a tab first) are shell; only $(file), $(guile),
# $(let) and $(intcmp) are looked for there too.
make_features() {
    for f in "$@"; do
        grep -n -v '^	' "$f" | grep -v -E '^[0-9]+:[[:space:]]*#' | grep -E \
            -e '^[0-9]+:[^=#]*[^:=!?+[:space:]]?[[:space:]]*!=' \
            -e ':::?=' \
            -e '^[0-9]+:[[:space:]]*(undefine|load|-load)[[:space:]]' \
            -e '\.(ONESHELL|RECIPEPREFIX|SHELLFLAGS|EXTRA_PREREQS|NOTINTERMEDIATE|WAIT|SHELLSTATUS)\b' \
            -e '(^|[[:space:]:;])private[[:space:]]+[A-Za-z_]' \
            -e '&:' \
            -e '^[0-9]+:[[:space:]]*define[[:space:]]+[^[:space:]]+[[:space:]]*(:?:?=|\+=|\?=|!=)' \
            -e 'output-sync|MAKEFLAGS.*[[:space:]]-O' | sed "s|^|$f:|"  # portable: a pattern
        grep -n -E '\$[({](file|guile|let|intcmp)[[:space:]]' "$f" | sed "s|^|$f:|"  # portable: a pattern
    done | grep .
}

# C: what Linux has and macOS lacks (or hides, or deprecates).
c_linux_only() {
    pat='#[[:space:]]*include[[:space:]]*<(linux/|sys/(prctl|sysinfo|epoll|inotify|signalfd|timerfd|eventfd|sendfile|vfs|personality|auxv)\.h|malloc\.h|endian\.h|byteswap\.h|features\.h|error\.h|argp\.h|obstack\.h)'  # portable: a pattern
    pat="$pat|(^|[^A-Za-z0-9_])(pipe2|dup3|accept4|getrandom|prctl|memfd_create|sysinfo|get_nprocs|gettid|clock_nanosleep|timer_create|sem_init|sem_timedwait|pthread_barrier_[a-z]+|pthread_spin_[a-z]+|pthread_[sg]etaffinity_np|pthread_condattr_setclock|sched_[sg]etaffinity|posix_fallocate|fallocate|posix_fadvise|sync_file_range|strchrnul|mempcpy|memrchr|rawmemchr|canonicalize_file_name|reallocarray|qsort_r|strerror_r|v?asprintf|mallinfo|malloc_usable_size|usleep|getauxval)[[:space:]]*\("  # portable: a pattern
    pat="$pat|\b(CPU_SET|CPU_ZERO|O_TMPFILE|O_PATH|O_DIRECT|O_NOATIME|MAP_POPULATE|MAP_HUGETLB|SOCK_CLOEXEC|SOCK_NONBLOCK|CLOCK_BOOTTIME|SIGPOLL|SIGPWR|SIGSTKFLT|program_invocation_name|_GNU_SOURCE)\b"  # portable: a pattern
    pat="$pat|\"/proc/|(^|[^A-Za-z0-9_])(v?sprintf|tmpnam|tempnam|mktemp|vfork|gets|getwd|sbrk|brk)[[:space:]]*\("  # portable: a pattern
    findings "$@"
    # MAP_ANONYMOUS needs MAP_ANON beside it; __float128 its guard.
    for f in $(grep -l 'MAP_ANONYMOUS' "$@" /dev/null); do
        grep -q 'MAP_ANON\b' "$f" || echo "$f: MAP_ANONYMOUS without the MAP_ANON fallback"
    done
    for f in $(grep -l '__float128' "$@" /dev/null); do
        grep -q '__SIZEOF_FLOAT128__' "$f" || echo "$f: __float128 not behind __SIZEOF_FLOAT128__"
    done
}

# C: a file that asks for POSIX alone (_POSIX_C_SOURCE, _XOPEN_SOURCE) must
# also define _DARWIN_C_SOURCE: macOS's headers otherwise hide mkdtemp,
# mkstemp, O_NOFOLLOW, _SC_NPROCESSORS_ONLN, RLIMIT_NPROC and more.
c_posix_alone() {
    posix=$(grep -l -E '^#[[:space:]]*define[[:space:]]+_(POSIX_C|XOPEN)_SOURCE' "$@" /dev/null)
    [ -n "$posix" ] || return 1
    # shellcheck disable=SC2086
    grep -L -E '^#[[:space:]]*define[[:space:]]+_DARWIN_C_SOURCE' $posix |
        sed 's/$/: _POSIX_C_SOURCE or _XOPEN_SOURCE without _DARWIN_C_SOURCE/' | grep .
}

# Every check must find its planted violation: "CHECK|WHAT|FILE|TEXT" a
# line, TEXT written by printf.  (The plants are written with '' inside
# their keywords, taken out here, so that this file does not hold them.)
mkdir "$tmp/plant"
while IFS='|' read -r checker what file text; do
    printf "$(printf '%s' "$text" | sed "s/''//g")" >"$tmp/plant/$file"
    $checker "$tmp/plant/$file" >/dev/null
    check "the $what check finds the planted $file" test $? -eq 0
done <<'EOF'
bashisms|bashism|bash.sh|#!/bin/sh\nif [''[ -n "$x" ]]; then echo yes; fi\n
bashisms|bashism|eqeq.sh|#!/bin/sh\nif [ "$a" =''= b ]; then :; fi\n
bashisms|bashism|subst.sh|#!/bin/sh\necho "$''{x//a/b}"\n
bashisms|bashism|setopt.sh|#!/bin/sh\nset -o pipe''fail\n
bashisms|bashism|herestring.sh|#!/bin/sh\ncat <<''< "$x"\n
gnu_only|GNU-only|sedi.sh|#!/bin/sh\nse''d -i "s/a/b/" f\n
gnu_only|GNU-only|dated.sh|#!/bin/sh\nwhen=$(dat''e -d yesterday +%%s)\n
gnu_only|GNU-only|cpus.sh|#!/bin/sh\nn=$(npro''c)\n
gnu_only|GNU-only|mktemp.sh|#!/bin/sh\nd=$(mkte''mp -d)\n
gnu_only|GNU-only|printf.sh|#!/bin/sh\nfin''d . -printf "%%p"\n
gnu_only|GNU-only|grepP.sh|#!/bin/sh\ngre''p -qP "x+" f\n
make_features|make 3.81|Makefile.bang|X != date\n
make_features|make 3.81|Makefile.undefine|undefine X\n
make_features|make 3.81|Makefile.oneshell|.ONESHELL:\n
make_features|make 3.81|Makefile.grouped|a b &: c\n\ttouch a b\n
make_features|make 3.81|Makefile.file|X := $(file <list)\n
c_linux_only|Linux-only C|prctl.c|#include <sys/prctl.h>\n
c_linux_only|Linux-only C|sprintf.c|int f(char *b) { return sprint''f(b, "%%d", 1); }\n
c_linux_only|Linux-only C|pipe2.c|int f(int *p) { return pipe''2(p, 0); }\n
c_linux_only|Linux-only C|anon.c|void *m(void) { return mmap(0, 1, 3, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0); }\n
c_linux_only|Linux-only C|proc.c|const char *p = "/pro''c/self/status";\n
c_posix_alone|POSIX-alone|posix.c|#define _POSIX_C_SOURCE 200809L\n#include <unistd.h>\n
EOF

# ---- 2. shell scripts ------------------------------------------------------------
scripts=$(cat "$tmp/scripts")
if have dash; then
    for s in $scripts; do
        check "dash -n $s" dash -n "$s"
    done
else
    echo "   skipped dash -n: dash is not installed (sh -n instead)"
    for s in $scripts; do
        check "sh -n $s" sh -n "$s"
    done
fi
# shellcheck disable=SC2086
bashisms $scripts >"$tmp/found"
check "no bashisms in the kit's scripts (grep check): $(tr '\n' ' ' <"$tmp/found")" test ! -s "$tmp/found"
if have checkbashisms; then
    # shellcheck disable=SC2086
    checkbashisms -f -p $scripts >"$tmp/cb" 2>&1
    check "checkbashisms: $(tr '\n' ' ' <"$tmp/cb")" test ! -s "$tmp/cb"
else
    echo "   skipped checkbashisms: not installed (Debian's devscripts has it)"
fi
if have shellcheck; then
    # shellcheck disable=SC2086
    shellcheck -s sh -f gcc $scripts 2>/dev/null | grep -E 'SC3[0-9]{3}' >"$tmp/sc"
    check "shellcheck -s sh finds no non-POSIX feature: $(tr '\n' ' ' <"$tmp/sc")" test ! -s "$tmp/sc"
else
    echo "   skipped shellcheck: not installed"
fi
# shellcheck disable=SC2086
gnu_only $scripts >"$tmp/found"
check "no GNU-only or Linux-only tool or flag in the kit's scripts: $(tr '\n' ' ' <"$tmp/found")" test ! -s "$tmp/found"

# The scripts that need no build, under every POSIX shell here.  /bin/sh
# runs all the others (tests/run.sh runs each suite with sh).
sh_is=$(ls -l /bin/sh 2>/dev/null | sed 's/.*-> *//')
echo "   /bin/sh is ${sh_is:-/bin/sh}"
# The self-tests written out from their table (tests/lib/selftests.sh), the
# same under every shell as under /bin/sh.
selftests=no
if [ -f tests/selftest/mistakes ]; then
    if sh tests/lib/selftests.sh "$tmp/selftest-sh" 2>"$tmp/selftest.err"; then
        selftests=yes
    else
        fail "sh tests/lib/selftests.sh: $(head -n 3 "$tmp/selftest.err" | tr '\n' ' ')"
    fi
fi
for shell in dash "bash --posix" ksh mksh posh yash "busybox sh"; do
    set -- $shell
    have "$1" || continue
    for mesh in cracks knot; do
        [ -f "tests/tools/$mesh-mesh.sh" ] && [ -f "labs/scenes/$mesh.obj" ] || continue
        $shell "tests/tools/$mesh-mesh.sh" >"$tmp/$mesh.obj" 2>"$tmp/$mesh.err"
        check "$shell tests/tools/$mesh-mesh.sh writes labs/scenes/$mesh.obj" \
            cmp -s "$tmp/$mesh.obj" "labs/scenes/$mesh.obj"
    done
    [ "$selftests" = yes ] || continue
    rm -rf "$tmp/selftest-other"
    $shell tests/lib/selftests.sh "$tmp/selftest-other" 2>"$tmp/selftest.err"
    check "$shell tests/lib/selftests.sh writes the self-tests as sh does" \
        diff -r "$tmp/selftest-sh" "$tmp/selftest-other"
done

# ---- 3. the Makefile ---------------------------------------------------------
make_features Makefile >"$tmp/found"
check "the Makefile needs nothing newer than GNU make 3.81: $(tr '\n' ' ' <"$tmp/found")" test ! -s "$tmp/found"

# ---- 4. the C sources --------------------------------------------------------
# Reading /proc is allowed where the code goes on without it: these lines
# say so with a "portable:" comment (tests/bench, tests/grader/sandbox.c).
# shellcheck disable=SC2046
c_linux_only $(cat "$tmp/csrc") >"$tmp/found"
check "no Linux-only (or deprecated on macOS) call, header or flag in C: $(tr '\n' ' ' <"$tmp/found")" \
    test ! -s "$tmp/found"
# shellcheck disable=SC2046
c_posix_alone $(cat "$tmp/csrc") >"$tmp/found"
check "every C file that asks for POSIX also defines _DARWIN_C_SOURCE: $(tr '\n' ' ' <"$tmp/found")" \
    test ! -s "$tmp/found"

# ---- 1. the compilers ----------------------------------------------------------
cc=${CC:-cc}
is_clang() { "$1" -dM -E - </dev/null 2>/dev/null | grep -q '__clang__'; }
is_gcc() { "$1" -dM -E - </dev/null 2>/dev/null | grep -q '__GNUC__' && ! is_clang "$1"; }
other=""
if is_clang "$cc"; then
    for c in gcc gcc-15 gcc-14 gcc-13 gcc-12 gcc-11; do
        if have "$c" && is_gcc "$c"; then other=$c; break; fi
    done
else
    for c in clang clang-20 clang-19 clang-18 clang-17 clang-16 clang-15 clang-14; do
        if have "$c" && is_clang "$c"; then other=$c; break; fi
    done
fi
cflags=$(printf 'portability-flags:\n\t@echo $(CFLAGS) $(THREADS)\n' | ${MAKE:-make} -s -f Makefile -f - portability-flags)

# The default compiler, -Werror, every C file (the main build compiled them
# without it).
# shellcheck disable=SC2046
set -- $(grep '\.c$' "$tmp/csrc")
$cc $cflags -Werror -fsyntax-only -Ilabs -DHARNESS_PART=PART_1 -DGRADER_ORACLE "$@" >"$tmp/werror.log" 2>&1
status=$?
check "$cc -std=c11 -pedantic -Werror compiles $# C files: $(grep -E 'error:|warning:' "$tmp/werror.log" | head -n 5 | tr '\n' ' ')" \
    test "$status" -eq 0
echo "   $cc: $($cc --version 2>/dev/null | head -n 1)"

if [ -z "$other" ]; then
    echo "   skipped the second compiler: $(is_clang "$cc" && echo gcc || echo clang) is not installed"
else
    name=$(basename "$other")
    root=out/port/$name
    echo "   second compiler: $other ($($other --version 2>/dev/null | head -n 1)), building into $root"
    mkdir -p "$root"
    ${MAKE:-make} -j2 OUT_ROOT="$root" CC="$other" STD="-std=c11 -Werror" all unit-tests "$root/build/bin/gentests" \
        >"$tmp/other.log" 2>&1
    status=$?
    check "make all with $other -std=c11 -pedantic -Werror (exit $status): $(grep -E 'error:|warning:' "$tmp/other.log" | head -n 5 | tr '\n' ' ')" \
        test "$status" -eq 0
    # Its unit tests.
    ran=0
    for c in tests/unit/test_*.c; do
        t=${c##*/}
        t=$root/build/tests/${t%.c}
        [ -x "$t" ] || continue
        ran=$((ran + 1))
        "$t" >"$tmp/unit.out" 2>&1
        status=$?
        if [ "$status" -eq 0 ] && tail -n 1 "$tmp/unit.out" | grep -q ' 0 failed'; then
            pass
        else
            fail "${t##*/} built with $other (exit $status)"
            grep -E 'FAIL|: ' "$tmp/unit.out" | head -n 10
        fi
    done
    echo "   ran $ran unit tests built with $name"
    check "the unit tests were built with $other" test "$ran" -gt 0
    # The same cases whichever compiler built the kit: C leaves the order of
    # a call's arguments open (gcc draws them last first, clang first
    # first), so each draw of the oracle and the hidden tests is a statement
    # of its own.  The public tests its build writes are the committed ones,
    # and the skeleton graded by its grader is shown the same hidden inputs.
    mkdir "$tmp/public-other"
    "$root/build/bin/gentests" "$tmp/public-other" >"$tmp/gentests.out" 2>&1
    check "the public tests $other's build writes are the committed ones" diff -r tests/public "$tmp/public-other"
    sed 's/^parts .*/parts 1 2 3a 3b 4 5/' tests/weights.conf >"$tmp/all-parts.conf"
    drawn() {   # drawn BUILD NAME: the skeleton's results by BUILD's grader, but for the time
        "$1/bin/grade" --submission labs --weights "$tmp/all-parts.conf" --results "$tmp/drawn.json" --quiet >/dev/null 2>&1
        grep -v '"execution_time"' "$tmp/drawn.json" >"$tmp/drawn-$2.json"
    }
    drawn out/build default
    drawn "$root/build" other
    check "the skeleton graded by $other's build meets the same hidden cases as by $cc's" \
        sh -c "grep -q 'input: ' '$tmp/drawn-default.json' && cmp -s '$tmp/drawn-default.json' '$tmp/drawn-other.json'"
fi

# A second C library and its maths, when installed: musl (musl-gcc, from
# Debian's musl-tools), whose libm is not glibc's, as Apple's is not.  The
# grader built with it into out/port/musl, and submissions graded by both
# builds, the students' code compiled and linked with each (the grader
# takes its compiler from CC): the grades must be the same, so that a
# student's grade does not depend on the machine's maths library.  The
# submissions are the reference and self-tests whose answers go through
# libm's tan, sqrt or float arithmetic.  Only the grader is built with
# musl (make grader): what the grades depend on.
if ! have musl-gcc; then
    echo "   skipped the second C library: musl-gcc is not installed (Debian's musl-tools has it)"
else
    mroot=out/port/musl
    ${MAKE:-make} -j2 OUT_ROOT="$mroot" CC=musl-gcc grader >"$tmp/musl.log" 2>&1
    status=$?
    check "make grader with musl-gcc (exit $status): $(grep -E 'error:|warning:' "$tmp/musl.log" | head -n 5 | tr '\n' ' ')" \
        test "$status" -eq 0
    if [ "$status" -eq 0 ]; then
        sed 's/^parts .*/parts 1 2 3a 3b 4 5/' tests/weights.conf >"$tmp/all-parts.conf"
        need_selftests "$tmp/selftest"
        same=0 differ=""
        for name in reference p1-float p1-pi-approximate rw-tinyraytracer rw-tinyraytracer-camera rw-pbrt-v4 \
            rw-rtiow-v1 rw-wikipedia-moller-trumbore textbook; do
            sub=$tmp/musl-$name
            mkdir "$sub" && cp solutions/part*.c "$sub/"
            [ "$name" = reference ] || cp "$tmp"/selftest/"$name"/part*.c "$sub/"
            a=$(out/build/bin/grade --submission "$sub" --weights "$tmp/all-parts.conf" --summary --quiet 2>/dev/null |
                grep '^summary')
            b=$(CC=musl-gcc "$mroot"/build/bin/grade --submission "$sub" --weights "$tmp/all-parts.conf" --summary \
                --quiet 2>/dev/null | grep '^summary')
            if [ -n "$a" ] && [ "$a" = "$b" ]; then same=$((same + 1)); else differ="$differ $name (${a:-none}; ${b:-none})"; fi
            [ "$name" = reference ] && ref=$b
        done
        check "graded with musl's libm as with the system's: $same of 9 the same${differ:+; differ:$differ}" \
            test "$same" -eq 9
        check "the reference keeps every point with musl ($ref)" test "$ref" = "summary 20 20 30 30 20 20 20 160 0"
        echo "   second C library: musl (musl-gcc), 9 submissions graded with both builds"
    fi
fi

# Against Apple's headers, when a macOS SDK is at hand (syntax only).
if [ -n "${MACOS_SDK:-}" ]; then
    if [ -d "$MACOS_SDK/usr/include" ] && have clang; then
        : >"$tmp/mac.log"
        for target in arm64-apple-macos13 x86_64-apple-macos10.15; do
            # shellcheck disable=SC2046,SC2086
            clang --target=$target -isysroot "$MACOS_SDK" $cflags -Werror -fsyntax-only -Ilabs \
                -DHARNESS_PART=PART_1 -DGRADER_ORACLE $(grep '\.c$' "$tmp/csrc") >>"$tmp/mac.log" 2>&1
            check "every C file against $MACOS_SDK for $target: $(grep -E 'error:|warning:' "$tmp/mac.log" | head -n 5 | tr '\n' ' ')" \
                test $? -eq 0
        done
    else
        fail "MACOS_SDK=$MACOS_SDK: no usr/include there, or no clang"
    fi
fi

echo "   portability checks took $(( $(date +%s) - start )) s"
finish
