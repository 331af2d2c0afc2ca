#!/bin/sh
# The report page (out/report/index.html, OUT/<name>.html): faulty
# submissions from tests/selftest, one per part at least, among them a
# hard-case failure, a part that does not build and a missing file, graded
# with `grade --all` (every part turned on); each page must be
#   - safe to open (tests/lib/pages.sh: no <script>, no event attribute,
#     every image a PNG data: URI, every link to the page or a file beside
#     it, none to the network);
#   - one figure per failing test that ran, exactly, and the tests of a
#     part that did not build listed by name, once;
#   - clear about a part that did not build or a render that failed.
# One page, of a failing case whose code prints markup and of a missing
# file, is compared whole with tests/pages/report.html (times, the folder,
# the style sheet and the PNGs' bytes left out), read once by eye and in a
# browser.
# Then: `make grade` writes out/report/index.html and ends with its path; a
# page that cannot be written changes neither the exit status nor the
# results file; and, when a headless browser (chromium) is installed, the
# page renders: its screenshot differs from a blank page's.  Without a
# browser that check says it skipped and counts nothing.
set -u
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES
grade=${GRADE:-out/build/bin/grade}   # make sanitize-grader: the sanitized one
compare=out/build/bin/compare
. tests/lib/checks.sh
. tests/lib/browser.sh
. tests/lib/pages.sh
temp_dir rtreport
chmod 755 "$tmp"

need_built "$grade" "$compare"
selftest=$tmp/selftest
need_selftests "$selftest"

# ---- faulty submissions ------------------------------------------------------
# Those of Parts 1-3b graded as by default, those of Parts 4 and 5 with
# those parts alone (every part is graded on its own: the others could only
# show the reference's full marks).
only45=$tmp/parts45.conf
sed 's/^parts .*/parts 4 5/' tests/weights.conf >"$only45"
mkdir "$tmp/subs" "$tmp/subs45"
core="p1-w-h-swapped p2-y-not-flipped p3a-far-root p3a-tangent-miss p3b-first-hit textbook
      hostile-compile-error hostile-missing-file hostile-segfault warn-unused"
flat="p4-hits-behind p4-one-sided p4-float p4-no-parallel-check p4-no-parallel-check-nan-safe"
flat="$flat p5-one-sided p5-strict-edges"
for name in $core $flat; do
    dir=$selftest/$name
    case " $flat " in *" $name "*) to=$tmp/subs45/$name ;; *) to=$tmp/subs/$name ;; esac
    mkdir "$to"
    cp solutions/part*.c "$to/"
    for f in "$dir"/part*.c; do [ -f "$f" ] && cp "$f" "$to/"; done
    [ -f "$dir/MISSING" ] && rm -f "$to/$(cat "$dir/MISSING")"
done
mkdir "$tmp/subs/reference"
cp solutions/part*.c "$tmp/subs/reference/"
# A Part 1 wrong in the worked example alone, where it prints markup, an
# ampersand and bytes that are not UTF-8: the page shows what it printed as
# text, and stays safe.  Its Part 2 is missing; both parts are graded.
core="$core markup-printer"
mkdir "$tmp/subs/markup-printer"
cp solutions/part*.c "$tmp/subs/markup-printer/"
rm "$tmp/subs/markup-printer/part2_pixel_coordinates.c"
sed 's/^parts .*/parts 1 2/' tests/weights.conf >"$tmp/parts12.conf"
cat >"$tmp/subs/markup-printer/part1_image_plane.c" <<'EOF2'
#include <stdio.h>
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    double half = fov_degrees / 2;
    *h = 2 * d * (half <= 45 ? tan(half * (M_PI / 180)) : 1 / tan((90 - half) * (M_PI / 180)));
    *w = aspect * *h;
    if (fov_degrees != 90 || aspect != 2 || d != 1)
        return;
    printf("<script>alert(1)</script> <b id=\"scores\"> </pre></div> & &amp \xff\xfe \x01 ]]> <!--\n");
    printf("\033]0;title\a \033]52;c;Y2xpcA==\a \033[2J \xc2\x9b" "31m \x7f \xc3\xa9\n");
    *w = 5;
    *h = 2;
}
EOF2
chmod -R a+rX "$tmp/subs" "$tmp/subs45"
# The faulty part alone (its expect file names it; textbook's is 3a), two
# at a time; Parts 4 and 5 through grade --all, which writes OUT/<name>.html.
start=$(date +%s)
mkdir "$tmp/grades"
running=0
for name in $core reference; do
    p=$(sed -n 's/^part //p; s/^hard lost //p' "$selftest/$name/expect" 2>/dev/null | head -n 1)
    set -- --part "${p:-1}"
    [ "$name" = markup-printer ] && set -- --weights "$tmp/parts12.conf"
    $grade --submission "$tmp/subs/$name" "$@" --results "$tmp/grades/$name.json" \
        --report-file "$tmp/grades/$name.html" --quiet >"$tmp/grades/$name.out" 2>&1 &
    running=$((running + 1))
    if [ "$running" -ge 2 ]; then wait; running=0; fi
done
wait
$grade --all "$tmp/subs45" --out "$tmp/grades" --weights "$only45" >"$tmp/all45.out" 2>&1
status=$?
check "grade --all ran on Parts 4 and 5 (exit $status)" [ "$status" -le 1 ]
check "grade --all wrote a page per submission" \
    sh -c "[ -s '$tmp/grades/p4-hits-behind.html' ] && [ -s '$tmp/grades/p5-strict-edges.html' ]"
elapsed=$(( $(date +%s) - start ))
echo "   graded $(( $(ls "$tmp/subs" | wc -l) + $(ls "$tmp/subs45" | wc -l) )) submissions with their pages in ${elapsed} s"
subs="$core $flat"

for name in $subs reference; do
    page=$tmp/grades/$name.html
    json=$tmp/grades/$name.json
    check "$name: no page $page" [ -s "$page" ] || continue
    check_output "$name: the page is not safe:" page_safe "$page"
    figures=$(page_tags "$page" | grep -c '^figure class="case"')
    failing=$(grep -c '"status": "failed"' "$json")
    # A test of a part whose file did not build could not run: it has no
    # figure, only its name in the part's folded list.
    unrun=$(grep -c -e '"output": "  your part[^ ]*\.c did not build' \
        -e '"output": "  the grader did not compile your part' "$json")
    listed=$(sed -n 's/.*None of its \([0-9]*\) tests could run.*/\1/p' "$page" | awk '{ n += $1 } END { print n + 0 }')
    check "$name: one figure per failing test that ran ($figures figures, $failing failing tests, $unrun could not run)" \
        [ "${figures:-x}" = "$((failing - unrun))" ]
    check "$name: each test that could not run listed once ($listed listed, $unrun could not run)" \
        [ "$listed" = "$unrun" ]
    check "$name: the results file does not mention the page" sh -c "! grep -q 'html' '$json'"
done
page=$tmp/grades
page_normal "$page/markup-printer.html" "$tmp" >"$tmp/markup-printer.html"
check_output "a submission that prints markup, its Part 2 missing: the page is tests/pages/report.html" \
    diff tests/pages/report.html "$tmp/markup-printer.html"
# The table, on a terminal: what the code printed, its escape sequences
# (a window title, the clipboard, clearing the screen, a C1 control) shown,
# not obeyed.
$grade --submission "$tmp/subs/markup-printer" --part 1 >"$tmp/table.out" 2>&1
check "the table shows no control character the code printed (but newline and tab)" \
    sh -c "[ \$(LC_ALL=C tr -d '\n\t\040-\176\200-\377' <'$tmp/table.out' | wc -c) -eq 0 ]"
check "... it shows them as ^X, and a C1 control as ?: ^[]52;c;Y2xpcA==^G ... ^[[2J ?31m ^? and UTF-8 as it is" \
    grep -q '\^\[\]52;c;Y2xpcA==\^G \^\[\[2J ?31m \^? '"$(printf '\303\251')" "$tmp/table.out"
check "what the code printed is indented under 'your code printed:'" \
    awk '/your code printed:$/ { want = index($0, "y") + 1; n = 1; next }
         n > 0 { n--; if (match($0, /[^ ]/) < want) bad = 1; seen++ }
         END { exit !(seen > 0 && !bad) }' "$tmp/table.out"
check "the reference's page: nothing failed" grep -q 'Nothing: every test passed' "$page/reference.html"
check "the reference's page: its picture is exactly the reference's" \
    grep -q 'exactly the reference' "$page/reference.html"
check "a page per submission: the renders are there (3 images and the heat scale)" \
    [ "$(page_tags "$page/p1-w-h-swapped.html" | grep -cE '^(img|image) ')" = 4 ]
check "identical pictures: the two renders, and a box in place of the all-black heat map and its scale" \
    [ "$(page_tags "$page/reference.html" | grep -cE '^(img|image) ')" = 2 ]
check "... and the page says they are identical" grep -q 'identical, pixel for pixel' "$page/reference.html"
check "a diagnosis: its causes each on a line of their own, as the terminal shows them" \
    sh -c "grep -A1 'Part 1, what went wrong (probes run on your code confirmed it):</strong>\$' '$page/p1-w-h-swapped.html' |
           grep -q '^- w and h are swapped'"
check_has "a part that built with a warning: the page shows the warning with the part" "$page/warn-unused.html" \
    'Part 1, the compiler warned (a warning often points at a mistake):' 'unused variable'
$grade --submission "$tmp/subs/warn-unused" --part 1 >"$tmp/warn-table.out" 2>&1
check "... and so does the table, under the part's heading" \
    sh -c "grep -A2 'The compiler warned (a warning often points at a mistake):' '$tmp/warn-table.out' |
           grep -q '^    part1_image_plane.c:[0-9]*:[0-9]*: warning: unused variable'"
check "a part that does not build: the page says so in the terminal's words, then what the compiler said" \
    sh -c "grep -A3 'Your part2_pixel_coordinates.c did not build, so none of its tests could run:' \
           '$page/hostile-compile-error.html' | grep -q 'error'"
check "a file the grader did not hand to the compiler: the page says so, in the terminal's words" \
    grep -q 'The grader did not compile your part[0-9a-z_]*.c, so none of its tests could run:' \
    "$page/hostile-missing-file.html"
check "a part that does not build: its tests listed once, folded away, not a picture-less article each" \
    sh -c "grep -q 'None of its [0-9]* tests could run (open to list them)' '$page/hostile-compile-error.html' &&
           grep -q 'tests failed: the files of their parts did not build, so none could run.' '$page/hostile-compile-error.html' &&
           ! grep -q '<article' '$page/hostile-compile-error.html'"
check "a part that does not build: no render, and the page says why" \
    grep -q 'could not be built into the renderer' "$page/hostile-compile-error.html"
check "a missing file: the page says the file is missing" \
    grep -q 'missing: the submission has no part3a_sphere_intersect.c' "$page/hostile-missing-file.html"
check "a render that crashes: the page says so" grep -q 'crashed (signal' "$page/hostile-segfault.html"
check "a hard-case failure: a zoomed-in window where the scale demands it" \
    grep -q 'zoomed in' "$page/textbook.html"
# An exact tangent has no gap to show: its window zooms in far enough to
# see the ray touch the circle (it once zoomed in 2.9e+299 times, and said
# "the ray passes 0 exactly on the edge").
check "a tangent ray: the zoomed-in window says the ray touches the edge" \
    grep -q 'the ray touches the edge: it passes exactly on it' "$page/p3a-tangent-miss.html"
grep -B2 'the ray touches the edge' "$page/p3a-tangent-miss.html" |
    sed -n 's/.*>zoomed in \([^ ]*\) times:<.*/\1/p' >"$tmp/tangent-zoom"
check "a tangent ray: zoomed in a readable number of times ($(cat "$tmp/tangent-zoom"))" \
    awk 'NR == 1 { ok = $1 + 0 >= 4 && $1 + 0 <= 1000 } END { exit !ok }' "$tmp/tangent-zoom"
check "Part 3b's image tests: the two renders with the pixel marked" \
    grep -q 'Your picture and the reference' "$page/p3b-first-hit.html"
check "Part 5's mesh tests: the mesh seen along the ray" grep -q 'The mesh seen along the ray' \
    "$page/p5-strict-edges.html"
check "Part 1's figure: the frustum from the side" grep -q 'From the side' "$page/p1-w-h-swapped.html"
check "Part 2's figure: the pixel grid" grep -q "pixels around pixel" "$page/p2-y-not-flipped.html"
check "Part 4's figure: the plane edge on" grep -q 'plane seen edge on' "$page/p4-hits-behind.html"
# An awk function for the checks of figures below: attr(s, name), the
# number in the attribute name="..." of the tag on the line s, or "".
awk_attr='
    function attr(s, name) {
        if (!match(s, " " name "=\"[^\"]*\"")) return ""
        return substr(s, RSTART + length(name) + 3, RLENGTH - length(name) - 4) + 0
    }'
# normal_shown PAGE TEST: in the plane figure of Part 4's TEST on PAGE (the
# test's name and what follows it in its heading: </h4>, or <span for a
# tagged test), the label "normal n" lies inside the main window and the
# normal's arrow starts 20 pixels or more off the ray's line: where the
# normal points along the ray, it was once drawn under the ray, its label
# past the frame; where the plane lies along the window's top and its
# normal points out, its label was drawn across the frame.
normal_shown() {
    awk -v head="Part 4: $2" "$awk_attr"'
    index($0, head) { on = 1; next }
    !on { next }
    /<svg x=/ && !seen { seen = inwin = 1; wx = attr($0, "x"); wy = attr($0, "y"); ww = attr($0, "width"); wh = attr($0, "height"); next }
    inwin && /^<\/svg>/ { inwin = 0 }
    inwin && /stroke-width="1.6"/ && attr($0, "y1") == attr($0, "y2") { axis = attr($0, "y1") }
    inwin && /stroke-width="1.4"/ { by = attr($0, "y1") }
    inwin && />normal n</ { tx = attr($0, "x"); ty = attr($0, "y"); label = 1 }
    /<\/figure>/ { exit }
    END {
        off = by - axis; if (off < 0) off = -off
        exit !(label && tx >= wx && tx + 56 <= wx + ww && ty - 10 >= wy && ty <= wy + wh && off >= 20)
    }' "$1"
}
# Part 5's figure of one triangle is drawn as the eye sees it looking along
# the ray (it was once a mirror image): for p5-one-sided's triangle
# a (-1, -1), b (0, 1), c (1, -1) at z = -4, seen down -z as the lab's
# camera looks, a is drawn left of c and b above both.  And its note on
# the winding of a, b, c, in every such figure of two pages, gives the
# sign of det = (b - a).(r x (c - a)), worked out here from the case's
# input (at least one of each sign).
check "Part 5's figure is the eye's view along the ray, not its mirror image: a left of c, b above" awk "$awk_attr"'
    index($0, "Part 5: both sides count</h4>") { on = 1 }
    on && />[abc]<\/text>/ { v = substr($0, index($0, "</text>") - 1, 1); x[v] = attr($0, "x"); y[v] = attr($0, "y"); n++ }
    on && /<\/figure>/ { exit }
    END { exit !(n == 3 && x["a"] < x["c"] && y["b"] < y["a"] && y["b"] < y["c"]) }' "$page/p5-one-sided.html"
# sign_notes NOTE INPUT BODY PAGE...: each figure note on the pages (a line
# matching the ERE NOTE, saying "&gt; 0", "&lt; 0" or "= 0") against the
# sign of a number worked out from the case's input that follows it (a
# line matching INPUT): the awk function body BODY returns it from
# val["a.x"] and the like.  Prints how many disagree, then how many were
# positive and how many negative; true when none disagrees and both signs
# were seen.
sign_notes() {
    note=$1 input=$2 body=$3
    shift 3
    awk -v note="$note" -v input="$input" '
        function value(val,   e1x, e1y, e1z, e2x, e2y, e2z, det) { '"$body"' }
        $0 ~ note { said = /&gt; 0/ ? 1 : /&lt; 0/ ? -1 : /= 0/ ? 0 : "?" }
        said != "" && $0 ~ input {
            line = $0
            sub(/.*input: */, "", line)
            k = split(line, part, ", ")
            for (i = 1; i <= k; i++) { split(part[i], nv, " = "); val[nv[1]] = nv[2] + 0 }
            x = value(val)
            sign = x > 0 ? 1 : x < 0 ? -1 : 0
            if (sign != said) wrong++
            seen[sign]++
            said = ""
        }
        END { printf "%d %d %d\n", wrong, seen[1], seen[-1]; exit !(wrong == 0 && seen[1] > 0 && seen[-1] > 0) }' "$@"
}
check_output "Part 5's note on a, b, c's winding gives det's sign, worked out from each case (shown: wrong, det > 0, det < 0)" \
    sign_notes 'Drawn as seen looking along the ray' 'input: *a[.]x = ' '
    e1x = val["b.x"] - val["a.x"]; e1y = val["b.y"] - val["a.y"]; e1z = val["b.z"] - val["a.z"]
    e2x = val["c.x"] - val["a.x"]; e2y = val["c.y"] - val["a.y"]; e2z = val["c.z"] - val["a.z"]
    det = e1x * (val["r.y"] * e2z - val["r.z"] * e2y) + e1y * (val["r.z"] * e2x - val["r.x"] * e2z)
    return det + e1z * (val["r.x"] * e2y - val["r.y"] * e2x)' \
    "$page/p5-one-sided.html" "$page/p5-strict-edges.html"
# Part 4's figure says which side the ray comes from: its note's sign of
# r.n, in every plane figure of two pages, against r.n worked out here from
# the case's input (at least one of each sign).
check_output "Part 4's note on the side the ray comes from gives r.n's sign, worked out from each case (shown: wrong, r.n > 0, r.n < 0)" \
    sign_notes 'The ray comes at the plane from|The ray is parallel to the plane' 'input: *p[.]x = ' '
    return val["r.x"] * val["n.x"] + val["r.y"] * val["n.y"] + val["r.z"] * val["n.z"]' \
    "$page/p4-one-sided.html" "$page/p4-hits-behind.html"
check "Part 4's figure, the normal along the ray: it is drawn in the window, off the ray" \
    normal_shown "$page/p4-one-sided.html" "both sides of the plane count</h4>"
check "Part 4's figure, the plane's nearest point at the window's top: the normal is drawn in the window" \
    normal_shown "$page/p4-one-sided.html" "hits and misses</h4>"
check "Part 4's figure, a plane along the window's top, its normal pointing out: the normal is drawn in the window" \
    normal_shown "$page/p4-no-parallel-check-nan-safe.html" "rounding: parallel, behind the plane (exact dyadic)</h4>"
# A ray in the plane answered with a hit at t = NaN (0 / 0): the figure says
# the ray lies in the plane, and that NaN is no point of the ray (it once
# said "off the figure", as of a t too large to draw).
check "Part 4's figure, a ray in the plane and a hit at t = NaN: both said as such" \
    awk 'index($0, "Part 4: rounding: in the plane (exact dyadic)</h4>") { on = 1 }
         !on { next }
         /lies in it [(][(]p - e[)][.]n = 0[)]/ { lies = 1 }
         /your t = NaN: no point of the ray/ { nan = 1 }
         /off the figure/ { off = 1 }
         /<\/figure>/ { exit }
         END { exit !(lies && nan && !off) }' "$page/p4-no-parallel-check.html"
# A grazing ray meets the plane far away: drawn to scale, the plane lies
# on the ray and the hit looks like a point of it (it once did).  Heights
# are stretched, and the figure says by how much, F: the plane's line in
# the main window then rises or falls 30 pixels or more, crosses the ray
# where the expected hit is marked, and its slope over F is the true
# tangent of the angle between the ray and the plane, worked out here from
# the case's input (r.n over |r| |n|).
grazing_drawn() {
    awk -v head="Part 4: $2</h4>" "$awk_attr"'
    index($0, head) { on = 1; next }
    !on { next }
    /<svg x=/ && !seen { seen = inwin = 1; next }
    inwin && /^<\/svg>/ { inwin = 0 }
    inwin && /stroke-width="3"/ { x1 = attr($0, "x1"); y1 = attr($0, "y1"); x2 = attr($0, "x2"); y2 = attr($0, "y2") }
    inwin && /stroke-width="1.6"/ && attr($0, "y1") == attr($0, "y2") { axis = attr($0, "y1") }
    inwin && /fill="#1f5fbf"/ && /<circle/ { want = attr($0, "cx") }
    />heights off the ray stretched / { F = $0; sub(/.*stretched /, "", F); sub(/ times.*/, "", F); F += 0 }
    /input: *p[.]x = / {
        line = $0
        sub(/.*input: */, "", line)
        k = split(line, part, ", ")
        for (i = 1; i <= k; i++) { split(part[i], nv, " = "); val[nv[1]] = nv[2] + 0 }
        rn = val["r.x"] * val["n.x"] + val["r.y"] * val["n.y"] + val["r.z"] * val["n.z"]
        rr = val["r.x"] ^ 2 + val["r.y"] ^ 2 + val["r.z"] ^ 2
        nn = val["n.x"] ^ 2 + val["n.y"] ^ 2 + val["n.z"] ^ 2
        c = rn / sqrt(rr * nn); if (c < 0) c = -c
        exit
    }
    END {
        dy = y2 - y1; if (dy < 0) dy = -dy
        dx = x2 - x1; if (dx < 0) dx = -dx
        cross = y2 != y1 ? x1 + (axis - y1) * (x2 - x1) / (y2 - y1) : -1e9
        off = cross - want; if (off < 0) off = -off
        ratio = F > 0 && c > 0 ? (dy / dx / F) / (c / sqrt(1 - c * c)) : 0
        printf "F %s, %.0f px tall, %.2f px from the mark, slope / F / tan %.4f\n", F, dy, off, ratio
        exit !(F > 1 && dy >= 30 && off <= 1.5 && ratio > 0.99 && ratio < 1.01)
    }' "$1"
}
check_output "Part 4's figure, a grazing ray: heights stretched and said so, the plane's slope true to F (shown: how it is drawn)" \
    grazing_drawn "$page/p4-float.html" "rounding: grazing ray, 1e-12..1e-3 off the plane"
check "Part 4's figure, a plane not grazed: drawn to scale" \
    sh -c "! grep -q 'heights off the ray stretched' '$page/p4-hits-behind.html'"
check "the scores are at the top" sh -c "grep -n 'id=\"scores\"' '$page/p3a-far-root.html' | \
    awk -F: '{ exit !(\$1 < 80) }'"

# ---- make grade: out/report/index.html, its path at the end ----------------
make -s --no-print-directory grade SUBMISSION="$tmp/subs/p2-y-not-flipped" PART=2 >"$tmp/make.out" 2>&1
check "make grade writes out/report/index.html" test -s out/report/index.html
check "make grade's output ends with the page's path" \
    sh -c "grep -v '^make' '$tmp/make.out' | tail -n 1 | grep -q 'out/report/index.html'"
check_output "make grade's page is safe" page_safe out/report/index.html
check "make grade's last line, with failures: the page has their pictures" \
    sh -c "grep -v '^make' '$tmp/make.out' | tail -n 1 | grep -q 'pictures of every failure'"
make -s --no-print-directory grade SUBMISSION=solutions PART=2 >"$tmp/make-full.out" 2>&1
check "make grade's last line, at full marks: no failure to draw, not 'pictures of every failure'" \
    sh -c "tail -n 1 '$tmp/make-full.out' | grep -q 'no failure to draw' &&
           ! grep -q 'pictures of every failure' '$tmp/make-full.out'"
check "the page at full marks has no legend for figures it does not have" \
    sh -c "! grep -q 'How to read the pictures' out/report/index.html"
check "a page with failures has the legend" grep -q 'How to read the pictures' "$page/p4-one-sided.html"

# ---- a page that cannot be written changes nothing else ---------------------
: >"$tmp/not-a-directory"
$grade --submission "$tmp/subs/p1-w-h-swapped" --part 1 --results "$tmp/plain.json" >"$tmp/plain.out" 2>&1
s1=$?
$grade --submission "$tmp/subs/p1-w-h-swapped" --part 1 --results "$tmp/paged.json" \
    --report-file "$tmp/not-a-directory/index.html" >"$tmp/paged.out" 2>"$tmp/paged.err"
s2=$?
check "an unwritable page: the same exit status ($s1, $s2)" [ "$s1" = "$s2" ]
check "an unwritable page: it says so" grep -q 'report page was not written' "$tmp/paged.err"
check "an unwritable page: the same results file" sh -c "[ \"\$(grep -v execution_time '$tmp/plain.json')\" = \"\$(grep -v execution_time '$tmp/paged.json')\" ]"

# ---- the page renders in a browser, when one is installed --------------------
page_renders "$page/p3a-far-root.html" "the page" "$tmp"

finish
