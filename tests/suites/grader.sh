#!/bin/sh
# The grader's self-test: the reference scores full marks, the untouched
# skeleton 0 on every part, and every faulty or hostile submission under
# tests/selftest (its folders, and the records of tests/selftest/mistakes
# written out as folders by tests/lib/selftests.sh) loses its own part's
# points and no other's, with the hint or message its expect file names.
# By default the optional Parts 4 and 5 are not graded at all; turned on,
# they are graded like the others.
set -u
root=$(pwd)
grade=${GRADE:-out/build/bin/grade}   # make sanitize-grader: the sanitized one
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rtselftest.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
chmod 755 "$tmp"
. tests/lib/checks.sh
. tests/lib/class_page.sh
. tests/lib/browser.sh
. tests/lib/pages.sh
# The self-test submissions, a folder each.
selftest=$tmp/selftest
need_selftests "$selftest"

# -- the table of self-tests (tests/selftest/mistakes) -------------------------
# A record whose lines to change are no longer in its base stops the
# writing, naming the table's line and the record, and nothing is written:
# here in a copy of the kit with a line of the reference changed (one that
# p4-t-infinite changes), a line of the table's plain Part 3a changed (one
# that several records change), and two records added, one whose line is
# in its base twice and one with a line of no kind.
kit=$tmp/kit
mkdir -p "$kit/tests"
cp -R tests/selftest "$kit/tests/"
cp -R solutions "$kit/"
old='    if (!(root > 0 && root < INFINITY))'
sed 's/root < INFINITY))$/root < HUGE_VAL))/' solutions/part4_plane_intersect.c >"$kit/solutions/part4_plane_intersect.c"
base_line='    if (disc < 0 || A == 0)'
{
    sed 's/^|    if (disc < 0 || A == 0)$/|    if (!(disc >= 0) || A == 0)/' tests/selftest/mistakes
    printf '\ntest extra-twice part4_plane_intersect.c\npart 4\n-        return false;\n+        return true;\n'
    printf '\ntest extra-typo part1_image_plane.c\nparts 1\n'
} >"$kit/tests/selftest/mistakes"
n=$(wc -l <tests/selftest/mistakes | tr -d ' ')
sh tests/lib/selftests.sh "$tmp/unwritten" "$kit" >"$tmp/unwritten.out" 2>&1
status=$?
table=$kit/tests/selftest/mistakes
at=$(grep -n -x -F -e "-$old" tests/selftest/mistakes | cut -d: -f1)
check "a reference line a record changes, edited: refused, naming the record and its line $at (exit $status)" \
    sh -c "[ $status -eq 1 ] && [ ! -e '$tmp/unwritten' ] &&
           grep -q -x -F -e '$table:$at: p4-t-infinite: the line to change ($old) is not in the reference part4_plane_intersect.c' '$tmp/unwritten.out'"
at=$(grep -n -x -F -e "-$base_line" tests/selftest/mistakes | cut -d: -f1 | tr '\n' ' ')
said=$(grep -F -e " to change ($base_line" "$tmp/unwritten.out" | grep -F -e " not in the base part3a_sphere_intersect.c" |
       sed 's/^.*mistakes:\([0-9]*\): .*/\1/' | tr '\n' ' ')
check "a line of a base of the table, edited: every record that changes it is named, at lines ${at:-none} (said: ${said:-none})" \
    sh -c "[ -n '$at' ] && [ '$at' = '$said' ] &&
           grep -q -F -e ': p3a-tangent-miss: the line to change ($base_line) is not in the base' '$tmp/unwritten.out'"
check "a line to change that is in its base twice is refused, how many times said" \
    grep -q -x -F -e "$table:$((n + 4)): extra-twice: the line to change (        return false;) is in the base part4_plane_intersect.c 2 times: say which with a line beside (=)" \
    "$tmp/unwritten.out"
check "a line of no kind in a record is refused" \
    grep -q -F -e "$table:$((n + 8)): extra-typo: not an expect line" "$tmp/unwritten.out"
[ "$failed" -eq 0 ] || sed 's/^/    | /' "$tmp/unwritten.out"

max1=20; max2=20; max3a=30; max3b=30; max4=20; max5=20     # tests/weights.conf
# The same points with the optional Parts 4 and 5 turned on.
all=$tmp/all-parts.conf
sed 's/^parts .*/parts 1 2 3a 3b 4 5/' tests/weights.conf >"$all"

# -- the reference and the skeleton ------------------------------------------
# By default (Parts 1-3b) and with every part.
$grade --submission solutions --results "$tmp/ref.json" --summary >"$tmp/ref.out" 2>&1
status=$?
check "the reference scores full marks (exit $status)" [ "$status" -eq 0 ]
check "the reference's summary" grep -q "^summary $max1 $max2 $max3a $max3b 0 0 " "$tmp/ref.out"
check "results.json written for the reference" grep -q '"tests"' "$tmp/ref.json"
check "by default Parts 4 and 5 are not graded" sh -c "! grep -q '\"Part [45]: ' '$tmp/ref.json'"
[ "$status" -eq 0 ] || tail -n 30 "$tmp/ref.out"
$grade --submission solutions --weights "$all" --results "$tmp/ref-all.json" --summary >"$tmp/ref-all.out" 2>&1
status=$?
check "the reference scores full marks on every part (exit $status)" [ "$status" -eq 0 ]
check "the reference's summary, every part" \
    grep -q "^summary $max1 $max2 $max3a $max3b $max4 $max5 " "$tmp/ref-all.out"
check_has "Parts 4 and 5 in results.json when turned on" "$tmp/ref-all.json" '"Part 4: ' '"Part 5: '
# A name is how a student, Gradescope and the report page tell tests apart.
grep '"name": ' "$tmp/ref-all.json" | sort | uniq -d >"$tmp/same-names"
check "no two tests share a name, every part, public and hidden: $(tr -s ' \n' ' ' <"$tmp/same-names")" \
    test ! -s "$tmp/same-names"
[ "$status" -eq 0 ] || tail -n 30 "$tmp/ref-all.out"
for p in 4 5; do
    $grade --submission solutions --part $p >"$tmp/ref-$p.out" 2>&1
    status=$?
    check "make grade PART=$p grades Part $p whatever the parts line (exit $status)" \
        sh -c "[ $status -eq 0 ] && grep -q '^Part $p: .* 20 / 20' '$tmp/ref-$p.out'"
done

# The reference keeps every hard case of Part 3a whatever the hidden cases'
# seed.  Seeds 30 and 31 draw an origin within rounding of the surface whose
# far root the reference gives and the oracle accepts: the grader once
# refused it.
for seed in 1 2 3 4 5 30 31; do
    sed "s/^seed .*/seed $seed/" tests/weights.conf >"$tmp/seed.conf"
    $grade --submission solutions --weights "$tmp/seed.conf" --part 3a --summary --quiet >"$tmp/seed.out" 2>&1
    check "the reference keeps full hard marks in Part 3a with seed $seed" \
        grep -q "^summary 0 0 $max3a 0 0 0 5 " "$tmp/seed.out"
done

# The hidden cases are the same for every submission: a file that differs
# only by a comment meets the same inputs (drawn from the files too, it met
# others, and a resubmission could fish for easier ones).
if [ -d tests/hidden ]; then
    mkdir -p "$tmp/hidden-a" "$tmp/hidden-b"
    cp labs/part3a_sphere_intersect.c "$tmp/hidden-a/"
    { cat labs/part3a_sphere_intersect.c; echo '/* handed in again */'; } >"$tmp/hidden-b/part3a_sphere_intersect.c"
    chmod -R a+rX "$tmp/hidden-a" "$tmp/hidden-b"
    for s in a b; do
        $grade --submission "$tmp/hidden-$s" --part 3a --results "$tmp/hidden-$s.json" --quiet >/dev/null 2>&1
        grep -o 'input: [^\\]*' "$tmp/hidden-$s.json" >"$tmp/hidden-$s.inputs"
    done
    check "a resubmission that changes only a comment meets the same hidden cases ($(wc -l <"$tmp/hidden-a.inputs" | tr -d ' ') inputs)" \
        sh -c "[ -s '$tmp/hidden-a.inputs' ] && cmp -s '$tmp/hidden-a.inputs' '$tmp/hidden-b.inputs' &&
               grep -q 'hidden' '$tmp/hidden-a.json'"
fi

$grade --submission labs --weights "$all" --summary --all-failures >"$tmp/labs.out" 2>&1
status=$?
check "the skeleton loses points (exit $status, want 1)" [ "$status" -eq 1 ]
check "the skeleton scores 0 on every part" grep -q "^summary 0 0 0 0 0 0 0 0 1" "$tmp/labs.out"
check "the skeleton's Parts 4 and 5 ran without a crash" \
    sh -c "! grep -q -e 'crashed' -e 'did not finish' '$tmp/labs.out'"

# The untouched skeleton as make grade shows it: short, a part not written
# yet one line, while the page keeps every failure (an article each), as
# grade --all-failures does.
$grade --submission labs --results "$tmp/labs-short.json" --report-file "$tmp/labs-short.html" \
    >"$tmp/labs-short.out" 2>&1
lines=$(wc -l <"$tmp/labs-short.out" | tr -d ' ')
nfailed=$(grep -c '"status": "failed"' "$tmp/labs-short.json")
articles=$(grep -c '<article class="test"' "$tmp/labs-short.html")
check "the untouched skeleton's table is short: $lines lines, at most 150" [ "$lines" -le 150 ]
check "... each part one line: not written yet" [ "$(grep -c '   not written yet: every answer' "$tmp/labs-short.out")" -eq 4 ]
check "... and its page shows every one of its $nfailed failed tests ($articles)" \
    sh -c "[ $nfailed -gt 0 ] && [ $articles -eq $nfailed ]"
check "grade --all-failures shows each in full" \
    sh -c "[ \$(grep -c '^  FAIL  ' '$tmp/labs.out') -ge $nfailed ] && ! grep -q '   not written yet: every answer' '$tmp/labs.out'"

# A part whose file did not build is one line of the table, with the
# compiler's (or the grader's) words once, not a line for each test.
mkdir "$tmp/unbuilt"
cp solutions/part1_image_plane.c "$tmp/unbuilt/"
printf '#include "raytracer.h"\nVec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)\n{\n    return oops;\n}\n' \
    >"$tmp/unbuilt/part2_pixel_coordinates.c"
chmod -R a+rX "$tmp/unbuilt"
$grade --submission "$tmp/unbuilt" --results "$tmp/unbuilt.json" >"$tmp/unbuilt.out" 2>&1
check "the results' summary (Gradescope's text above the tests) says why each part did not build" \
    sh -c "grep -m 1 '\"output\": ' '$tmp/unbuilt.json' >'$tmp/unbuilt.top' &&
           grep -q 'Part 2: your part2_pixel_coordinates.c did not build, so none of its tests could run:.*oops.*undeclared' '$tmp/unbuilt.top' &&
           grep -q 'Part 3a: the grader did not compile your part3a_sphere_intersect.c, so none of its tests could run:.u000amissing: the submission has no part3a_sphere_intersect.c' '$tmp/unbuilt.top' &&
           ! grep -q 'Part 1: your' '$tmp/unbuilt.top'"
check "a part that did not compile: one line for its tests, the compiler's error once" \
    sh -c "[ \$(grep -c '^  FAIL  all [0-9]* tests ([0-9]* core, [0-9]* hard cases): your part2_pixel_coordinates.c did not build, so none could run:\$' '$tmp/unbuilt.out') -eq 1 ] &&
           [ \$(grep -c 'oops.*undeclared' '$tmp/unbuilt.out') -eq 1 ] && ! grep -q 'FAIL  Part 2:' '$tmp/unbuilt.out'"
check "a missing file: one line for its part's tests, saying it is missing once" \
    sh -c "[ \$(grep -c '^  FAIL  all [0-9]* tests .*: the grader did not compile your part3a_sphere_intersect.c, so none could run:\$' '$tmp/unbuilt.out') -eq 1 ] &&
           [ \$(grep -c 'the submission has no part3a_sphere_intersect.c' '$tmp/unbuilt.out') -eq 1 ] &&
           ! grep -q 'FAIL  Part 3a:' '$tmp/unbuilt.out' && grep -q 'PASS  Part 1: ' '$tmp/unbuilt.out'"

# A submission of Parts 1-3b alone keeps full marks by default.
mkdir "$tmp/core-only"
for f in part1_image_plane part2_pixel_coordinates part3a_sphere_intersect part3b_ray_color; do
    cp "solutions/$f.c" "$tmp/core-only/"
done
chmod -R a+rX "$tmp/core-only"
$grade --submission "$tmp/core-only" >"$tmp/core-only.out" 2>&1
status=$?
check "a Parts 1-3b submission keeps full marks by default (exit $status)" [ "$status" -eq 0 ]

# -- a malformed weights file: refused, naming its file and line -----------
for line in "output 0" "output 65537" "output 12k" "seed -1" "hard maybe" "part 6 core 1 hard 1" \
    "part 1 core -1 hard 0" "parts 1 1" "colour red" "hints some" "hints full extra" "timeout 0" "timeout 601" "timeout 2 s"; do  # portable: text
    printf 'part 1 core 20 hard 2.5\n%s\n' "$line" >"$tmp/bad.conf"
    $grade --submission solutions --weights "$tmp/bad.conf" >"$tmp/bad.out" 2>&1
    status=$?
    check "weights line '$line' is refused, naming the file and line 2 (exit $status)" \
        sh -c "[ $status -eq 2 ] && grep -q 'bad.conf:2: expected ' '$tmp/bad.out'"
done

# A line longer than the reader's buffer: a comment is read past, a setting
# refused (it was once read as two lines, the second with the next number).
long=$(awk 'BEGIN { while (n++ < 600) printf "x" }')
printf 'part 1 core 20 hard 2.5  # %s\ntimeout 3\n' "$long" >"$tmp/long.conf"
$grade --submission solutions --part 1 --weights "$tmp/long.conf" --quiet >"$tmp/long.out" 2>&1
status=$?
check "a weights comment 600 characters long is read past (exit $status)" [ "$status" -eq 0 ]
printf 'part 1 core 20 hard 2.5\ntimeout 3 %s\n' "$long" >"$tmp/long.conf"
$grade --submission solutions --part 1 --weights "$tmp/long.conf" --quiet >"$tmp/long.out" 2>&1
status=$?
check "a weights line 600 characters long is refused, naming the file and line 2 (exit $status)" \
    sh -c "[ $status -eq 2 ] && grep -q 'long.conf:2: the line is longer than 510 characters' '$tmp/long.out'"

# A weights file saved with a byte-order mark first (as some Windows
# editors save UTF-8) reads as without it.
printf '\357\273\277part 1 core 25 hard 2.5\r\n' >"$tmp/bom.conf"
$grade --submission solutions --part 1 --weights "$tmp/bom.conf" --quiet --summary >"$tmp/bom.out" 2>&1
status=$?
check "a weights file that starts with a byte-order mark is read (exit $status)" \
    sh -c "[ $status -eq 0 ] && grep -q '^summary 25 ' '$tmp/bom.out'"

# -- faulty and hostile submissions, graded as one class -------------------
# Every self-test submission, every part turned on: each part is graded on
# its own, so a part whose file is the reference's keeps full marks.  Two
# of them are copied again under hostile names (a control byte, quotes,
# angle brackets, an ampersand, a space, a percent sign), and an empty
# folder is handed in too, for the class page (tests/lib/class_page.sh).
# A test's time limit is 0.5 s here, not the default 2: the submissions
# that loop (hostile-infinite-loop, hostile-ignore-alarm) wait out the
# limit three times each (their batch, then two tests alone), burning CPU
# all the while.  The reference's whole batch of a part takes under 0.05 s.
# The limit is ten times that because a run that ran out of time on a
# loaded machine costs more than time: after it the diagnosis's probes
# stop, and a hint they would have confirmed is not given (at 0.25 s, with
# two runs of the suite at once, p3a-tangent-miss once lost its
# cancellation hint so).
# And a test may print 256 KiB here, not the default 4096:
# hostile-output-flood prints until it is stopped, in its batch and in each
# of its 68 tests alone (17 MiB in all instead of 272).
core=$tmp/core.conf
sed -e 's/^\(timeout\) .*/\1 0.5/' -e 's/^\(output\) .*/\1 256/' tests/weights.conf >"$core"
check_has "the test class's weights set a test's time and output" "$core" '^timeout 0.5$' '^output 256$'  # portable: text
classconf=$tmp/class.conf
sed 's/^parts .*/parts 1 2 3a 3b 4 5/' "$core" >"$classconf"
class=$tmp/class
mkdir "$class"
# Each submission: its own files.  Those whose harm could reach past their
# own part (hostile code, mistakes of linking and building, a whole
# submission) bring the reference's other files too, so that the class
# shows each costs its own part's points and no other's; a mistake in one
# part's formula brings that file alone, and the parts it does not hand
# in are not checked (graded, they cost only time).
for dir in "$selftest"/*/; do
    name=${dir%/}
    sub="$class/${name##*/}"
    mkdir "$sub"
    case ${name##*/} in
    hostile-* | link-* | build-* | warn-* | independent) cp solutions/part*.c "$sub/" ;;
    esac
    for f in "$dir"part*.c "$dir"*.h; do   # *.h: a student's own headers (build-own-header)
        [ -f "$f" ] && cp "$f" "$sub/"
    done
    [ -f "$dir/MISSING" ] && rm -f "$sub/$(cat "$dir/MISSING")"
done
# A file that includes the reference by its absolute path must be refused.
mkdir "$class/hostile-include-reference"
cp solutions/part*.c "$class/hostile-include-reference/"
printf '#include "%s/solutions/part1_image_plane.c"\n' "$root" \
    >"$class/hostile-include-reference/part1_image_plane.c"
mkdir -p "$tmp/expect/hostile-include-reference"
printf 'part 1\noutput refused\n' >"$tmp/expect/hostile-include-reference/expect"
# The same, where the compiler cannot read the file (a kit inside a directory
# only its owner may enter, graded as root: the compiler runs as nobody).
# The refusal must not depend on that.
mkdir -p out/tests/private && chmod 700 out/tests/private
cp solutions/part1_image_plane.c out/tests/private/secret.c
mkdir "$class/hostile-include-unreadable"
cp solutions/part*.c "$class/hostile-include-unreadable/"
printf '#include "%s/out/tests/private/secret.c"\n' "$root" \
    >"$class/hostile-include-unreadable/part1_image_plane.c"
mkdir -p "$tmp/expect/hostile-include-unreadable"
printf 'part 1\noutput refused\n' >"$tmp/expect/hostile-include-unreadable/expect"
nsubs=$(ls "$class" | wc -l | tr -d ' ')
hostile1=$(printf 'p1 <b>"q\047&amp;\001x')
cp -R "$class/p1-degrees-to-tan" "$class/$hostile1"
cp -R "$class/p2-no-half" "$class/=50% <i>"
mkdir "$class/empty-folder"
chmod -R a+rX "$class"

# Graded one at a time: beside the other lane of make test both cores are
# busy anyway, and two gradings at once making processes on both of them
# cost more CPU-seconds than one at a time.
start=$(date +%s)
$grade --all "$class" --out "$tmp/grades" --weights "$classconf" --jobs 1 >"$tmp/all.out" 2>&1
status=$?
echo "   graded $(ls "$class" | wc -l | tr -d ' ') submissions in $(( $(date +%s) - start )) s"
check "grade --all ran (exit $status)" [ "$status" -le 1 ]
check "the gradebook has a column per graded part" \
    grep -q "^submission,part1,part2,part3a,part3b,part4,part5,hard,total,status\$" "$tmp/grades/gradebook.csv"
check_class_page "$tmp/grades" "$classconf" "$tmp/all.out" "$class"
check_output "every page of the class is safe to open" page_safe "$tmp/grades"/*.html
check "the folders named with markup: on every page, only escaped" \
    sh -c "! grep -l -e '<b>\"q' -e '<i>' '$tmp/grades'/*.html"
page_renders "$tmp/grades/index.html" "the class page" "$tmp"

hard_failed() {   # hard_failed JSON PART: a test of the part tagged hard has failed
    awk -v p="\"Part $2: " '/"name": /   { name = $0; failed = 0 }
        /"status": "failed"/          { failed = 1 }
        /^ *"hard"$/ && failed && index(name, p) { found = 1 }
        END { exit !found }' "$1"
}
# diagnosis_check NAME EXPECT JSON: for each part the expect file names in a
# "cause PART WORD..." or "nocause PART" line, "pass" when the part's
# diagnosis (the "causes" of the results' extra_data) names exactly those
# causes, else "fail MESSAGE"; one process for all of a submission's parts.
diagnosis_check() {
    awk -v name="$1" -v q="'" '
        function sorted(s,   w, n, i, j, x, out) {
            n = split(s, w, " ")
            for (i = 2; i <= n; i++)
                for (j = i; j > 1 && w[j - 1] > w[j]; j--) { x = w[j]; w[j] = w[j - 1]; w[j - 1] = x }
            out = ""
            for (i = 1; i <= n; i++) out = out (i > 1 ? " " : "") w[i]
            return out
        }
        FNR == NR {
            if ($1 == "cause") { p = $2; $1 = ""; $2 = ""; want[p] = want[p] " " $0; parts[p] = 1 }
            else if ($1 == "nocause") parts[$2] = 1
            next
        }
        { text = text $0 }
        END {
            if (match(text, /"causes": *\{[^}]*\}/)) {
                obj = substr(text, RSTART, RLENGTH)
                sub(/^"causes": *\{/, "", obj)
                sub(/\}$/, "", obj)
                n = split(obj, pair, ",")
                for (i = 1; i <= n; i++)
                    if (match(pair[i], /^ *"[^"]*": *"[^"]*"/)) {
                        split(substr(pair[i], RSTART, RLENGTH), kv, "\"")
                        got[kv[2]] = kv[4]
                    }
            }
            for (p in parts) {
                w = sorted(want[p])
                g = sorted(got[p])
                if (w == g)
                    print "pass"
                else
                    print "fail " name ": Part " p q "s diagnosis names " q w q " (got " q g q ")"
            }
        }' "$2" "$3"
}
# The gradebook's rows of the self-test submissions, read once: "NAME
# POINTS..." with the points of Parts 1, 2, 3a, 3b, 4 and 5 (the hostile
# names and the empty folder are the class page's).
awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) col[$k] = k; next }
    $1 ~ /^[A-Za-z0-9][A-Za-z0-9._-]*$/ && $1 != "empty-folder" {
        line = $1
        split("1 2 3a 3b 4 5", p, " ")
        for (k = 1; k <= 6; k++) line = line " " $col["part" p[k]]
        print line }' "$tmp/grades/gradebook.csv" >"$tmp/points"
check "every submission has its row in the gradebook" [ "$(wc -l <"$tmp/points" | tr -d ' ')" -eq "$nsubs" ]
# It can fail: the reference fails no hard case.
if hard_failed "$tmp/ref.json" 3a || hard_failed "$tmp/ref.json" 1; then
    fail "the reference's results show a failed hard case"
else
    pass
fi
while read -r sname g1 g2 g3a g3b g4 g5; do
    expect="$selftest/$sname/expect"
    [ -f "$expect" ] || expect="$tmp/expect/$sname/expect"
    json="$tmp/grades/$sname.json"
    core_full=no part="" hardpart=""
    while read -r key rest; do
        case "$key $rest" in
        "core full"*) core_full=yes ;;
        "part "*) part="$part $rest " ;;
        "hard lost "*) hardpart=${rest#lost } ;;
        esac
    done <"$expect"
    # Each handed-in part's points and its maximum; "-" for a part not graded.
    got_all="" max_all=""
    for p in 1 2 3a 3b 4 5; do
        case $p in
        1) max=$max1 got=$g1 file=part1_image_plane ;;
        2) max=$max2 got=$g2 file=part2_pixel_coordinates ;;
        3a) max=$max3a got=$g3a file=part3a_sphere_intersect ;;
        3b) max=$max3b got=$g3b file=part3b_ray_color ;;
        4) max=$max4 got=$g4 file=part4_plane_intersect ;;
        5) max=$max5 got=$g5 file=part5_triangle_intersect ;;
        esac
        [ "$got" = "-" ] && max=-
        if case $part in *" $p "*) true ;; *) false ;; esac; then
            check "$sname: Part $p loses points (got $got of $max)" [ -n "$got" -a "$got" != "$max" -a "$got" != "-" ]
        elif [ ! -f "$class/$sname/$file.c" ]; then
            continue
        elif [ -n "$part" ] && [ "$got" != "-" ]; then
            check "$sname: Part $p keeps full marks (got $got of $max)" [ "$got" = "$max" ]
        fi
        got_all="$got_all $got" max_all="$max_all $max"
    done
    if [ "$core_full" = yes ]; then
        check "$sname: full core marks ($got_all)" [ "$got_all" = "$max_all" ]
    fi
    while read -r key want; do
        if [ "$key" = output ]; then
            check "$sname: the report says '$want'" grep -q -e "$want" "$json"
        elif [ "$key" = nooutput ]; then
            check "$sname: the report never says '$want'" sh -c '! grep -q -e "$1" "$2"' sh "$want" "$json"
        fi
    done <"$expect"
    # The diagnosis: exactly the causes the expect file names, part by part.
    diagnosis_check "$sname" "$expect" "$json" >"$tmp/diagnosis"
    while read -r verdict message; do
        if [ "$verdict" = pass ]; then pass; else fail "$message"; fi
    done <"$tmp/diagnosis"
    if [ -n "$hardpart" ]; then
        check "$sname: some Part $hardpart hard cases fail" hard_failed "$json" "$hardpart"
    fi
done <"$tmp/points"
# Parts 4 and 5 name a mistake only where it explains every answer of the
# test and the tests the code passed do not rule it out.  An epsilon on det
# answers every case of the far tiny triangles with a miss, as the skeleton
# does, and so would two wrong signs; but those signs fail the worked
# example, which this code passes: the epsilon is named there too.  The
# skeleton, which passes no test with a hit in it, is told the fact alone.
tiny="Part 5: hard: tiny triangle far away"
awk -v name="\"name\": \"$tiny" 'index($0, name) { p = 1 } p && /"output":/ { print; exit }' \
    "$tmp/grades/p5-det-epsilon.json" >"$tmp/tiny-epsilon"
check "p5-det-epsilon: the far tiny triangles' misses are put down to the epsilon on det" \
    grep -q "hint: *a hit was missed where det is small.*no epsilon on det" "$tmp/tiny-epsilon"
awk -v name="FAIL  $tiny" 'index($0, name) { p = 1; next } p && /^  (PASS|FAIL)/ { exit } p' \
    "$tmp/labs.out" >"$tmp/tiny-skeleton"
check "the skeleton's far tiny triangles: every case answered as a miss, no mistake named" \
    sh -c "grep -q 'hint: *every case of this test was answered as a miss' '$tmp/tiny-skeleton' &&
           ! grep -q 'epsilon' '$tmp/tiny-skeleton'"

# A two-sided plane test with an epsilon on r.n misses the tiny normals'
# hit as one-sided code would, but passes every test of both sides: the
# epsilon is named, never the sides (named before the epsilon had a hint).
check "p4-epsilon: no hint says the plane has two sides" \
    sh -c "! grep -q 'two sides' '$tmp/grades/p4-epsilon.json'"

# A case's numbers are shown in the fewest digits that read back as the
# same double (kit_shortest_double, labs/kit/numtext.c): the test's normal (0.48, 0.6,
# 0.64) as written, not as %.17g's 0.47999999999999998.
check "a failing case's input reads n.x = 0.48, n.y = 0.6, n.z = 0.64, not 17 digits" \
    sh -c "grep -q 'n.x = 0.48, n.y = 0.6, n.z = 0.64' '$tmp/grades/p4-one-sided.json' &&
           ! grep -q '0.47999999999999998' '$tmp/grades/p4-one-sided.json'"

# On Linux a part with one student file is built as a shared object that a
# prebuilt runner loads; GRADE_NO_LOAD=1 links the whole program as
# elsewhere.  Both ways must give the same grades, link errors included.
# Each submission below differs from the reference in one part's file, and
# each part is graded on its own (the class above checks that the other
# parts keep full marks), so each is graded whole on that part alone; the
# reference itself is graded whole on every part.
if [ -x out/build/grader/runner_part1 ]; then
    # parity PART SUBMISSION...: grades them on PART alone, linked whole.
    parity() {
        p=$1
        shift
        mkdir -p "$tmp/parity-$p"
        for sname in "$@"; do
            cp -R "$class/$sname" "$tmp/parity-$p/"
        done
        chmod -R a+rX "$tmp/parity-$p"
        sed "s/^parts .*/parts $p/" tests/weights.conf >"$tmp/parity-$p.conf"
        GRADE_NO_LOAD=1 $grade --all "$tmp/parity-$p" --out "$tmp/grades-parity-$p" \
            --weights "$tmp/parity-$p.conf" --jobs 2 >"$tmp/parity-$p.out" 2>&1
        for sname in "$@"; do
            # The gradebook's row: "name,points,hard,total,status"; the
            # class's row has a column per part.
            got=$(grep "^$sname," "$tmp/grades-parity-$p/gradebook.csv" | cut -d, -f2)
            want=$(awk -F, -v s="$sname" -v col="part$p" 'NR == 1 { for (k = 1; k <= NF; k++) if ($k == col) c = k }
                                                       $1 == s { print $c }' "$tmp/grades/gradebook.csv")
            check "$sname: the same Part $p grade linked whole as loaded ($got, loaded $want)" \
                [ -n "$got" -a "$got" = "$want" ]
        done
    }
    parity 1 link-defines-main link-libm hostile-exit
    parity 2 link-defines-other-part p2-no-half
    parity 3a link-undefined hostile-constructor hostile-segfault rw-rtiow-v1
    parity 3b p3b-reversed link-helper-elsewhere
    GRADE_NO_LOAD=1 $grade --submission solutions --weights "$all" --summary \
        >"$tmp/ref-whole.out" 2>&1
    check "the reference linked whole scores full marks on every part" \
        grep -q "^summary $max1 $max2 $max3a $max3b $max4 $max5 " "$tmp/ref-whole.out"
else
    echo "   no prebuilt runners (not Linux): every part's program is linked whole; parity not checked"
fi

# Code that works for a test's calls but not for a whole part's in one process:
# the tests run together fail, and each runs alone (grade --verbose says so).
for sname in hostile-crash-across-tests hostile-state-across-tests; do
    $grade --submission "$class/$sname" --part 1 --verbose --quiet >"$tmp/$sname.verbose" 2>&1
    check "$sname: the tests run together fail, and run alone" \
        grep -q "^  Part 1: the [0-9]* tests together: .*run.* alone" "$tmp/$sname.verbose"
    check "$sname: not every test passed together" \
        sh -c "! grep -q 'together: [0-9]* passed; 0 run alone' '$tmp/$sname.verbose'"
done
# The table marks the hard cases too (one submission is enough to see it),
# after the core tests, under a heading of their own, and a part with its
# core points is never told what went wrong.
$grade --submission "$class/rw-rtiow-camera" --part 1 >"$tmp/rw-rtiow-camera.table" 2>&1
check "the table marks a failed hard case [hard]" grep -q "FAIL  Part 1: .*\[hard\]" "$tmp/rw-rtiow-camera.table"
core_line=$(grep -n '^  PASS  Part 1: hidden: random' "$tmp/rw-rtiow-camera.table" | cut -d: -f1)
hard_line=$(grep -n '^  Hard cases (extra credit): 1.04 / 2.5$' "$tmp/rw-rtiow-camera.table" | cut -d: -f1)
fail_line=$(grep -n '^  FAIL  Part 1: hard' "$tmp/rw-rtiow-camera.table" | head -n 1 | cut -d: -f1)
check "the hard cases after the core tests, as extra credit (lines ${core_line:-none}, ${hard_line:-none}, ${fail_line:-none})" \
    sh -c "[ -n '$core_line' ] && [ -n '$hard_line' ] && [ -n '$fail_line' ] &&
           [ '$core_line' -lt '$hard_line' ] && [ '$hard_line' -lt '$fail_line' ]"
check "a part with its core points is never told what went wrong" \
    sh -c "! grep -qi 'what went wrong' '$tmp/rw-rtiow-camera.table' '$tmp/grades/rw-rtiow-camera.json'"
# The hard-case challenges' answers are the handout's, hidden behind its
# hint: by default no results file or page gives them (Part 1's
# complement of the angle, Part 3a's discriminant); with "hints full" in
# the weights, the cause gives it.
check "with the default hints, no results file or page gives a hard-case challenge's formula" \
    sh -c "! grep -rlF -e 'tan(90 - alpha' -e 'f x r|' '$tmp/grades'"
sed 's/^hints .*/hints full/' "$core" >"$tmp/full-hints.conf"
for sname in rw-rtiow-camera textbook; do
    $grade --submission "$class/$sname" --weights "$tmp/full-hints.conf" --results "$tmp/full-$sname.json" \
        --quiet >/dev/null 2>&1
done
check "with hints full, the causes give the challenges' formulas" \
    sh -c "grep -qF 'tan(90 - alpha / 2)' '$tmp/full-rw-rtiow-camera.json' && grep -qF 'A R^2 - |f x r|^2' '$tmp/full-textbook.json'"
check "forged results: the grader's own score stands" \
    grep -q '"score": *[0-9.]*,' "$tmp/grades/hostile-forge-results.json"
check "forged results: no score of 1000 anywhere" sh -c "! grep -rq '\"score\": 1000' '$tmp/grades'"
# grade --all writes gradebook.csv, the class page and causes.csv, and, per
# submission, NAME.json and NAME.html (the report page).
check "forged results: nothing written beside the submissions" \
    sh -c "[ \$(ls '$tmp/grades' | wc -l) -eq \$(( 2 * \$(ls '$class' | wc -l) + 3 )) ]"

# Folder names a spreadsheet would take for a formula, or that hold a
# comma, are written so that it reads them as text; folders whose names
# start with "." are not submissions: left out, and named.
names=$tmp/names
esc=$(printf 'esc\033[31mred')
nl=$(printf 'two\nlines')
for d in '=SUM(A1)' '-rf' '@me' '+1' 'a,b' plain .git .github "$esc" "$nl"; do
    mkdir -p "$names/$d"
    cp solutions/part1_image_plane.c "$names/$d/"
done
chmod -R a+rX "$names"
sed 's/^parts .*/parts 1/' tests/weights.conf >"$tmp/part1.conf"
$grade --all "$names" --out "$tmp/grades-names" --weights "$tmp/part1.conf" --jobs 1 >"$tmp/names.out" 2>&1
for d in '=SUM(A1)' '-rf' '@me' '+1'; do
    check "a folder named $d is written \"'$d\" in the gradebook, read as text" \
        grep -qxF "\"'$d\",20,2.5,22.5,full marks" "$tmp/grades-names/gradebook.csv"
done
check "a folder named a,b is quoted in the gradebook" \
    grep -qxF '"a,b",20,2.5,22.5,full marks' "$tmp/grades-names/gradebook.csv"
check "a plain name is written as it is" grep -qxF 'plain,20,2.5,22.5,full marks' "$tmp/grades-names/gradebook.csv"
check "control bytes of a folder's name (an escape, a line break) are written as \\xHH in the gradebook" \
    sh -c "grep -qxF 'esc\\x1b[31mred,20,2.5,22.5,full marks' '$tmp/grades-names/gradebook.csv' &&
           grep -qxF 'two\\x0alines,20,2.5,22.5,full marks' '$tmp/grades-names/gradebook.csv' &&
           ! grep -q \"\$(printf '\\033')\" '$tmp/grades-names/gradebook.csv'"
check "the gradebook has a row for each of the 8 submissions and no more" \
    [ "$(wc -l <"$tmp/grades-names/gradebook.csv")" -eq 9 ]
check "the results files keep the names as they are" \
    sh -c "[ -f '$tmp/grades-names/=SUM(A1).json' ] && [ -f '$tmp/grades-names/-rf.html' ]"
check_has "folders whose names start with . are left out, and the run names them, in order" "$tmp/names.out" \
    '^left out 2 folders of the system.s own (a name starting with ".", or macOS.s __MACOSX), not taken for a submission: ' \
    ': \.git, \.github$' '^graded 8 submissions'
[ "$failed" -eq 0 ] || sed 's/^/    | /' "$tmp/names.out" "$tmp/grades-names/gradebook.csv"
# Folder names with escape sequences, in the lists the run prints (the
# folders left out, those with no stage file): shown as ^[ and ^G, and no
# ESC or BEL reaches the terminal.
esc=$tmp/escnames
mkdir -p "$esc/ok" "$esc/$(printf 'x\033]0;title\007y')" "$esc/$(printf '.\033[2Jz')"
cp solutions/part1_image_plane.c "$esc/ok/"
chmod -R a+rX "$esc"
$grade --all "$esc" --out "$tmp/grades-esc" --weights "$tmp/part1.conf" --jobs 1 >"$tmp/esc.out" 2>&1
check "folder names with escape sequences are printed as ^[ and ^G, with no ESC or BEL" \
    sh -c "grep -qF '.^[[2Jz' '$tmp/esc.out' && grep -qF 'x^[]0;title^Gy' '$tmp/esc.out' &&
           ! grep -q \"\$(printf '[\\033\\007]')\" '$tmp/esc.out'"
# A class of repositories made from the student kit (GitHub Classroom's,
# cloned): each keeps its stage files in labs/, where they are graded; a
# folder with stage files of its own is graded there, whatever its labs/.
repos=$tmp/repos
mkdir -p "$repos/kit-layout/labs" "$repos/both/labs"
cp solutions/part1_image_plane.c "$repos/kit-layout/labs/"
cp labs/part1_image_plane.c "$repos/both/"
cp solutions/part1_image_plane.c "$repos/both/labs/"
cp solutions/part1_image_plane.c "$repos/smith_1234_part1_image_plane.c"   # a loose file
chmod -R a+rX "$repos"
$grade --all "$repos" --out "$tmp/grades-repos" --weights "$tmp/part1.conf" --jobs 1 >"$tmp/repos.out" 2>&1
check "a repository made from the student kit is graded in its labs folder" \
    grep -qxF 'kit-layout,20,2.5,22.5,full marks' "$tmp/grades-repos/gradebook.csv"
check "a folder with stage files of its own is graded there, not in its labs folder" \
    grep -q '^both,0,0,0,points lost$' "$tmp/grades-repos/gradebook.csv"
check "a stage file lying in the class folder itself is left out, and counted" \
    grep -q "^left out 1 stage file lying in $repos itself: a submission is a folder of its own\$" "$tmp/repos.out"
# Every student's files in one folder (as some downloads give them): refused,
# and the message says what to do.
mkdir "$tmp/flat"
cp solutions/part1_image_plane.c "$tmp/flat/doe_123_part1_image_plane.c"
cp solutions/part2_pixel_coordinates.c "$tmp/flat/roe_456_part2_pixel_coordinates.c"
$grade --all "$tmp/flat" --out "$tmp/grades-flat" >"$tmp/flat.out" 2>&1
status=$?
check "one folder of every student's files is refused (exit $status), and the message says what to do" \
    sh -c "[ $status -eq 2 ] && [ ! -e '$tmp/grades-flat' ] &&
           grep -q 'it holds 2 stage files of its own: put each submission.s files in a folder of its own' '$tmp/flat.out'"
[ "$failed" -eq 0 ] || sed 's/^/    | /' "$tmp/repos.out" "$tmp/grades-repos/gradebook.csv"
# Stage files that are not files: a link to the reference (as root it once
# gave full marks), a link to a file only root may read (its first line
# once came back in the compiler's message), a pipe (reading it waits
# forever); and a repository whose labs folder is a link to the reference.
# Each is refused, scores 0 and shows nothing of what it points at.
links=$tmp/links
mkdir -p "$links/stage-links" "$links/labs-link" out/tests/private
chmod 700 out/tests/private
printf 'SECRET-MARKER-27182\n' >out/tests/private/marker.c
ln -s "$root/solutions/part1_image_plane.c" "$links/stage-links/part1_image_plane.c"
ln -s "$root/out/tests/private/marker.c" "$links/stage-links/part2_pixel_coordinates.c"
mkfifo "$links/stage-links/part3a_sphere_intersect.c"
ln -s "$root/solutions" "$links/labs-link/labs"
mkdir -p "$links/utf16"
cp solutions/part2_pixel_coordinates.c solutions/part3a_sphere_intersect.c "$links/utf16/"
printf '\377\376i\000n\000t\000 \000x\000;\000\n\000' >"$links/utf16/part1_image_plane.c"
mkdir -p "$links/too-large"
cp solutions/part2_pixel_coordinates.c solutions/part3a_sphere_intersect.c "$links/too-large/"
{ cat solutions/part1_image_plane.c; awk 'BEGIN { while (n++ < 20000) print "/* padding padding padding padding padding padding */" }'; } \
    >"$links/too-large/part1_image_plane.c"
chmod -R a+rX "$links" 2>/dev/null
sed 's/^parts .*/parts 1 2 3a/' "$core" >"$tmp/parts123a.conf"
$grade --all "$links" --out "$tmp/grades-links" --weights "$tmp/parts123a.conf" --jobs 1 >"$tmp/links.out" 2>&1
check "a stage file that is a link to the reference is refused: 0 points" \
    grep -q '^stage-links,0,0,0,0,0,points lost$' "$tmp/grades-links/gradebook.csv"
check "... with a message that says why" \
    grep -q 'refused: a symbolic link, not a file (hand in the file itself): part1_image_plane.c' \
    "$tmp/grades-links/stage-links.json"
check "... a pipe is refused too, and the grading ends" \
    grep -q 'refused: not a regular file: part3a_sphere_intersect.c' "$tmp/grades-links/stage-links.json"
check "a link to a file only root may read shows nothing of it" \
    sh -c "! grep -rq 'SECRET-MARKER' '$tmp/grades-links'"
check "a stage file over 1 MiB is refused as too large, by its own name" \
    grep -q 'refused: too large: part1_image_plane.c is [0-9]* bytes; a stage file may be at most 1048576 (1 MiB)' \
    "$tmp/grades-links/too-large.json"
check "... and costs that part alone" grep -q '^too-large,0,20,30,' "$tmp/grades-links/gradebook.csv"
check "a stage file saved as UTF-16 is refused with what to do, not the compiler's stray bytes" \
    sh -c "grep -q 'refused: part1_image_plane.c is saved as UTF-16 (what some Windows editors call ..Unicode..), which C compilers do not read: save it as UTF-8' '$tmp/grades-links/utf16.json' &&
           grep -q '^utf16,0,20,30,' '$tmp/grades-links/gradebook.csv'"
check "a labs folder that is a link (to the reference) is not graded: 0 points, no stage file" \
    grep -q '^labs-link,0,0,0,0,0,no stage file$' "$tmp/grades-links/gradebook.csv"
[ "$failed" -eq 0 ] || sed 's/^/    | /' "$tmp/links.out" "$tmp/grades-links/gradebook.csv"
# Graded as another user than root, grade --all says what that means: in
# the namespace jail the code saw none of that user's files, else it ran
# as that user.
self_jail=""
if [ "$(id -u)" != 0 ]; then
    $grade --all "$names" --out "$tmp/grades-self" --weights "$tmp/part1.conf" --jobs 1 >"$tmp/self.out" 2>&1
    self_jail=$($grade --jail)
elif ! command -v setpriv >/dev/null 2>&1 || ! id nobody >/dev/null 2>&1; then
    echo "   skipped: no setpriv here, so grade --all was not run as another user than root"
    : >"$tmp/self.out"
elif ! setpriv --reuid=nobody --regid="$(id -g nobody)" --clear-groups test -x "$(cd "$(dirname "$grade")" && pwd)/${grade##*/}"; then   # portable: guarded
    echo "   skipped: nobody cannot reach the kit here (made private for the fallback jail), so grade --all was not run as another user than root"
    : >"$tmp/self.out"
else
    # as nobody, with an output folder nobody may write in  # portable: guarded
    mkdir -m 777 "$tmp/self"
    setpriv --reuid=nobody --regid="$(id -g nobody)" --clear-groups \
        $grade --all "$names" --out "$tmp/self/grades" --weights "$tmp/part1.conf" --jobs 1 >"$tmp/self.out" 2>&1
    self_jail=$(setpriv --reuid=nobody --regid="$(id -g nobody)" --clear-groups $grade --jail 2>/dev/null)   # portable: guarded
fi
if [ -s "$tmp/self.out" ]; then
    case $self_jail in
    namespaces*)
        check "graded as another user than root, in the namespace jail, grade --all says their code saw none of that user's files" \
            grep -q '^graded as yourself, not as root: each submission.s code ran in a jail of its own (a user namespace)' "$tmp/self.out" ;;
    *)
        check "graded as another user than root, without namespaces, grade --all says each one's code ran as that user" \
            grep -q '^graded as yourself, not as root, where this system gives no namespaces: each submission.s code ran as you' "$tmp/self.out" ;;
    esac
fi
# A folder that holds no submission (the wrong one, most likely).
mkdir -p "$tmp/no-class/.git"
$grade --all "$tmp/no-class" --out "$tmp/grades-none" >"$tmp/none.out" 2>&1
status=$?
check "a folder with no submission in it is refused (exit $status, want 2), and nothing is written" \
    sh -c "[ $status -eq 2 ] && [ ! -e '$tmp/grades-none' ] &&
           grep -q 'no-class holds no submissions: .*left out: .git)' '$tmp/none.out'"
# A folder the outputs cannot name: "index" (its page would be the class
# page, index.html) and a name too long for NAME.json.  Refused, naming it,
# before anything is written.
long=$(awk 'BEGIN { while (n++ < 251) printf "x" }')
for bad in Index "$long"; do
    mkdir -p "$tmp/misnamed/ok" "$tmp/misnamed/$bad"
    cp solutions/part1_image_plane.c "$tmp/misnamed/$bad/"
    chmod -R a+rX "$tmp/misnamed"
    $grade --all "$tmp/misnamed" --out "$tmp/grades-misnamed" >"$tmp/misnamed.out" 2>&1
    status=$?
    check "a submission's folder named ${bad%"${bad#?????}"}... (${#bad} bytes) is refused (exit $status, want 2), naming it, and nothing is written" \
        sh -c "[ $status -eq 2 ] && [ ! -e '$tmp/grades-misnamed' ] &&
               grep -q 'misnamed/${bad%"${bad#?????}"}.*rename the folder' '$tmp/misnamed.out'"
    rm -rf "$tmp/misnamed"
done
# A submission with no stage file (an empty folder, or only files under
# other names) is told apart in the gradebook from one that lost points.
mkdir -p "$tmp/handed/empty" "$tmp/handed/renamed" "$tmp/handed/part1-only" "$tmp/handed/in-labs/labs"
cp solutions/part1_image_plane.c "$tmp/handed/renamed/Part1.c"
cp solutions/part1_image_plane.c "$tmp/handed/part1-only/"
cp solutions/part1_image_plane.c "$tmp/handed/in-labs/labs/"
chmod -R a+rX "$tmp/handed"
$grade --all "$tmp/handed" --out "$tmp/grades-handed" --weights "$core" >"$tmp/handed.out" 2>&1
check_has "the gradebook's status: 'no stage file' for an empty folder and for one of files under other names" \
    "$tmp/grades-handed/gradebook.csv" '^empty,0,0,0,0,0,0,no stage file$' '^renamed,0,0,0,0,0,0,no stage file$'
check "... and the run names them" grep -q '^2 submissions hold no stage file (.*): empty, renamed$' "$tmp/handed.out"
check_has "... and 'points lost' for one with a stage file, in its folder or its labs" "$tmp/grades-handed/gradebook.csv" \
    '^part1-only,20,0,0,0,.*,points lost$' '^in-labs,20,0,0,0,.*,points lost$'
check "... and the renamed file is named in its results" \
    grep -q 'it has Part1.c: hand it in as part1_image_plane.c' "$tmp/grades-handed/renamed.json"

for j in 0 two 3x; do
    $grade --all "$names" --out "$tmp/grades-jobs" --jobs $j >"$tmp/jobs.out" 2>&1
    status=$?
    check "--jobs $j is refused (exit $status, want 2), and nothing is written" \
        sh -c "[ $status -eq 2 ] && [ ! -e '$tmp/grades-jobs' ] && grep -q -- '--jobs $j: want a whole number' '$tmp/jobs.out'"
done

# The results for PrairieLearn and for GitHub Classroom's reporter, written
# by this grader (make sanitize-grader: the writers under the sanitizers;
# prairielearn.sh and classroom.sh check the platforms' own rules).
$grade --submission solutions --format prairielearn --results "$tmp/pl-ref.json" --quiet >/dev/null 2>&1
check_has "PrairieLearn: the reference scores 1, gradable" "$tmp/pl-ref.json" '"score": 1,$' '"gradable": true'
mkdir "$tmp/no-factor-2"        # the reference, but for Part 1's factor 2
cp solutions/part*.c "$tmp/no-factor-2/"
cp "$class/p1-no-factor-2/part1_image_plane.c" "$tmp/no-factor-2/"
chmod -R a+rX "$tmp/no-factor-2"
$grade --submission "$tmp/no-factor-2" --format prairielearn --results "$tmp/pl-bad.json" --quiet \
    >/dev/null 2>&1
check_has "PrairieLearn: Part 1 with its factor 2 missing scores between 0 and 1, and says what went wrong" \
    "$tmp/pl-bad.json" '"score": 0\.[0-9]*,$' 'What went wrong'
: >"$tmp/classroom.out"
$grade --submission "$class/p1-no-factor-2" --part 1 --classroom "$tmp/classroom.out" --quiet >/dev/null 2>&1
check "Classroom: one line per Part 1 test and one for the hard cases, each its name = base64" \
    sh -c "[ \$(grep -c '^part1test' '$tmp/classroom.out') -ge 5 ] && grep -q '^hard=' '$tmp/classroom.out' &&
           ! grep -v -q -E '^(part1test[0-9]+|hard)=[A-Za-z0-9+/]+=*\$' '$tmp/classroom.out'"

finish
