#!/bin/sh
# The bounding volume hierarchy changes no picture: for the reference, the
# textbook submission and every self-test submission with a Part 5 of its
# own (tests/selftest: Moller-Trumbore, each p5-* mistake, the real-world
# ones), every shipped scene renders byte for byte the same with
# `--hierarchy on` as with `--hierarchy off`, which tests every object for
# every ray.  The reference meets no stray hit (labs/kit/closest.h), so its
# pictures did come through the hierarchy.
#
# Each submission's renderer is linked here without link-time optimisation,
# from its own stage files and the reference's for the other parts
# (out/build/sub/solutions), as the grader builds it: a second or so for
# all of them, where `make render` takes that for each.  The scenes render
# at 160 x 120, knot.scene (10,000 triangles a ray without the hierarchy)
# at 80 x 60, cracks.scene at its own size, where its rays run along the
# triangles' edges.
set -u
. tests/lib/checks.sh

if [ ! -d solutions ]; then
    echo "no solutions/: this suite is the instructor kit's"
    echo "0 passed, 0 failed"
    exit 0
fi
for f in out/build/kit/libkit.a out/build/sub/solutions/part5_triangle_intersect.o; do
    if [ ! -f "$f" ]; then
        echo "FAIL: $f is missing: run make first"
        echo "0 passed, 1 failed"
        exit 1
    fi
done
# In out/tests, not in a temporary directory: a folder the suite clears.
dir=$PWD/out/tests/hierarchy
rm -rf "$dir"
mkdir -p "$dir"
stages="part1_image_plane part2_pixel_coordinates part3a_sphere_intersect part3b_ray_color
        part4_plane_intersect part5_triangle_intersect"

cc_flags=$(${MAKE:-make} -s --no-print-directory print-cflags)
# shellcheck disable=SC2086
if ! ${CC:-cc} $cc_flags -c labs/kit/render_main.c -o "$dir/render_main.o" -pthread >"$dir/build.log" 2>&1; then
    fail "render_main.c does not compile: $(head -n 3 "$dir/build.log")"
fi

# link NAME SUBMISSION: builds $dir/NAME/render from SUBMISSION's stage
# files and the reference's for the others.
link() {
    mkdir -p "$dir/$1"
    : >"$dir/$1/build.log"
    objs=
    for s in $stages; do
        if [ -f "$2/$s.c" ]; then
            # shellcheck disable=SC2086
            ${CC:-cc} $cc_flags -Ilabs -c "$2/$s.c" -o "$dir/$1/$s.o" >>"$dir/$1/build.log" 2>&1 || return 1
            objs="$objs $dir/$1/$s.o"
        else
            objs="$objs out/build/sub/solutions/$s.o"
        fi
    done
    # shellcheck disable=SC2086
    ${CC:-cc} $cc_flags -pthread "$dir/render_main.o" $objs out/build/kit/libkit.a -o "$dir/$1/render" -lm \
        >>"$dir/$1/build.log" 2>&1
}

# same NAME: renders every shipped scene with NAME's renderer both ways;
# one check per scene.  Sets strays to the scenes where a stray hit set
# the hierarchy aside.
same() {
    strays=
    for scene in labs/scenes/*.scene; do
        base=$(basename "$scene" .scene)
        case $base in
        cracks) size= ;;
        knot) size="--size 80x60" ;;
        *) size="--size 160x120" ;;
        esac
        # shellcheck disable=SC2086
        "$dir/$1/render" "$scene" $size --hierarchy on -o "$dir/$1/on.ppm" >"$dir/$1/on.out" 2>&1
        on=$?
        # shellcheck disable=SC2086
        "$dir/$1/render" "$scene" $size --hierarchy off --quiet -o "$dir/$1/off.ppm" >"$dir/$1/off.out" 2>&1
        off=$?
        check "$1: $base.scene renders unlike itself with the hierarchy (exit $on and $off)" \
            sh -c "[ $on -eq 0 ] && [ $off -eq 0 ] && cmp -s '$dir/$1/on.ppm' '$dir/$1/off.ppm'"
        if grep -q "set it aside" "$dir/$1/on.out"; then
            strays="$strays $base"
        fi
    done
}

# The self-test submissions, written out where their paths stay the same
# (and hold no space: $subs is split on them).
selftest=out/tests/hierarchy/selftest
need_selftests "$selftest"
subs="solutions $selftest/textbook"
for f in "$selftest"/*/part5_triangle_intersect.c; do
    subs="$subs ${f%/part5_triangle_intersect.c}"
done
for sub in $subs; do
    name=$(basename "$sub")
    if ! link "$name" "$sub"; then
        fail "$name: the renderer does not build: $(head -n 3 "$dir/$name/build.log")"
        continue
    fi
    same "$name"
    # (Moller-Trumbore meets some in cracks.scene, whose side walls lie in
    # planes through the eye: closest_probe's rays from the eye lie in
    # them, and its t there is far off.)
    case $name in
    solutions | textbook)
        check "$name: the reference's Part 5 met a stray hit in:$strays" [ -z "$strays" ] ;;
    esac
done

# The hierarchy is built where it is meant to be, and said so.
"$dir/solutions/render" labs/scenes/knot.scene --size 64x48 -o "$dir/knot.ppm" >"$dir/knot.out" 2>&1
check_has "render knot.scene says how many triangles it read and the hierarchy it built" "$dir/knot.out" \
    '^read knot.scene in [0-9.]* s: 10000 triangles$' \
    '^built a hierarchy of 10000 triangles in [0-9]* nodes in [0-9.]* s$'
"$dir/solutions/render" labs/scenes/triangles.scene --size 64x48 -o "$dir/tri.ppm" >"$dir/tri.out" 2>&1
check "render triangles.scene (4 triangles) builds no hierarchy" \
    sh -c "grep -q '^read triangles.scene' '$dir/tri.out' && ! grep -q '^built' '$dir/tri.out'"
"$dir/solutions/render" labs/scenes/default.scene --size 64x48 --hierarchy on -o "$dir/d.ppm" >"$dir/d.out" 2>&1
check "render default.scene (spheres alone, Part 3b's) builds no hierarchy, even asked to" \
    sh -c "grep -q '^rendered default.scene' '$dir/d.out' && ! grep -q -e '^built' -e '^read' '$dir/d.out'"
"$dir/solutions/render" labs/scenes/knot.scene --hierarchy sometimes >"$dir/bad.out" 2>&1
status=$?
check "render --hierarchy sometimes is refused (exit $status)" \
    sh -c "[ $status -eq 2 ] && grep -q -- '--hierarchy wants auto, on or off' '$dir/bad.out'"
"$dir/p5-no-sum-check/render" labs/scenes/knot.scene --size 64x48 -o "$dir/ns.ppm" >"$dir/ns.out" 2>"$dir/ns.err"
check "a stray hit is explained before the slow render, and the hierarchy said set aside" \
    sh -c "grep -q 'render: note: sphere_intersect or triangle_intersect said a ray hit' '$dir/ns.err' &&
           grep -q 'then set it aside: a stray hit' '$dir/ns.out'"

finish
