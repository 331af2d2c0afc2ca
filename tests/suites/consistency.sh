#!/bin/sh
# The kit keeps itself in step:
# - labs/ and solutions/ carry the same contract comments: outside the
#   function bodies the stage files are identical;
# - the committed public tests match what the oracle writes now;
# - labs/scenes/cracks.obj and knot.obj are what tests/tools/cracks-mesh.sh
#   and knot-mesh.sh write;
# - labs/raytracer.h keeps the lab contract (when the contract probe is
#   beside the kit).
set -u
. tests/lib/checks.sh
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rtconsistency.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# Everything but the bodies: drop the lines from a "{" at the start of a
# line to the matching "}" at the start of a line, and #include lines.
outside() { awk '/^\{/ { inside = 1 } !inside && !/^#include/ { print } /^\}/ { inside = 0 }' "$1"; }
for f in labs/part*.c; do
    base=$(basename "$f")
    outside "$f" >"$tmp/labs"
    outside "solutions/$base" >"$tmp/solutions"
    check "labs/$base and solutions/$base differ outside the function bodies" \
        cmp -s "$tmp/labs" "$tmp/solutions"
    check "labs/$base has a contract comment with an example and a formula" \
        sh -c "grep -q ' \* Example:' '$f' && grep -q ' \* Formula:' '$f'"
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

probe=../shared/contract/probe.c
if [ -f "$probe" ]; then
    check "labs/raytracer.h keeps the lab contract" \
        ${CC:-cc} -std=c11 -Wall -Wextra -Werror -I labs -c "$probe" -o "$tmp/probe.o"
else
    echo "the lab contract's probe ($probe) is not beside the kit: skipped compiling it against labs/raytracer.h"
fi

finish
