# cc_build.sh - builds a suite's small C helper program.  A suite sources it
# from the kit's top directory:
#     . tests/lib/cc_build.sh
#     cc_build DIR PROGRAM LOG FILE.c...
# compiles each FILE.c on its own with the kit's flags (the Makefile's
# CFLAGS, asked of make once) and -Werror, then links the objects into
# DIR/PROGRAM with -lm; the compiler's words go to LOG.  Returns the first
# failing step's status.
cc_build() {
    cc_dir=$1 cc_prog=$2 cc_log=$3
    shift 3
    : >"$cc_log"
    if [ -z "${cc_flags:-}" ]; then
        cc_flags=$(${MAKE:-make} -s --no-print-directory print-cflags 2>>"$cc_log") && [ -n "$cc_flags" ] ||
            { echo "cc_build: make print-cflags failed" >>"$cc_log"; return 1; }
    fi
    cc_objs=
    for cc_src in "$@"; do
        cc_obj=${cc_src##*/}
        cc_obj=${cc_obj%.c}.o
        # shellcheck disable=SC2086
        ${CC:-cc} $cc_flags -Werror -c "$cc_src" -o "$cc_dir/$cc_obj" >>"$cc_log" 2>&1 || return
        cc_objs="$cc_objs $cc_obj"
    done
    # shellcheck disable=SC2086
    (cd "$cc_dir" && ${CC:-cc} $cc_flags $cc_objs -o "$cc_prog" -lm) >>"$cc_log" 2>&1
}
