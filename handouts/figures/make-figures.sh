#!/bin/sh
# make-figures.sh - renders the handouts' figures into handouts/figures/.
#
#     make handouts        (runs this script from the kit's top directory)
#
# Every figure is drawn by the kit itself:
#   scene-NAME.png       the reference solution's render of labs/scenes/NAME.scene;
#   mistake-*.png        a common mistake next to the reference: a submission
#                        assembled in a temporary directory from solutions/
#                        plus the faulty stage file of self-test CASE
#                        (tests/lib/selftests.sh writes them out),
#                        rendered with `make render`, then compare's
#                        side-by-side image: the mistake | the reference |
#                        a heat map of their difference;
#   hard-*.png           the same for the hard cases: far.scene with the
#                        lecture's textbook quadratic (self-test textbook),
#                        in double and, made from it here, in float; and
#                        cracks.scene with Moller-Trumbore's triangle test.
#   report-*.svg         a figure of the report page `make grade` writes
#                        (out/report/index.html): the first failing test of
#                        one faulty stage file, drawn by the grader.
# Sizes are kept small so that each PNG stays a few kilobytes.  The output
# depends only on the sources: rerunning changes no byte of an unchanged
# figure.  Needs solutions/, out/build/sub/solutions/render,
# out/build/bin/compare and out/build/bin/grade (`make handouts` builds them).
set -eu

MAKE=${MAKE:-make}
top=$(pwd)
figs=handouts/figures
render=out/build/sub/solutions/render
compare=out/build/bin/compare

if [ ! -d solutions ] || [ ! -x "$render" ] || [ ! -x "$compare" ]; then
    echo "make-figures.sh: needs solutions/, $render and $compare (run make handouts)" >&2
    exit 2
fi

mkdir -p out "$figs"
work=$(mktemp -d "$top/out/figures.XXXXXX")
# `make render SUBMISSION=dir` builds in out/build/sub/<dir with / as _>.
builds="$top/out/build/sub/$(printf '%s' "$work" | tr / _)"
trap 'rm -rf "$work" "$builds"_*' EXIT
trap 'exit 1' HUP INT TERM
# The self-test submissions, a folder each.
selftest=$work/selftest
sh tests/lib/selftests.sh "$selftest"

# reference SCENE SIZE: the reference's render, as figure scene-SCENE.png.
reference() {
    "$render" "labs/scenes/$1.scene" --size "$2" --quiet -o "$figs/scene-$1.png"
    echo "wrote $figs/scene-$1.png"
}

# assemble NAME CASE: a submission directory $work/NAME holding the reference
# stage files with those of self-test CASE in their place.
assemble() {
    mkdir -p "$work/$1"
    cp solutions/*.c "$work/$1/"
    cp "$selftest/$2/"*.c "$work/$1/"
}

# side_by_side NAME SCENE SIZE: renders the submission $work/NAME with
# `make render` and writes figure NAME.png: it | the reference | difference.
side_by_side() {
    "$MAKE" -s --no-print-directory render SUBMISSION="$work/$1" \
        SCENE="labs/scenes/$2.scene" SIZE="$3" OUT="$work/$1.png" >/dev/null
    "$render" "labs/scenes/$2.scene" --size "$3" --quiet -o "$work/$1-reference.png"
    status=0
    "$compare" "$work/$1.png" "$work/$1-reference.png" -o "$figs/$1.png" >/dev/null || status=$?
    if [ "$status" -ne 1 ]; then    # 0: the mistake shows nothing; 2: error
        echo "make-figures.sh: $1 on $2.scene: compare exited $status, expected 1 (the images differ)" >&2
        exit 1
    fi
    echo "wrote $figs/$1.png"
}

# mistake NAME CASE SCENE SIZE: one faulty stage file against the reference.
mistake() {
    assemble "$1" "$2"
    side_by_side "$1" "$3" "$4"
}

# ---- the reference's render of every scene -----------------------------
reference default 320x240
reference flip    240x240
reference wide    480x150
reference behind  320x240
reference inside  320x240
reference far     256x256
reference ground  320x240
reference cracks  320x240      # its own size: the pixel rays run along its edges
reference triangles 320x240
reference knot    320x240

# ---- common mistakes, one faulty stage file each -------------------------
mistake mistake-degrees-to-tan  p1-degrees-to-tan  flip    240x240   # Part 1
mistake mistake-aspect-inverted p1-aspect-inverted wide    480x150
mistake mistake-w-h-swapped     p1-w-h-swapped     wide    480x150
mistake mistake-y-not-flipped   p2-y-not-flipped   flip    240x240   # Part 2
mistake mistake-hits-behind     p3a-hits-behind    behind  320x240   # Part 3a
mistake mistake-inside-miss     p3a-inside-miss    inside  320x240
mistake mistake-far-root        p3a-far-root       default 320x240
mistake mistake-first-hit       p3b-first-hit      default 320x240   # Part 3b
mistake mistake-plane-behind    p4-hits-behind     ground  320x240   # Part 4
mistake mistake-plane-one-sided p4-one-sided       ground  320x240
mistake mistake-triangle-no-sum p5-no-sum-check    cracks  320x240   # Part 5
mistake mistake-triangle-one-sided p5-one-sided    triangles 320x240
mistake mistake-triangle-epsilon p5-det-epsilon    triangles 320x240
mistake mistake-triangle-behind p5-hits-behind     triangles 320x240

# ---- the hard case: a small sphere 10^7 radii away -----------------------
# The textbook quadratic in double, at the scene's own size (as make compare).
mistake hard-far-textbook textbook far 256x256
# The same quadratic with its numbers in float: every "double" that starts
# a declaration in the body becomes "float", and sqrt becomes sqrtf.
assemble hard-far-textbook-float textbook
sed 's/^\( *\)double /\1float /; s/sqrt(/sqrtf(/g' \
    "$selftest"/textbook/part3a_sphere_intersect.c \
    >"$work/hard-far-textbook-float/part3a_sphere_intersect.c"
side_by_side hard-far-textbook-float far 256x256

# ---- Part 5's hard case: a closed box whose edges lie along pixel rays -----
# Moller-Trumbore in double (self-test moller-trumbore), the skeleton's
# formula: rays slip through between triangles that share an edge.
mistake hard-cracks-moller-trumbore moller-trumbore cracks 320x240

# ---- the report page: one figure per part ----------------------------------
# `make grade` writes out/report/index.html with a drawing of every failing
# test's first wrong case.  Each handout shows one: the grader grades a
# submission with one faulty stage file (the part alone) and writes its
# page; the first figure (the page's first <svg class="fig"> element, whole,
# with the windows nested in it) is cut out as report-NAME.svg.
grade=out/build/bin/grade
report() {     # report NAME CASE PART: figure report-NAME.svg
    assemble "$1" "$2"
    status=0
    "$grade" --submission "$work/$1" --part "$3" --report-file "$work/$1.html" --quiet \
        >/dev/null 2>&1 || status=$?
    if [ "$status" -ne 1 ]; then    # 1: points lost, as the mistake should
        echo "make-figures.sh: grading $2 (Part $3) exited $status, expected 1" >&2
        exit 1
    fi
    awk '!on && /^<svg xmlns=.* class="fig"/ { on = 1 }
         on { print; depth += gsub(/<svg[ >]/, "&") - gsub(/<\/svg>/, "&"); if (depth == 0) exit }' \
        "$work/$1.html" >"$work/$1.svg"
    if ! grep -q '</svg>' "$work/$1.svg"; then
        echo "make-figures.sh: no figure in the page of $2" >&2
        exit 1
    fi
    mv "$work/$1.svg" "$figs/report-$1.svg"
    echo "wrote $figs/report-$1.svg"
}
if [ ! -x "$grade" ]; then
    echo "make-figures.sh: needs $grade (run make)" >&2
    exit 2
fi
report p1-w-h-swapped   p1-w-h-swapped   1
report p2-y-not-flipped p2-y-not-flipped 2
report p3a-far-root     p3a-far-root     3a
report p3b-first-hit    p3b-first-hit    3b
report p4-hits-behind   p4-hits-behind   4
report p5-strict-edges  p5-strict-edges  5
