#!/bin/sh
# The render and compare programs run as a user runs them: every shipped
# scene renders, every kind of bad command line and a bad scene of each
# way render meets one (the kinds: tests/unit/test_scene.c) are refused
# with a clear message and the right exit status (never a crash), nothing
# is left half-written, and compare tells equal images from different ones.
#
# Usage: sh tests/suites/render_cli.sh     (from the kit's top directory,
# after make; tests/run.sh does both).  The programs can be replaced with
# RENDER=... RENDER_LABS=... RENDER_ASAN=... COMPARE=...
# The last line is "N passed, N failed"; the exit status is 1 if any failed.
set -u

top=$(pwd)
RENDER=${RENDER:-out/build/sub/solutions/render}
RENDER_LABS=${RENDER_LABS:-out/build/sub/labs/render}
RENDER_ASAN=${RENDER_ASAN:-out/asan/bin/render-solutions}
COMPARE=${COMPARE:-out/build/bin/compare}

. tests/lib/checks.sh
# `make compare SUBMISSION=$tmp/...` builds in out/build/sub/<path with / as _>.
temp_dir render_cli '"$top/out/build/sub/$(printf "%s" "$tmp" | tr / _)"_*'

# The programs by absolute paths (a relative one is from the top directory).
for v in RENDER RENDER_LABS RENDER_ASAN COMPARE; do
    eval "case \$$v in /*) ;; *) $v=\$top/\$$v ;; esac"
done

# fail WHAT: counts a failure, shown with what went wrong.
fail() { fail_showing "$tmp/stderr" 5 '    stderr: ' "$@"; }

# run PROGRAM ARGS...: runs it; sets status, keeps stdout and stderr in
# files.  Also sets stderr_text (all of stderr) and stderr_lines (the lines
# that end in a newline, as wc -l counts them: a message without its final
# newline is not one line), read by the shell itself: these checks run
# hundreds of times, and a grep or a wc each is a process each.
run() {
    "$@" >"$tmp/stdout" 2>"$tmp/stderr"
    status=$?
    stderr_text= stderr_lines=0
    while IFS= read -r line; do
        stderr_text="$stderr_text$line
"
        stderr_lines=$((stderr_lines + 1))
    done <"$tmp/stderr"
    if [ -n "$line" ]; then
        stderr_text="$stderr_text$line"
    fi
}

# crashed: true when the last run died of a signal or a sanitizer spoke.
crashed() {
    [ "$status" -ge 128 ] && return 0
    case $stderr_text in
    *Sanitizer* | *"runtime error"*) return 0 ;;
    esac
    return 1
}

# exited WHAT N: true when the last run exited N; otherwise counts a
# failure that says how it ended instead (a crash, or another status).
exited() {
    if crashed; then
        fail "$1 crashed (exit $status)"
    elif [ "$status" -ne "$2" ]; then
        fail "$1: exit $status, want $2"
    else
        return 0
    fi
    return 1
}

# png_size FILE: prints "W H" from the PNG's header, or nothing if it is no PNG.
png_size() {
    [ -f "$1" ] || return 0
    signature=$(od -An -tx1 -N8 "$1" | tr -d ' \n')
    [ "$signature" = "89504e470d0a1a0a" ] || return 0
    od -An -tu1 -j16 -N8 "$1" |
        awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4, $5 * 16777216 + $6 * 65536 + $7 * 256 + $8 }'
}

# scene_size FILE: prints "W H" from the scene's image line.
scene_size() {
    awk '$1 == "image" { print $2, $3 }' "$1"
}

# (Every shipped scene rendered at its own size: make compare, below.)
# The default output is out/<scene name>.png, made in the current directory.
mkdir "$tmp/home"
(cd "$tmp/home" && "$RENDER" "$top/labs/scenes/flip.scene" --quiet >"$tmp/stdout" 2>"$tmp/stderr")
status=$?
got=$(png_size "$tmp/home/out/flip.png")
check "render flip.scene --quiet without -o: exit $status, out/flip.png '$got', want 0, '320 320' and no output" \
    sh -c "[ $status -eq 0 ] && [ '$got' = '320 320' ] && [ ! -s '$tmp/stdout' ]"

# A PPM output when the name ends in .ppm.
run "$RENDER" labs/scenes/flip.scene --size 16x8 --threads 1 -o "$tmp/flip.ppm"
check "render -o flip.ppm: exit $status, want a P6 file" \
    sh -c "[ $status -eq 0 ] && [ \"\$(head -c 2 '$tmp/flip.ppm' 2>/dev/null)\" = P6 ]"

# ---- --size overrides the scene's size ------------------------------------
# (one-row and one-column images: test_render's test_tiny_images, and
# test_png's round trips)
for size in 37x23 1x1; do
    run "$RENDER" labs/scenes/default.scene --size "$size" -o "$tmp/sized.png"
    got=$(png_size "$tmp/sized.png")
    check "render --size $size: exit $status, image '$got'" \
        sh -c "[ $status -eq 0 ] && [ '$got' = '$(echo "$size" | tr x ' ')' ] &&
               grep -q '^rendered default.scene $size with' '$tmp/stdout'"
    rm -f "$tmp/sized.png"
done

# The thread count is honoured (that the image does not depend on it:
# test_render's test_threads_byte_identical).
run "$RENDER" labs/scenes/default.scene --size 160x120 --threads 3 -o "$tmp/t3.png"
check "render --threads 3: exit $status, or not with 3 threads" \
    sh -c "[ $status -eq 0 ] && grep -q 'with 3 threads' '$tmp/stdout'"

# ---- bad command lines: exit 2 and the usage ------------------------------
# refused WHAT PROGRAM ARGS...: passes when PROGRAM exits 2 without a crash,
# render with its usage on stderr; WHAT names the run in a failure.
refused() {
    what=$1
    shift
    run "$@"
    exited "$what" 2 || return 0
    case $1 in
    "$RENDER") check "$what: no usage on stderr" grep -q "usage: render" "$tmp/stderr" ;;
    *) pass ;;
    esac
}
refused "render (no arguments)" "$RENDER"
# each an option and a value it refuses (split on the space)
for bad in "--size 0x5" "--size 5x" "--size abc" "--size 99999x2" "--size 16385x1" "--size 5x5x5" \
           "--size -5x5" "--size 99999999999999999999x5" "--threads abc" "--threads 0"; do
    refused "render $bad" "$RENDER" labs/scenes/default.scene $bad -o "$tmp/u.png"
done
refused "render --size (no value)" "$RENDER" labs/scenes/default.scene --size
refused "render -o (no value)" "$RENDER" labs/scenes/default.scene -o
refused "render -o x.jpg" "$RENDER" labs/scenes/default.scene -o "$tmp/u.jpg"
refused "render --bogus" "$RENDER" labs/scenes/default.scene --bogus
refused "render (two scenes)" "$RENDER" labs/scenes/default.scene labs/scenes/flip.scene
check "a refused command line still wrote an image" sh -c "[ ! -e '$tmp/u.png' ] && [ ! -e '$tmp/u.jpg' ]"

# ---- bad scenes: exit 1, "file:line: reason", no image, never a crash -----
# check_bad_scene PROGRAM FILE NAME LINE WORD: checks the render of FILE
# refuses it with a message holding "NAME:LINE: " (just "NAME: " when LINE
# is -) and WORD.
check_bad_scene() {
    rm -f "$tmp/bad-out.png"
    run "$1" "$2" -o "$tmp/bad-out.png"
    if [ "$4" = "-" ]; then where="$3: "; else where="$3:$4: "; fi
    exited "${1##*/} $3" 1 || return 0
    if case $stderr_text in *"$where"*) false ;; *) true ;; esac then
        fail "${1##*/} $3: the message does not say '$where'"
    elif case $stderr_text in *"$5"*) false ;; *) true ;; esac then
        fail "${1##*/} $3: the message does not say '$5'"
    elif [ "$stderr_lines" -ne 1 ]; then
        fail "${1##*/} $3: the message is not one line"
    elif [ -e "$tmp/bad-out.png" ]; then
        fail "${1##*/} $3: an image was written"
    else
        pass
    fi
}

# bad_scenes PROGRAM: bad scenes against one renderer, one of each way
# render meets them: a bad line (after a comment, which counts as a line),
# a scene with no image line, a file that is not there, a mesh that is not
# there.  Every kind of bad line and file is refused by the scene reader's
# own tests (tests/unit/test_scene.c); render refuses them all alike
# (render_main.c), which is what these hold.
bad_scenes() {
    p=$1
    rm -rf "$tmp/bad"
    mkdir "$tmp/bad"
    head='image 64 48'
    fov='fov 60'
    printf '%s\n' "$head" "$fov" "# a comment" "sphere 0 0 -5 1 1 0 0 9" >"$tmp/bad/long-sphere.scene"
    check_bad_scene "$p" "$tmp/bad/long-sphere.scene" long-sphere.scene 4 "got 8"
    printf '%s\n' "$fov" "sphere 0 0 -5 1 1 0 0" >"$tmp/bad/no-image.scene"
    check_bad_scene "$p" "$tmp/bad/no-image.scene" no-image.scene - "no image line"
    check_bad_scene "$p" "$tmp/bad/missing.scene" missing.scene - "No such file or directory"
    # the OBJ, read beside the scene: the message names it, then the scene's line
    printf '%s\n' "$head" "$fov" "mesh no-such.obj 1 0 0 0 1 1 1" >"$tmp/bad/mesh-missing.scene"
    check_bad_scene "$p" "$tmp/bad/mesh-missing.scene" no-such.obj - \
        "No such file or directory (the mesh of $tmp/bad/mesh-missing.scene:3)"
}
bad_scenes "$RENDER"

# ---- an output that cannot be written: exit 1 and no file, not even a part
# (Each way image_write fails, and that it leaves nothing: test_png's
# test_image_write_failures.)
run "$RENDER" labs/scenes/flip.scene --size 40x40 -o "$tmp/no/such/dir/x.png"
check "render -o into a missing directory: exit $status" \
    sh -c "[ $status -eq 1 ] && [ ! -e '$tmp/no' ] && grep -q x.png '$tmp/stderr'"

# ---- compare ---------------------------------------------------------------
run "$RENDER" labs/scenes/default.scene --size 120x90 --quiet -o "$tmp/ref.png"
run "$COMPARE" "$tmp/ref.png" "$tmp/ref.png"
check "compare of an image with itself: exit $status, want 0 and 'identical'" \
    sh -c "[ $status -eq 0 ] && grep -q identical '$tmp/stdout'"

# the same render as PPM compares identical with the PNG
run "$RENDER" labs/scenes/default.scene --size 120x90 --quiet -o "$tmp/ref.ppm"
run "$COMPARE" "$tmp/ref.ppm" "$tmp/ref.png" -o "$tmp/same-side.png"
check "compare of the PPM and the PNG of one render: exit $status, want 0" \
    sh -c "[ $status -eq 0 ] && grep -q identical '$tmp/stdout' && [ -f '$tmp/same-side.png' ]"

# the skeleton's render (the background only) against the reference's
run "$RENDER_LABS" labs/scenes/default.scene --size 120x90 --quiet -o "$tmp/sub.png"
run "$COMPARE" "$tmp/sub.png" "$tmp/ref.png" -o "$tmp/side.png"
size=$(png_size "$tmp/side.png")
width=${size% *}
height=${size#* }
if ! exited "compare of the skeleton's render with the reference" 1; then
    :
elif ! grep -q "differ" "$tmp/stdout" || ! grep -q "PSNR" "$tmp/stdout" || ! grep -q "%" "$tmp/stdout"; then
    fail "compare: no share of differing pixels or PSNR in: $(tr '\n' ' ' <"$tmp/stdout")"
elif [ -z "$size" ] || [ "$height" -ne $((90 + 11)) ] || [ "$width" -le 360 ] || [ "$width" -gt $((360 + 2 * 16)) ] ||
    [ $(((width - 360) % 2)) -ne 0 ]; then
    fail "compare -o: the side-by-side image is '$size', want 3 x 120 plus two gaps by 90 and the labels' band of 11"
else
    pass
fi

# The self-test submissions, a folder each (the instructor's kit).
selftest=$tmp/selftest
need_selftests "$selftest"

# A correct submission written independently of solutions/
# (tests/selftest/independent: the geometric method, the plain pixel
# formula, a plane through its constant n.p) renders, through `make
# compare` as a student runs it, the same image as the reference on every
# shipped scene but two hard cases: far.scene, which is there to show what
# a plain formula loses on a small, far sphere, and cracks.scene, which
# shows the cracks of a triangle test that is not watertight: its Part 5
# is Moller-Trumbore (tests/selftest/moller-trumbore, the skeleton's
# formula).  Each render of the submission's is at the scene's own size
# and says what it did.
if [ -d "$selftest/independent" ] && [ -d "$selftest/moller-trumbore" ]; then
    # In out/tests, not in $tmp: a folder the suite clears.
    sub=$PWD/out/tests/independent
    rm -rf "$sub"
    mkdir -p "$sub"
    cp "$selftest"/independent/*.c "$selftest"/moller-trumbore/*.c "$sub/"
    for scene in labs/scenes/*.scene; do
        name=$(basename "$scene" .scene)
        out=out/compare/$name-submission.png
        rm -f "$out"
        run ${MAKE:-make} --no-print-directory compare SUBMISSION="$sub" SCENE="$scene"
        want=$(scene_size "$scene")
        got=$(png_size "$out")
        check "render $scene: $out is '$got', want a PNG of $want, with a summary line and a 'wrote' line" \
            sh -c "[ '$got' = '$want' ] && grep -q '^wrote $out\$' '$tmp/stdout' &&
                   grep -q '^rendered $name.scene $(echo "$want" | tr ' ' x) with [0-9]* threads* in [0-9.]* s: [0-9.]* million rays/s' '$tmp/stdout'"
        # make turns compare's exit 1 (the images differ) into 2
        case $name in
        far) check "the independent submission renders far.scene like the reference (exit $status): the scene no longer shows the far sphere's rounding" \
                 grep -q "the images differ" "$tmp/stdout" ;;
        cracks) check "Moller-Trumbore renders cracks.scene like the watertight reference (exit $status): the scene no longer shows cracks" \
                    grep -q "the images differ" "$tmp/stdout" ;;
        *) check "the independent submission renders $name.scene unlike the reference (exit $status): $(grep 'differ' "$tmp/stdout")" \
               sh -c "[ $status -eq 0 ] && grep -q '^identical' '$tmp/stdout'" ;;
        esac
    done
fi

# Part 2 as the lecture writes it and the textbook's Part 4, both right
# (tests/selftest/textbook-ground): their rays and t differ from the
# reference's in the last bits, so where two surfaces meet (ground.scene's
# wall on the ground) or an outline runs through pixel centres
# (cracks.scene's box) rounding decides a few pixels' colour.  make compare
# takes the reference's pixels on an edge (render --edges) in their other
# colour as equal: identical on every shipped scene.  Without them the
# same renders differ (the check has something to forgive).
if [ -d "$selftest/textbook-ground" ]; then
    sub=$PWD/out/tests/textbook-ground
    rm -rf "$sub"
    mkdir -p "$sub"
    cp solutions/*.c "$sub/"
    cp "$selftest"/textbook-ground/*.c "$sub/"
    for scene in labs/scenes/*.scene; do
        name=$(basename "$scene" .scene)
        run ${MAKE:-make} --no-print-directory compare SUBMISSION="$sub" SCENE="$scene"
        check "the lecture's Part 2 and the textbook's Part 4 render $name.scene as the reference does (exit $status): $(grep 'differ' "$tmp/stdout" | tr '\n' ' ')" \
            sh -c "[ $status -eq 0 ] && grep -q '^identical' '$tmp/stdout'"
        case $name in ground | cracks)
            run "$COMPARE" out/compare/$name-submission.png out/compare/$name-reference.png
            check "without the pixels on an edge, the textbook's $name.scene differs from the reference's (exit $status)" \
                sh -c "[ $status -eq 1 ] && grep -q '^the images differ' '$tmp/stdout'" ;;
        esac
    done
fi

# render --edges on ground.scene: the ground (y = -1) meets the wall
# (x = 7) where x = -7 y on the image plane, that is (i + 1/2 - 320) =
# -7 (240 - j - 1/2) at 640 x 480: i = 7 j - 1357.  Below the yellow
# sphere, rows 263 to 285 (the last whose i is in the image), nothing
# hides it.  Every pixel on an edge is on that line, in the wall's colour
# (0.82 0.74 0.64: 209 189 163) as its other, and none of those rows' is
# missing.
run "$RENDER" labs/scenes/ground.scene --quiet -o "$tmp/ground.png" --edges "$tmp/ground.edges"
check "render --edges ground.scene (exit $status)" sh -c "[ $status -eq 0 ] && [ -s '$tmp/ground.edges' ]"
check "render --edges ground.scene: every pixel on an edge is on the wall's foot, i = 7 j - 1357, with the wall's colour: $(sed -n '5,8p' "$tmp/ground.edges" | tr '\n' '|')" \
    sh -c "awk 'NR > 4 && !(\$1 == 7 * \$2 - 1357 && NF == 5 && \$3 == 209 && \$4 == 189 && \$5 == 163) { bad = 1 }
                \$2 >= 263 && \$2 <= 285 { rows++ } END { exit bad || rows != 23 }' '$tmp/ground.edges'"

# compare --edges takes a pixel on an edge as equal only in a colour the
# file lists for it; a bad file of edges is an error (exit 2) naming its
# line.  The images: the reference's 120 x 90 render, and a copy with
# pixel (5, 2) changed (written as PPM by the shell).
ppm_pixel() {   # ppm_pixel IN OUT R G B: OUT is IN with pixel (5, 2) in R G B
    head -c 14 "$1" >"$2"                           # "P6\n120 90\n255\n"
    tail -c +15 "$1" | head -c $(((2 * 120 + 5) * 3)) >>"$2"
    printf "\\$(printf %o "$3")\\$(printf %o "$4")\\$(printf %o "$5")" >>"$2"
    tail -c +$((15 + (2 * 120 + 6) * 3)) "$1" >>"$2"
}
run "$RENDER" labs/scenes/default.scene --size 120x90 --quiet -o "$tmp/e-ref.ppm"
if [ "$(head -c 14 "$tmp/e-ref.ppm" | tr '\n' ' ')" = "P6 120 90 255 " ]; then
    ppm_pixel "$tmp/e-ref.ppm" "$tmp/e-sub.ppm" 1 2 3
    printf '# test\nsize 120 90\n5 2  9 9 9  1 2 3\n' >"$tmp/e-ok.edges"
    printf 'size 120 90\n5 2  9 9 9\n' >"$tmp/e-other.edges"
    run "$COMPARE" "$tmp/e-sub.ppm" "$tmp/e-ref.ppm" --edges "$tmp/e-ok.edges"
    check "compare --edges: a pixel on an edge in a colour listed for it is equal (exit $status)" \
        sh -c "[ $status -eq 0 ] && grep -q '^1 pixel on an edge' '$tmp/stdout' && grep -q '^identical' '$tmp/stdout'"
    run "$COMPARE" "$tmp/e-sub.ppm" "$tmp/e-ref.ppm" --edges "$tmp/e-other.edges"
    check "compare --edges: a pixel on an edge in a colour not listed differs (exit $status)" \
        sh -c "[ $status -eq 1 ] && grep -q '(1 of 10800)' '$tmp/stdout'"
    # each: the file's lines, what is wrong, what the message must hold
    for bad in 'size 120 90|5 2  9 9|a colour of two numbers|:2:' 'size 120 90|120 2  9 9 9|column 120|:2:' \
               'size 120 90|5 2  9 9 256|colour 256|:2:' 'size 120 90|5 2  9 9 9|4 2  9 9 9|out of order|:3:' \
               '5 2  9 9 9|no size line|:1:' 'size 60 90|5 2  9 9 9|another size|60x90'; do
        want=${bad##*|}
        rest=${bad%|*}
        what=${rest##*|}
        printf '%s\n' "${rest%|*}" | tr '|' '\n' >"$tmp/e-bad.edges"
        run "$COMPARE" "$tmp/e-sub.ppm" "$tmp/e-ref.ppm" --edges "$tmp/e-bad.edges"
        check "compare --edges with a bad file ($what): exit $status, want 2 and '$want' in: $stderr_text" \
            sh -c "[ $status -eq 2 ] && grep -q -- '$want' '$tmp/stderr'"
    done
else
    fail "render -o x.ppm: not a 120 x 90 binary PPM: $(head -c 14 "$tmp/e-ref.ppm" | tr '\n' ' ')"
fi

# A repository made from the student kit: its stage files are in labs/,
# and make compare renders them from there, as the grader grades them (it
# once rendered the kit's own skeletons instead, without a word).
repo=$PWD/out/tests/repo-layout
rm -rf "$repo"
mkdir -p "$repo/labs"
cp solutions/*.c "$repo/labs/"
run ${MAKE:-make} --no-print-directory compare SUBMISSION="$repo"
check "make compare SUBMISSION=<a student kit's repository> renders its labs/ (exit $status)" \
    sh -c "[ $status -eq 0 ] && grep -q '^identical' '$tmp/stdout'"

# A mistyped SUBMISSION is refused, and nothing is drawn (it once drew the
# skeletons over the picture).
run ${MAKE:-make} --no-print-directory render SUBMISSION="$tmp/no-such-folder" OUT="$tmp/typo.png"
check "make render SUBMISSION=<no such folder> is refused (exit $status), and draws nothing" \
    sh -c "[ $status -eq 2 ] && grep -q 'SUBMISSION=$tmp/no-such-folder is not a directory' '$tmp/stdout' &&
           [ ! -e '$tmp/typo.png' ]"

# A stage file with characters that only look like C's (a non-breaking
# space and a curly quote, as pasted from a web page): make render names
# them with their line, as the grader does; it once showed only the
# compiler's "stray '\342' in program".  One saved as UTF-16 is named so.
mkdir -p "$tmp/pasted" "$tmp/utf16"
nbsp=$(printf '\302\240')
sed "/^ *double tan_half = /s/ = / $nbsp= /" solutions/part1_image_plane.c >"$tmp/pasted/part1_image_plane.c"
printf 'static const char *where = \342\200\234here\342\200\235;\n' >>"$tmp/pasted/part1_image_plane.c"
run ${MAKE:-make} --no-print-directory render SUBMISSION="$tmp/pasted" OUT="$tmp/pasted.png"
at=$(grep -n 'double tan_half' "$tmp/pasted/part1_image_plane.c" | sed -n 1s/:.*//p)
check "make render names a pasted non-breaking space and curly quotes, with their lines (exit $status)" \
    sh -c "[ $status -eq 2 ] && [ ! -e '$tmp/pasted.png' ] &&
           grep -q 'characters that look like C.s but are not' '$tmp/stderr' &&
           grep -q 'part1_image_plane.c:$at: a non-breaking space (U+00A0): type an ordinary space' '$tmp/stderr' &&
           grep -q 'part1_image_plane.c:[0-9]*: a curly opening double quote (U+201C): type a straight \"' '$tmp/stderr'"
printf '\377\376i\000n\000t\000 \000x\000;\000\n\000' >"$tmp/utf16/part1_image_plane.c"
run ${MAKE:-make} --no-print-directory render SUBMISSION="$tmp/utf16" OUT="$tmp/utf16.png"
check "make render says a stage file saved as UTF-16 is, and to save it as UTF-8 (exit $status)" \
    sh -c "[ $status -eq 2 ] && grep -q 'part1_image_plane.c is saved as UTF-16 .*save it as UTF-8' '$tmp/stderr'"

# A stage file that includes a header of the student's own, beside it:
# make render found it (the file is compiled where it lies), the grader
# does not (it builds each stage file alone), so the render worked and the
# grade was 0.  make render now refuses it, saying why, as the grader does;
# with the header's function moved into the file it renders.
mkdir -p "$tmp/ownhdr"
cp solutions/*.c "$tmp/ownhdr/"
printf 'static double my_dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }\n' \
    >"$tmp/ownhdr/myvec.h"
{ sed -n '1,/#include "raytracer.h"/p' solutions/part3a_sphere_intersect.c
  echo '#include "myvec.h"'
  echo 'double twice_dot(Vec3 a) { return 2 * my_dot(a, a); }'
  sed '1,/#include "raytracer.h"/d' solutions/part3a_sphere_intersect.c; } >"$tmp/ownhdr/part3a_sphere_intersect.c"
at=$(grep -n '#include "myvec.h"' "$tmp/ownhdr/part3a_sphere_intersect.c" | sed 's/:.*//')
run ${MAKE:-make} --no-print-directory render SUBMISSION="$tmp/ownhdr" OUT="$tmp/ownhdr.png"
check "make render refuses a stage file that includes a header of its own, naming it and its line (exit $status)" \
    sh -c "[ $status -eq 2 ] && [ ! -e '$tmp/ownhdr.png' ] &&
           grep -q 'part3a_sphere_intersect.c:$at: #include \"myvec.h\": the grader will not have myvec.h' '$tmp/stderr' &&
           grep -q 'put what myvec.h holds into .*part3a_sphere_intersect.c itself' '$tmp/stderr'"
awk -v h="$(cat "$tmp/ownhdr/myvec.h")" '$0 == "#include \"myvec.h\"" { $0 = h } 1' \
    "$tmp/ownhdr/part3a_sphere_intersect.c" >"$tmp/ownhdr/part3a.c"
mv "$tmp/ownhdr/part3a.c" "$tmp/ownhdr/part3a_sphere_intersect.c"
run ${MAKE:-make} --no-print-directory render SUBMISSION="$tmp/ownhdr" OUT="$tmp/ownhdr.png"
check "... and renders it once the header's function is in the file (exit $status)" \
    sh -c "[ $status -eq 0 ] && [ -s '$tmp/ownhdr.png' ]"
# What the grader refuses outright, make render refuses with its words
# (a kit header by a path with .., which the compiler would find).
mkdir -p "$tmp/dotdot"
cp solutions/*.c "$tmp/dotdot/"
sed "s|#include \"raytracer.h\"|#include \"../../labs/raytracer.h\"|" solutions/part2_pixel_coordinates.c \
    >"$tmp/dotdot/part2_pixel_coordinates.c"
run ${MAKE:-make} --no-print-directory render SUBMISSION="$tmp/dotdot" OUT="$tmp/dotdot.png"
check "make render refuses an include the grader refuses, in the grader's words (exit $status)" \
    sh -c "[ $status -eq 2 ] && [ ! -e '$tmp/dotdot.png' ] &&
           grep -q 'part2_pixel_coordinates.c: refused, as the grader refuses it: .*write #include \"raytracer.h\"' '$tmp/stderr'"

# Links that fail.  A helper defined, not static, in two stage files: the
# grader builds each file alone and gives full marks, but make render links
# them together and the linker refuses; make render says why, and that
# static is the cure.  A function of the contract defined twice, and one
# its file does not define: said as plainly.
mkdir -p "$tmp/twice"
cp solutions/*.c "$tmp/twice/"
for f in part2_pixel_coordinates part3a_sphere_intersect; do
    printf 'double sq(double x);\ndouble sq(double x) { return x * x; }\n' >>"$tmp/twice/$f.c"
done
run ${MAKE:-make} --no-print-directory render SUBMISSION="$tmp/twice" OUT="$tmp/twice.png"
check "make render says a helper is defined in two stage files, and to make each static (exit $status)" \
    sh -c "[ $status -eq 2 ] && [ ! -e '$tmp/twice.png' ] &&
           grep -q 'make render: sq is defined in .*/part2_pixel_coordinates.c and .*/part3a_sphere_intersect.c' '$tmp/stderr' &&
           grep -q 'write static in front of each' '$tmp/stderr' &&
           grep -q 'definition of sq' '$tmp/stderr'"
for f in part2_pixel_coordinates part3a_sphere_intersect; do
    sed 's/^double sq(/static double sq(/' "$tmp/twice/$f.c" >"$tmp/twice/x.c"
    mv "$tmp/twice/x.c" "$tmp/twice/$f.c"
done
run ${MAKE:-make} --no-print-directory render SUBMISSION="$tmp/twice" OUT="$tmp/twice.png"
check "... and renders once both are static (exit $status)" \
    sh -c "[ $status -eq 0 ] && [ -s '$tmp/twice.png' ]"
sed -n '/^bool sphere_intersect(/,/^}/p' solutions/part3a_sphere_intersect.c >>"$tmp/twice/part3b_ray_color.c"
run ${MAKE:-make} --no-print-directory render SUBMISSION="$tmp/twice" OUT="$tmp/twice.png"
check "make render says a function of the contract defined twice belongs in its own file (exit $status)" \
    sh -c "[ $status -eq 2 ] &&
           grep -q 'It belongs in part3a_sphere_intersect.c only .*remove it from .*/part3b_ray_color.c' '$tmp/stderr'"
cp solutions/part3b_ray_color.c "$tmp/twice/"
sed 's/^bool sphere_intersect(/bool sphere_intersects(/' solutions/part3a_sphere_intersect.c \
    >"$tmp/twice/part3a_sphere_intersect.c"
run ${MAKE:-make} --no-print-directory render SUBMISSION="$tmp/twice" OUT="$tmp/twice.png"
check "make render says a stage file does not define its function of the contract (exit $status)" \
    sh -c "[ $status -eq 2 ] &&
           grep -q 'part3a_sphere_intersect.c defines no function sphere_intersect, which the renderer\$' '$tmp/stderr' &&
           grep -q 'The functions it defines: sphere_intersects\.\$' '$tmp/stderr'"

# misbehaving DIR STATEMENT: a submission in DIR, the reference's but for a
# Part 3b whose ray_color runs STATEMENT for the pixels right of the centre.
misbehaving() {
    mkdir -p "$1"
    cp solutions/*.c "$1/"
    cat >"$1/part3b_ray_color.c" <<EOF2
#include <stddef.h>
#include "raytracer.h"

Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    Ray ray = { eye, vec3_normalize(vec3_sub(pixel, eye)) };
    return ray;
}

Vec3 ray_color(const Scene *scene, const Ray *ray)
{
    if (ray->direction.x > 0) {
        $2
    }
    return scene->background;
}
EOF2
}

# Code of the parts that crashes while drawing: the renderer says where
# and what, and still ends by the signal (make reports it); nothing is
# written.  It once ended with the shell's "Segmentation fault" alone.
misbehaving "$tmp/crashes" '*(volatile int *)NULL = 1;'
run ${MAKE:-make} --no-print-directory render SUBMISSION="$tmp/crashes" SIZE=40x30 OUT="$tmp/crashes.png"
check "code that crashes while drawing: the renderer says where and what (exit $status)" \
    sh -c "[ $status -ne 0 ] &&
           grep -q 'render: the code of the parts crashed while drawing rows* [0-9]*.*: a segmentation fault (SIGSEGV)' '$tmp/stderr'"
check "... and writes no picture" [ ! -e "$tmp/crashes.png" ]

# Code that loops forever: once no row has been finished for a while
# (RENDER_STALLED_SECONDS here, 10 s by default), a line says how to stop
# it, on a terminal and elsewhere (output to a file or a pipe, as a log or
# an editor's pane takes it), where it once waited in silence.  A terminal through
# util-linux's script, where there is one.
misbehaving "$tmp/loops" 'for (volatile int forever = 1; forever;) ;'
loops_bin=out/build/sub/$(printf '%s' "$tmp/loops" | tr / _)/render
run ${MAKE:-make} --no-print-directory "$loops_bin" SUBMISSION="$tmp/loops"
RENDER_STALLED_SECONDS=1 "$loops_bin" labs/scenes/default.scene --size 40x30 -o "$tmp/loops.png" \
    </dev/null >"$tmp/loops-pipe.out" 2>&1 &
loops_pid=$!
sleep 3
kill "$loops_pid" 2>/dev/null
wait "$loops_pid" 2>/dev/null
check "code that loops forever, its output to a file: a line says how to stop it" \
    grep -q '^render: no row finished in the last 1 s: if the code loops forever, stop it with Ctrl-C' \
    "$tmp/loops-pipe.out"
if script --version 2>/dev/null | grep -q util-linux; then
    loops_cmd="timeout 3 $loops_bin labs/scenes/default.scene --size 40x30 -o $tmp/loops.png"  # portable: util-linux only
    RENDER_STALLED_SECONDS=1 script -qec "$loops_cmd" /dev/null </dev/null >"$tmp/loops.out" 2>&1  # portable: util-linux only
    check "code that loops forever: on a terminal, a line says how to stop it" \
        grep -q 'no row finished in the last 1 s: if the code loops forever, stop it with Ctrl-C' "$tmp/loops.out"
else
    echo "   skipped: the endless-loop line (util-linux's script, which gives a terminal, is not here)"
fi

# A shipped scene named without its folder: the message says where it is.
run "$RENDER" wide --quiet -o "$tmp/wide-typo.png"
check "a scene named 'wide': exit $status, and the message names labs/scenes/wide.scene" \
    sh -c "[ $status -eq 1 ] && grep -q 'SCENE=labs/scenes/wide.scene' '$tmp/stderr' && [ ! -e '$tmp/wide-typo.png' ]"

# images of different sizes: a clear message, exit 1
run "$RENDER" labs/scenes/default.scene --size 60x90 --quiet -o "$tmp/small.png"
run "$COMPARE" "$tmp/small.png" "$tmp/ref.png"
check "compare of images of different sizes: exit $status, want 1 and a message" \
    sh -c "[ $status -eq 1 ] && grep -q size '$tmp/stderr' && grep -q 60x90 '$tmp/stderr'"

# errors and bad usage: exit 2
refused "compare (no arguments)" "$COMPARE"
refused "compare (one image)" "$COMPARE" "$tmp/ref.png"
refused "compare (three images)" "$COMPARE" "$tmp/ref.png" "$tmp/ref.png" "$tmp/ref.png"
refused "compare (a missing image)" "$COMPARE" "$tmp/ref.png" "$tmp/missing.png"
refused "compare (-o without a name)" "$COMPARE" "$tmp/ref.png" "$tmp/ref.png" -o
refused "compare (unwritable -o)" "$COMPARE" "$tmp/ref.png" "$tmp/ref.png" -o "$tmp/no/such/side.png"
run "$COMPARE"
check_has "compare: the usage does not explain the exit status" "$tmp/stderr" \
    'usage: compare' 'exit status: 0 identical, 1 .*differ, 2 error'

# ---- the same bad scenes against the address-sanitized renderer -----------
if [ -x "$RENDER_ASAN" ]; then
    run "$RENDER_ASAN" labs/scenes/default.scene --size 64x48 --threads 2 -o "$tmp/asan.png"
    exited "sanitized render of default.scene" 0 && pass
    bad_scenes "$RENDER_ASAN"
else
    echo "note: no sanitized renderer at $RENDER_ASAN (make $RENDER_ASAN): its checks were skipped"
fi

finish
