#!/bin/sh
# The kit keeps itself in step:
# - labs/ and solutions/ carry the same contract comments: outside the
#   function bodies the stage files are identical;
# - the committed public tests match what the oracle writes now;
# - labs/scenes/cracks.obj and knot.obj are what tests/tools/cracks-mesh.sh
#   and knot-mesh.sh write;
# - labs/raytracer.h keeps the lab contract (when the contract probe is
#   beside the kit);
# - a make target's usage names the settings make help names.
set -u
. tests/lib/checks.sh
temp_dir rtconsistency

# Everything but the bodies: drop the lines from a "{" at the start of a
# line to the matching "}" at the start of a line, and #include lines.
outside() { awk '/^\{/ { inside = 1 } !inside && !/^#include/ { print } /^\}/ { inside = 0 }' "$1"; }
for f in labs/part*.c; do
    base=$(basename "$f")
    outside "$f" >"$tmp/labs"
    outside "solutions/$base" >"$tmp/solutions"
    check "labs/$base and solutions/$base differ outside the function bodies" \
        cmp -s "$tmp/labs" "$tmp/solutions"
    check_has "labs/$base has a contract comment with an example and a formula" "$f" \
        ' \* Example:' ' \* Formula:'
done

if [ -x out/build/bin/gentests ]; then
    mkdir "$tmp/public"
    out/build/bin/gentests "$tmp/public"
    for f in tests/public/*.tests; do
        check "$f is out of date: run make public-tests" cmp -s "$f" "$tmp/public/$(basename "$f")"
    done
fi

# The closed meshes of cracks.scene and knot.scene are what their
# generators write.
for mesh in cracks knot; do
    if [ -f "tests/tools/$mesh-mesh.sh" ]; then
        sh "tests/tools/$mesh-mesh.sh" >"$tmp/$mesh.obj"
        check "labs/scenes/$mesh.obj is out of date: run sh tests/tools/$mesh-mesh.sh >labs/scenes/$mesh.obj" \
            cmp -s "labs/scenes/$mesh.obj" "$tmp/$mesh.obj"
    fi
done

# A make target's usage, given when a setting it needs is missing, is the
# line make help gives it: the same settings.
make -s --no-print-directory help >"$tmp/help" 2>&1 </dev/null
for target in grade-all sort-submissions; do
    make -s --no-print-directory "$target" >"$tmp/usage" 2>&1 </dev/null
    usage=$(sed -n 's/^usage: //p' "$tmp/usage")
    check "make $target's usage ($usage) is its line in make help" \
        sh -c "[ -n \"\$1\" ] && grep -qxF -e \"\$1\" '$tmp/help'" sh "$usage"
done

probe=../shared/contract/probe.c
if [ -f "$probe" ]; then
    check "labs/raytracer.h keeps the lab contract" \
        ${CC:-cc} -std=c11 -Wall -Wextra -Werror -I labs -c "$probe" -o "$tmp/probe.o"
else
    echo "the lab contract's probe ($probe) is not beside the kit: skipped compiling it against labs/raytracer.h"
fi

finish
