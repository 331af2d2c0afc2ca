#!/bin/sh
# The class page (OUT/index.html) that grade --all writes, over regrades and
# small classes: with --previous, the scores that changed and the folders
# new or gone; a class of one; a class where no one lost points; a class
# the grader could not grade, one of its folders named with markup: that
# page is compared whole with tests/pages/class.html (times, the folder and
# the style sheet left out), read once by eye and in a browser.  Every page
# is safe to open (tests/lib/pages.sh).  The page of a whole class (every
# self-test submission, hostile names among them) is checked against its
# results files by tests/lib/class_page.sh, which tests/suites/grader.sh
# runs on the class it grades.
set -u
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES
grade=${GRADE:-out/build/bin/grade}   # make sanitize-grader: the sanitized one
. tests/lib/checks.sh
. tests/lib/class_page.sh
. tests/lib/pages.sh
temp_dir rtclass
chmod 755 "$tmp"

need_built "$grade"
LC_ALL=C
export LC_ALL
sed 's/^parts .*/parts 1/' tests/weights.conf >"$tmp/p1.conf"
selftest=$tmp/selftest
need_selftests "$selftest"

# ---- a regrade, with --previous ------------------------------------------------------------
# Three submissions of Part 1 graded, then graded again with Part 1's core
# points doubled and one folder renamed: the page lists each score that
# changed, by how much, as the two gradebooks say; the new folder and the
# one gone are counted.
small=$tmp/small
for s in p1-degrees-to-tan p1-float p1-w-h-swapped; do
    mkdir -p "$small/$s"
    cp "$selftest/$s/part1_image_plane.c" "$small/$s/"
done
mkdir "$small/reference-like"
cp solutions/part1_image_plane.c "$small/reference-like/"
chmod -R a+rX "$small"
sed -e 's/^part 1 .*/part 1   core 40   hard 2.5/' "$tmp/p1.conf" >"$tmp/p1x2.conf"
$grade --all "$small" --out "$tmp/before" --weights "$tmp/p1.conf" --jobs 2 >"$tmp/before.out" 2>&1
mv "$small/p1-float" "$small/p1-float-again"
$grade --all "$small" --out "$tmp/after" --weights "$tmp/p1x2.conf" --jobs 2 --previous "$tmp/before" \
    >"$tmp/after.out" 2>&1
changes_agree() {   # changes_agree BEFORE.csv AFTER.csv PAGE
    awk "$csv_awk"'
        FILENAME == ARGV[1] && FNR > 1 { n = parse($0); then[unguard(1)] = F[n - 1]; next }
        FILENAME == ARGV[2] && FNR > 1 { n = parse($0); name = unguard(1)
            if (name in then && then[name] != F[n - 1]) { want[name] = then[name] " " F[n - 1]; nwant++ }
            next }
        /<tr class="change"/ { b = $0; sub(/.*data-before="/, "", b); sub(/".*/, "", b)
            a = $0; sub(/.*data-after="/, "", a); sub(/".*/, "", a)
            h = $0; sub(/.*<a href="/, "", h); sub(/".*/, "", h); h = unpercent(h); sub(/\.html$/, "", h)
            split(want[h], w, " ")
            if (!(h in want) || w[1] + 0 != b + 0 || w[2] + 0 != a + 0) { print "change " h ": " b " " a " want " want[h]; bad = 1 }
            got[h] = 1 }
        END { for (h in want) if (!(h in got)) { print "missing change " h; bad = 1 }
              exit bad || nwant == 0 }' "$1" "$2" "$3"
}
check_output "with --previous: each score that changed, from what to what, as the two gradebooks say" \
    changes_agree "$tmp/before/gradebook.csv" "$tmp/after/gradebook.csv" "$tmp/after/index.html"
check "with --previous: the folder renamed is counted new, and the one gone named" \
    grep -q ' 1 is new\. 1 graded then is not here now: <code>p1-float</code>' "$tmp/after/index.html"
check_output "with --previous: the page is safe" page_safe "$tmp/after/index.html"
# A regrade into the previous run's own folder compares with its gradebook
# as it was before the regrade wrote over it.
cp -R "$tmp/before" "$tmp/inplace"
$grade --all "$small" --out "$tmp/inplace" --weights "$tmp/p1x2.conf" --jobs 2 --previous "$tmp/inplace" \
    >"$tmp/inplace.out" 2>&1
check_output "with --previous the output folder itself: the changes from the gradebook it held" \
    changes_agree "$tmp/before/gradebook.csv" "$tmp/inplace/gradebook.csv" "$tmp/inplace/index.html"
$grade --all "$small" --out "$tmp/nowhere-prev" --weights "$tmp/p1.conf" --jobs 2 --previous "$tmp/no-such" \
    >"$tmp/noprev.out" 2>&1
check "with a --previous that holds no gradebook, the page says so and compares nothing" \
    grep -q 'could not be read as a gradebook' "$tmp/nowhere-prev/index.html"

# ---- a class of one, and a class with no points lost ----------------------------------------------
hostile=$(printf 'b <i>"q\047&amp;\001x')
mkdir -p "$tmp/one/only" "$tmp/allfull/a" "$tmp/allfull/$hostile"
cp "$selftest/p1-degrees-to-tan/part1_image_plane.c" "$tmp/one/only/"
cp solutions/part1_image_plane.c "$tmp/allfull/a/"
cp solutions/part1_image_plane.c "$tmp/allfull/$hostile/"
chmod -R a+rX "$tmp/one" "$tmp/allfull"
for c in one allfull; do
    $grade --all "$tmp/$c" --out "$tmp/$c-out" --weights "$tmp/p1.conf" --jobs 2 >"$tmp/$c.out" 2>&1
    check_output "a class '$c': the page is safe" page_safe "$tmp/$c-out/index.html"
    check "a class '$c': no table without a row under its header" \
        awk '/<table/ { rows = 0 } /<tr>|<tr / { rows++ } /<\/table>/ && rows < 2 { bad = 1 } END { exit bad }' \
        "$tmp/$c-out/index.html"
done
check_has "a class of one: the page says 1 submission, its cause and its test" "$tmp/one-out/index.html" \
    '<strong>1 submission</strong> graded (Part 1)' 'data-cause="degrees-as-radians" data-count="1"' \
    'Passed by <strong>0 of 1</strong>'
check_has "a class with no points lost: the page says there is nothing to diagnose, no test failed, no one needs a person" \
    "$tmp/allfull-out/index.html" 'No submission lost points' \
    'None: every submission whose files built passed every test' 'None: every submission.s files were there and built'
check "... and causes.csv has its header alone" [ "$(wc -l <"$tmp/allfull-out/causes.csv")" -eq 1 ]

# A cause of the hard cases alone is worded as the students read it, as
# the others are: on the page, as the most common cause, in causes.csv.
# textbook's Part 1 is the lecture's formula (tan-near-90); tmin's Part 3a
# misses tangent rays (a core cause) and hits before 1e-9 (hard cases
# alone), the hard cases' cause named first by the probes.
mkdir -p "$tmp/hardonly/textbook" "$tmp/hardonly/tmin"
cp "$selftest/textbook/part1_image_plane.c" "$tmp/hardonly/textbook/"
sed 's/ > 0) {/ > 1e-9) {/' "$selftest/p3a-tangent-miss/part3a_sphere_intersect.c" \
    >"$tmp/hardonly/tmin/part3a_sphere_intersect.c"
chmod -R a+rX "$tmp/hardonly"
sed 's/^parts .*/parts 1 3a/' "$tmp/p1.conf" >"$tmp/p13a.conf"
$grade --all "$tmp/hardonly" --out "$tmp/hardonly-out" --weights "$tmp/p13a.conf" --jobs 2 \
    >"$tmp/hardonly.out" 2>&1
check "a cause of the hard cases alone has its sentence: on the page, as the most common, in causes.csv" \
    sh -c "grep -q '<p class=\"said\">h = 2 d tan(alpha / 2), the lecture&#39;s formula, loses digits near 180 degrees' '$tmp/hardonly-out/index.html' &&
           ! grep -q -e '<p class=\"said\"></p>' -e '&ldquo;&rdquo;' '$tmp/hardonly-out/index.html' &&
           grep -q '^1,tan-near-90,\"h = 2 d tan(alpha / 2), the lecture.s formula, loses digits' '$tmp/hardonly-out/causes.csv' &&
           grep -q '^3a,tmin-epsilon,\"hits closer than a tmin' '$tmp/hardonly-out/causes.csv' &&
           grep -q '^3a,tangent-miss,\"a tangent ray' '$tmp/hardonly-out/causes.csv'"

# A class the grader could not grade at all (no compiler on PATH): each
# submission needs a person, with the grader's own message, its name
# escaped.
CC=no-such-cc $grade --all "$tmp/allfull" --out "$tmp/nocc-out" --weights "$tmp/p1.conf" --jobs 2 \
    >"$tmp/nocc.out" 2>&1
check "a class with grader errors: each submission needs a person, with the grader's message" \
    sh -c "[ \$(grep -c 'data-need=\"grader error\"><td>.*no C compiler: no-such-cc is not on PATH' \
               '$tmp/nocc-out/index.html') -eq 2 ]"
check_output "a class with grader errors: the page is safe" page_safe "$tmp/nocc-out/index.html"
page_normal "$tmp/nocc-out/index.html" "$tmp" >"$tmp/nocc.html"
check_output "a class with grader errors: the page is tests/pages/class.html" \
    diff tests/pages/class.html "$tmp/nocc.html"

finish
