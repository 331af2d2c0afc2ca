#!/bin/sh
# The student kit as a student gets it: make student-kit, unpack the
# tarball into an empty directory (with tar, as a student does), and
# there:
#   - nothing of solutions/, tests/hidden, tests/oracle, tests/selftest or
#     tests/bench, nor the hidden cases' seed, and no line of the
#     solutions' function bodies in any file;
#   - the handouts, their figures and a reference render of every scene;
#   - .gitattributes (LF in every checkout, tests/suites/line_ends.sh) and
#     a .gitignore that keeps its builds out of a student's repository;
#   - `make` builds without a warning;
#   - `make grade` on the untouched skeleton: 0 points on every part,
#     status 1, no crash; it writes the report page out/report/index.html
#     (valid, self-contained, with the stored reference render), and the
#     results file names no page;
#   - every `make ...` command of the handouts' ```sh blocks (and the
#     README's) runs as written: status 0 or 1, never 2 or a crash;
#   - GitHub Classroom: the workflow (the reporter action, the grade step,
#     one environment variable per runner), and the runners `make grade
#     CLASSROOM=file` writes for the reference, a partial submission and
#     the skeleton, read through the workflow and totalled by the reporter's
#     rules (tests/lib/classroom.sh): both totals are the kit's core score;
#   - with the reference stage files copied into its labs/: `make grade`
#     gives full marks (status 0), its page's render is exactly the stored
#     reference, and `make compare SUBMISSION=labs` reports `identical`
#     for every scene.
#
# `make` turns a recipe's failure into its own exit status 2, so the status
# of the program it ran (the grader's 1 for "points lost", compare's 1 for
# "the images differ") is read from its "make: *** [...] Error N" line.
#
# Usage: sh tests/suites/student_kit.sh     (from the kit's top directory;
# tests/run.sh runs it).  Set KEEP=1 to keep the unpacked kit.
# The last line is "N passed, N failed"; the exit status is 1 if any failed.
set -u
# The kit's own make must not see the settings of a make that runs us.
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES

top=$(pwd)
. tests/lib/checks.sh
. tests/lib/pages.sh
temp_dir student_kit
# The self-test submissions, a folder each.
selftest=$tmp/selftest
need_selftests "$selftest"

# fail WHAT: counts a failure; shows the start of the last output, if any.
fail() { fail_showing "$tmp/out" 15 '    | ' "$@"; }

# run_in DIR COMMAND...: runs COMMAND in DIR, output in $tmp/out.  Sets
# status (its own) and ran (when it is a make, the status of the recipe
# that failed, from make's "Error N" line; 0 when it succeeded; 2 when it
# failed with no such line, e.g. a recipe killed by a signal).
run_in() {
    dir=$1
    shift
    (cd "$dir" && "$@") >"$tmp/out" 2>&1 </dev/null
    status=$?
    ran=$status
    if [ "$status" -ne 0 ]; then
        n=$(sed -n 's/^.*make\(\[[0-9]*\]\)\{0,1\}: \*\*\* \[.*\] Error \([0-9][0-9]*\)$/\2/p' "$tmp/out" | tail -n 1)
        ran=${n:-2}
    fi
}
# crashed: true when the last output shows a crash or a sanitizer report.
crashed() {
    grep -q -i -e 'segmentation fault' -e 'core dumped' -e 'aborted' -e 'bus error' \
        -e 'sanitizer' -e 'runtime error' -e 'floating point exception' "$tmp/out"
}
# part_points PART: prints "N M" from the last output's line "Part PART: ... N / M".
part_points() {
    sed -n "s/^Part $1: [^0-9]*\([0-9][0-9.]*\) \/ \([0-9][0-9.]*\).*\$/\1 \2/p" "$tmp/out" | head -n 1
}
# squeeze: blanks runs of spaces and tabs into one space, trims the ends.
squeeze() {
    awk '{ gsub(/[ \t]+/, " "); sub(/^ /, ""); sub(/ $/, ""); print }'
}

# ---- make student-kit, unpacked with tar ----------------------------------
run_in "$top" make student-kit
if [ "$status" -ne 0 ] || [ ! -f out/student-kit.tar.gz ]; then
    fail "make student-kit: exit $status"
    finish
fi
pass
mkdir "$tmp/unpacked"
: >"$tmp/out"
if ! tar -xzf out/student-kit.tar.gz -C "$tmp/unpacked" >"$tmp/out" 2>&1; then
    fail "tar -xzf out/student-kit.tar.gz"
    finish
fi
kit=
for d in "$tmp/unpacked"/*; do
    if [ -z "$kit" ] && [ -d "$d" ]; then kit=$d; else kit=; break; fi
done
if [ -z "$kit" ] || [ ! -f "$kit/Makefile" ]; then
    fail "the tarball does not hold exactly one directory with a Makefile"
    finish
fi
pass
: >"$tmp/out"

# ---- what must not be there, and what must --------------------------------
for p in solutions tests/hidden tests/oracle tests/selftest tests/bench tests/suites tests/gradescope; do
    check "the kit holds $p" test ! -e "$kit/$p"
done
for f in README.md labs/raytracer.h labs/vec3.h tests/weights.conf \
         handouts/overview.md handouts/part1_image_plane.md handouts/part2_pixel_coordinates.md \
         handouts/part3a_sphere_intersect.md handouts/part3b_ray_color.md; do
    check "the kit lacks $f" test -s "$kit/$f"
done
for f in labs/part*.c tests/public/*.tests .gitattributes .gitignore; do
    check "the kit lacks $f" cmp -s "$f" "$kit/$f"
done
# The hidden cases' seed is the instructor's: the kit's weights.conf is
# the instructor's without it.
grep -v '^[ 	]*seed[ 	]' tests/weights.conf >"$tmp/weights.want"
grep -v '^# seed: the hidden cases' "$kit/tests/weights.conf" >"$tmp/weights.got"
check "the kit's tests/weights.conf holds the hidden cases' seed" \
    sh -c "! grep -q '^[ 	]*seed[ 	]' '$kit/tests/weights.conf' && grep -q '^# seed: the hidden cases' '$kit/tests/weights.conf'"
check "the kit's tests/weights.conf differs from the instructor's elsewhere than the seed" \
    cmp -s "$tmp/weights.want" "$tmp/weights.got"
for s in labs/scenes/*.scene; do
    name=$(basename "$s" .scene)
    check "the kit lacks $s" cmp -s "$s" "$kit/$s"
    check "the kit lacks the reference render labs/reference/$name.png" test -s "$kit/labs/reference/$name.png"
    check "the kit lacks the reference's pixels on an edge labs/reference/$name.edges" \
        grep -q '^size [0-9]* [0-9]*$' "$kit/labs/reference/$name.edges"
done
# One README, the kit's own (handouts/student-readme.md is its source, and
# not shipped beside it: its links are written from the kit's top).  Every
# picture and file the handouts and the README link to is there.
check "the kit ships handouts/student-readme.md beside its README" test ! -e "$kit/handouts/student-readme.md"
# The instructor's pages stay with the instructor: the guide (grading a
# class, the hidden tests, the platforms) and the grader's README.
check "the kit ships the instructor guide (handouts/instructor-guide.md)" test ! -e "$kit/handouts/instructor-guide.md"
check "the kit ships the grader's README (tests/grader/README.md)" test ! -e "$kit/tests/grader/README.md"
for md in "$kit"/README.md "$kit"/handouts/*.md; do
    base=$(dirname "$md")
    sed -n 's/.*\](\([^)#]*\)).*/\1/p; s/.*src="\([^"]*\)".*/\1/p' "$md" | grep -v '^[a-z]*:' |
        sort -u >"$tmp/links"
    while read -r link; do
        check "${md#$kit/} links to $link, which is not in the kit" test -e "$base/$link"
    done <"$tmp/links"
done
for png in "$kit"/handouts/figures/*.png; do
    size=$(wc -c <"$png")
    check "${png#$kit/} is $size bytes (over 200 KB)" test "$size" -le 204800
done

# ---- no line of the solutions' bodies anywhere in the kit -----------------
# Lines inside the function bodies ("{" ... "}" at the start of a line),
# comments removed, blanks squeezed; short ones ("return true;") and those
# the skeletons and headers of labs/ already hold (their stubs, the
# helpers' examples) are left out.  The kit's code under labs/kit is not:
# it must not hold a line of the solutions (its closest hit over planes and
# triangles must not hand out Part 3b's ray_color).
cat >"$tmp/body.awk" <<'EOF'
/^\{/ { inside = 1; next }
/^\}/ { inside = 0; next }
inside {
    line = $0; out = ""
    while (line != "") {
        if (comment) {
            k = index(line, "*/")
            if (k == 0) break
            line = substr(line, k + 2); comment = 0
        } else {
            a = index(line, "/*"); b = index(line, "//")
            if (b > 0 && (a == 0 || b < a)) { out = out substr(line, 1, b - 1); break }
            if (a == 0) { out = out line; break }
            out = out substr(line, 1, a - 1); line = substr(line, a + 2); comment = 1
        }
    }
    print out
}
EOF
# absent TEXT: the lines of stdin found nowhere in the file TEXT (as a
# substring of one of its lines), in one pass.
absent() {
    awk 'FNR == NR { text = text "\n" $0; next } !index(text, $0)' "$1" -
}
cat labs/*.c labs/*.h | squeeze >"$tmp/labs.txt"
for f in solutions/*.c; do
    awk -f "$tmp/body.awk" "$f"
done | squeeze | awk 'length($0) >= 14' | absent "$tmp/labs.txt" >"$tmp/patterns"
npatterns=$(wc -l <"$tmp/patterns")
check "the scan has lines of the solutions to look for ($npatterns)" test "$npatterns" -ge 10
# The scan itself works: it finds every line in the solutions.
cat solutions/*.c | squeeze >"$tmp/solutions.txt"
missed=$(absent "$tmp/solutions.txt" <"$tmp/patterns" | wc -l | tr -d ' ')
check "the scan finds its own lines in solutions/ ($missed missed)" test "$missed" -eq 0
# Every file of the kit, squeezed as squeeze does, each line after its
# file's name and a tab (no pattern holds a tab), through one grep.
(cd "$kit" && find . -type f | sed 's|^\./||' | sort | awk '{
    f = $0
    while ((getline line <f) > 0) {
        gsub(/[ \t]+/, " ", line); sub(/^ /, "", line); sub(/ $/, "", line)
        print f "\t" line
    }
    close(f)
}') >"$tmp/kit.txt" 2>/dev/null
grep -a -F -f "$tmp/patterns" "$tmp/kit.txt" >"$tmp/leaks"
leaks=0
cut -f 1 "$tmp/leaks" | uniq >"$tmp/leaking"
while IFS= read -r f; do
    leaks=$((leaks + 1))
    echo "FAIL: $f holds lines of the solutions:"
    awk -F '\t' -v f="$f" '$1 == f' "$tmp/leaks" | cut -f 2- | sed -n '1,5s/^/    | /p'
done <"$tmp/leaking"
if [ "$leaks" -eq 0 ]; then pass; else failed=$((failed + leaks)); fi

# ---- it builds, warning-free ----------------------------------------------
run_in "$kit" make
if [ "$status" -ne 0 ]; then
    fail "make in the kit: exit $status"
    finish
elif grep -q -i 'warning' "$tmp/out"; then
    fail "make in the kit prints warnings"
    grep -i 'warning' "$tmp/out" | sed -n '1,5s/^/    | /p'
else
    pass
fi

# make help lists what runs here, and no target of the instructor's kit.
run_in "$kit" make help
check "the kit's make help lists render, compare, grade, test and clean, and nothing of the instructor's" \
    sh -c "[ $status -eq 0 ] && grep -q '^make render' '$tmp/out' && grep -q '^make compare' '$tmp/out' &&
           grep -q '^make grade ' '$tmp/out' && grep -q 'make test | clean' '$tmp/out' &&
           ! grep -q -e grade-all -e sort-submissions -e 'make gradescope' -e student-kit -e bench -e fuzz \
                     -e sanitize-grader -e handouts -e selftests '$tmp/out'"

# ---- the untouched skeleton: 0 on every part, status 1 --------------------
run_in "$kit" make grade
if crashed; then
    fail "make grade on the skeleton crashed"
elif [ "$ran" -ne 1 ]; then
    fail "make grade on the skeleton: the grader's status is $ran, want 1"
else
    pass
fi
for p in 1 2 3a 3b; do
    set -- $(part_points "$p")
    if [ $# -ne 2 ]; then
        fail "make grade on the skeleton: no line for Part $p"
    elif [ "$1" != 0 ]; then
        fail "make grade on the skeleton: Part $p scores $1 / $2, want 0"
    else
        pass
    fi
done
check "make grade on the skeleton: Score: 0 / 100" grep -q '^Score: 0 / 100' "$tmp/out"
check "make grade on the skeleton is short ($(wc -l <"$tmp/out" | tr -d ' ') lines, at most 150; a part not written yet is one line)" \
    sh -c "[ \$(wc -l <'$tmp/out') -le 150 ] && [ \$(grep -c '   not written yet: every answer' '$tmp/out') -eq 4 ]"
check "make grade on the untouched kit says nothing of its headers" \
    sh -c "! grep -q 'is not the one the kit came with' '$tmp/out'"

# ---- the report page: out/report/index.html, with the stored reference ----
page=$kit/out/report/index.html
check "make grade in the kit ends with the report page's path" \
    sh -c "grep -v '^make' '$tmp/out' | tail -n 1 | grep -q 'out/report/index.html'"
check "make grade in the kit writes out/report/index.html" test -s "$page"
check_output "the kit's report page is safe to open and self-contained (tests/lib/pages.sh)" page_safe "$page"
check "the kit's report page shows the stored reference render" \
    grep -q 'alt="the scene drawn by the reference solution"' "$page"
run_in "$kit" make grade PART=1 RESULTS=out/results.json
check "the results file names no report page (Gradescope has none)" \
    sh -c "[ -s '$kit/out/results.json' ] && ! grep -q -e 'html' -e 'out/report' '$kit/out/results.json'"

# ---- every make command of the handouts runs as written --------------------
# Lines of ```sh blocks that start with "make ", each run once in the kit
# (on the skeleton): `make grade` and `make compare` may end with status 1
# (points lost, the images differ); anything else must succeed.
for md in "$kit"/README.md "$kit"/handouts/*.md; do
    awk -v name="${md#$kit/}" '
        /^```/ { if (fence) fence = 0; else fence = ($0 ~ /^```sh[ \t]*$/); next }
        fence && /^make( |$)/ { print name "\t" $0 }' "$md"
done >"$tmp/commands"
check "the handouts have make commands to try" test -s "$tmp/commands"
awk -F '\t' '!seen[$2]++ { print $2 }' "$tmp/commands" >"$tmp/unique"
while IFS= read -r command; do
    where=$(awk -F '\t' -v c="$command" '$2 == c { print $1 }' "$tmp/commands" | sort -u |
        tr '\n' ' ' | sed 's/ $//')
    case $command in
        "make grade"*|"make compare"*) allowed="0 or 1" ;;
        *) allowed="0" ;;
    esac
    run_in "$kit" sh -c "$command"
    if crashed; then
        fail "'$command' (in $where) crashed"
    elif [ "$ran" -ne 0 ] && { [ "$ran" -ne 1 ] || [ "$allowed" = 0 ]; }; then
        fail "'$command' (in $where): status $ran, want $allowed"
    else
        pass
    fi
done <"$tmp/unique"

# ---- GitHub Classroom: the workflow, and its runners' results -------------
. tests/lib/classroom.sh
: >"$tmp/out"
wf="$kit/.github/workflows/classroom.yml"
check "the student kit has .github/workflows/classroom.yml" [ -s "$wf" ]

check "the workflow has no tab" sh -c "! grep -q '	' '$wf'"
check "the workflow's indentation is in steps of two spaces" \
    sh -c "! awk '/^ *[^ #]/ { match(\$0, /^ */); if (RLENGTH % 2) bad = 1 } END { exit !bad }' '$wf'"
check "the workflow runs on push" grep -q '^  - push$' "$wf"
check "the workflow names the reporter action" \
    grep -q '^        uses: classroom-resources/autograding-grading-reporter@v1$' "$wf"
check "the workflow's grade step has id 'grade'" grep -q '^        id: grade$' "$wf"
check "the grade step appends to \$GITHUB_OUTPUT" \
    grep -q '^        run: make grade CLASSROOM="\$GITHUB_OUTPUT"' "$wf"
runners=$(sed -n 's/^          runners: //p' "$wf")
check "the workflow has a runners: line" [ -n "$runners" ]
check "its runner ids are letters and digits, comma-separated (as the action asks)" \
    sh -c "printf '%s' '$runners' | grep -Eq '^([a-zA-Z0-9]+,)*[a-zA-Z0-9]+\$'"
# The reporter step's environment: NAME_RESULTS from steps.grade.outputs.id
sed -n 's/^          \([A-Za-z0-9_-]*\): "\${{ steps\.grade\.outputs\.\([A-Za-z0-9_-]*\) }}"$/\1 \2/p' \
    "$wf" >"$tmp/envmap"
nenv=$(wc -l <"$tmp/envmap")
nrun=$(printf '%s' "$runners" | tr ',' '\n' | grep -c .)
check "one environment variable per runner ($nenv for $nrun)" [ "$nenv" -eq "$nrun" ]
check "each runner's variable is its id in capitals with _RESULTS" sh -c "
    printf '%s' '$runners' | tr ',' '\n' | while read -r id; do
        up=\$(printf '%s' \"\$id\" | tr 'a-z' 'A-Z')
        grep -qx \"\${up}_RESULTS \$id\" '$tmp/envmap' || exit 1
    done"
# One run of python3 both asks for the module and parses (a python3 started
# through a version manager's shims can take a second to start).
have_yaml=no
if command -v python3 >/dev/null 2>&1; then
    python3 - "$wf" "$runners" >"$tmp/yaml.out" 2>&1 <<'EOF_PY'
import sys
try:
    import yaml
except ImportError:
    sys.exit(0)
print("yaml module found")
doc = yaml.safe_load(open(sys.argv[1]))
runners = sys.argv[2].split(",")
on = doc.get("on", doc.get(True))
assert "push" in on, "not run on push"
steps = [s for job in doc["jobs"].values() for s in job["steps"]]
grade = [s for s in steps if s.get("id") == "grade"]
assert len(grade) == 1 and 'CLASSROOM="$GITHUB_OUTPUT"' in grade[0]["run"], "no grade step"
rep = [s for s in steps if s.get("uses") == "classroom-resources/autograding-grading-reporter@v1"]
assert len(rep) == 1, "no reporter step"
assert steps.index(rep[0]) > steps.index(grade[0]), "the reporter runs before grading"
assert rep[0]["with"]["runners"] == ",".join(runners), "runners differ"
want = {r.upper() + "_RESULTS": "${{ steps.grade.outputs.%s }}" % r for r in runners}
assert rep[0]["env"] == want, "env differs"
print("ok")
EOF_PY
    grep -qx 'yaml module found' "$tmp/yaml.out" && have_yaml=yes
fi
if [ "$have_yaml" = yes ]; then
    check "the workflow parses as YAML with the steps, runners and env ($(tail -n 1 "$tmp/yaml.out"))" \
        grep -qx ok "$tmp/yaml.out"
else
    echo "python3 with its yaml module is not installed: skipped parsing the workflow as YAML"
fi

# reporter_env MAP OUTPUTS: the reporter's environment, "VAR=VALUE" for
# each "VAR ID" line of MAP, VALUE being what OUTPUTS holds after "ID=" (as
# the workflow passes the grade step's outputs); one awk for all runners.
reporter_env() {
    awk 'NR == FNR { var[++n] = $1; id[n] = $2; next }
         { k = index($0, "=") }
         k > 1 { key = substr($0, 1, k - 1)
                 v = (key in val) ? val[key] "\n" substr($0, k + 1) : substr($0, k + 1)
                 val[key] = v }
         END { for (i = 1; i <= n; i++) print var[i] "=" val[id[i]] }' "$1" "$2"
}

# grade_kit LABEL SUBMISSION CASE WANT_WORKFLOW: make grade in the kit,
# CLASSROOM standing in for $GITHUB_OUTPUT (with an earlier step's line in
# it), then the environment the workflow gives the reporter, and the
# reporter's totals from it (totals CASE ... WANT_WORKFLOW).
grade_kit() {
    label=$1 sub=$2
    printf 'earlier=an output of an earlier step\n' >"$tmp/$label.outputs"
    (cd "$kit" && make grade SUBMISSION="$sub" CLASSROOM="$tmp/$label.outputs") >"$tmp/$label.kit" 2>&1
    check "$label: the earlier step's output is kept" \
        sh -c "head -n 1 '$tmp/$label.outputs' | grep -qx 'earlier=an output of an earlier step'"
    check "$label: one line per runner of the workflow, in its order" \
        sh -c "sed -n '2,\$p' '$tmp/$label.outputs' | cut -d= -f1 | paste -s -d, - | grep -qx '$runners'"
    reporter_env "$tmp/envmap" "$tmp/$label.outputs" >"$tmp/$label.env"
    longest=$(awk '{ if (length($0) > n) n = length($0) } END { print n + 0 }' "$tmp/$label.outputs")
    check "$label: every runner's results are under 64 KB (an environment variable may hold 128 KB): $longest bytes" \
        [ "$longest" -lt 65536 ]
    decode "$runners" "$tmp/$label.env" >"$tmp/$label.dump"
    check "$label: every runner decodes" [ "$(grep -c '^[a-z0-9]* {"version":1,' "$tmp/$label.dump")" -eq "$nrun" ]
    check "$label: no test is a hidden test" sh -c "! grep -q '\"name\":\"[^\"]*hidden' '$tmp/$label.dump'"
    totals "$3" "$tmp/$1.kit" "$runners" "$tmp/$1.env" "$4"
}
grade_kit student-full "$tmp/full" "student kit, reference" pass
check "student kit, reference: full marks" grep -q '^Score: 100 / 100' "$tmp/student-full.kit"
grade_kit student-partial "$tmp/partial" "student kit, partial" fail
check "student kit, partial: partial credit" \
    sh -c "grep '^Score: ' '$tmp/student-partial.kit' | grep -Eqv '^Score: (0|100) '"
grade_kit student-zero "$kit/labs" "student kit, skeleton" fail
check "student kit, skeleton: 0 points" grep -q '^Score: 0 / 100' "$tmp/student-zero.kit"

# With Parts 4 and 5 turned on, the workflow written for that kit lists
# their runners too, and the totals are out of 140 (the kit's own
# weights.conf is put back after).
cp "$kit/tests/weights.conf" "$tmp/weights.kit"
sed 's/^parts .*/parts 1 2 3a 3b 4 5/' "$tmp/weights.kit" >"$kit/tests/weights.conf"
(cd "$kit" && sh "$top/tests/classroom/workflow.sh" "$top/tests/classroom/classroom.yml") >"$tmp/all.yml"
runners_all=$(sed -n 's/^          runners: //p' "$tmp/all.yml")
check "Parts 4 and 5 on: the workflow lists their runners" \
    sh -c "printf '%s' '$runners_all' | grep -q 'part4test1,.*part5test1,.*,hard\$'"
sed -n 's/^          \([A-Za-z0-9_-]*\): "\${{ steps\.grade\.outputs\.\([A-Za-z0-9_-]*\) }}"$/\1 \2/p' \
    "$tmp/all.yml" >"$tmp/envmap.all"
: >"$tmp/all.outputs"
(cd "$kit" && make grade SUBMISSION="$tmp/full" CLASSROOM="$tmp/all.outputs") >"$tmp/all.kit" 2>&1
check "Parts 4 and 5 on: the grader writes the workflow's runners, in its order" \
    sh -c "cut -d= -f1 '$tmp/all.outputs' | paste -s -d, - | grep -qx '$runners_all'"
reporter_env "$tmp/envmap.all" "$tmp/all.outputs" >"$tmp/all.env"
totals "student kit, Parts 1 to 5, reference" "$tmp/all.kit" "$runners_all" "$tmp/all.env" pass
check "student kit, Parts 1 to 5, reference: 140 / 140" grep -q '^Score: 140 / 140' "$tmp/all.kit"
cp "$tmp/weights.kit" "$kit/tests/weights.conf"
js_checks

# A student who puts a macro in labs/raytracer.h is told that the
# instructor grades with the kit's own (their stage file would not build
# there), and which file that is.  Tried in a copy of the built kit (its
# times kept, cp -p), so that the kit itself stays built from the files
# it shipped with: what the header changes is built again in the copy
# alone, and the kit's make rebuilds nothing for it below.
changed=$tmp/changed
cp -R -p "$kit" "$changed"
printf '#define EPSILON 1e-9\n' >>"$changed/labs/raytracer.h"
run_in "$changed" out/build/bin/grade --submission labs --part 1 --quiet
check "a changed labs/raytracer.h: make grade warns that the instructor grades with the kit's own" \
    sh -c "grep -q 'grade: labs/raytracer.h is not the one the kit came with' '$tmp/out' &&
           grep -q 'tests/grader/shipped/raytracer.h' '$tmp/out' && cmp -s labs/raytracer.h '$kit/tests/grader/shipped/raytracer.h'"
# A stage file that uses the macro: it built here, with the changed header,
# and got full marks, where the instructor's grader (the kit's own header)
# gives 0. make grade here builds it with the kit's own too, and says so
# below the compiler's message.
sed 's/\*h = 2 \* d \* tan_half;/*h = 2 * d * tan_half * (1 + EPSILON);/' solutions/part1_image_plane.c \
    >"$changed/labs/part1_image_plane.c"
run_in "$changed" out/build/bin/grade --submission labs --part 1
check "a stage file that uses a macro added to labs/raytracer.h does not build in make grade either (exit $status)" \
    sh -c "[ $status -eq 1 ] && grep -q 'EPSILON' '$tmp/out' && grep -q '^Part 1: .*  0 / 20' '$tmp/out' &&
           grep -q 'labs/raytracer.h is not the one the kit came with: part1_image_plane.c was built with the kit.s own' '$tmp/out'"
run_in "$changed" ${MAKE:-make} --no-print-directory render OUT="$tmp/changed.png"
check "... while make render, which builds with labs/raytracer.h, draws and notes that it is not the kit's (exit $status)" \
    sh -c "[ $status -eq 0 ] && [ -s '$tmp/changed.png' ] &&
           grep -q '^note: labs/raytracer.h is not the one the kit came with. make render used yours' '$tmp/out' &&
           ! grep -q 'labs/vec3.h is not' '$tmp/out'"
# The header as shipped, with its time: make render below builds Part 1
# again (the stage file is newer) and nothing the header alone changed.
cp -p "$kit/labs/raytracer.h" "$changed/labs/raytracer.h"
run_in "$changed" out/build/bin/grade --submission labs --part 1
check "... and, with the header as shipped, neither it nor the warning is there (exit $status)" \
    sh -c "[ $status -eq 1 ] && grep -q 'EPSILON' '$tmp/out' && ! grep -q 'is not the one the kit came with' '$tmp/out'"
cp "$kit/labs/part1_image_plane.c" "$changed/labs/part1_image_plane.c"
run_in "$changed" ${MAKE:-make} --no-print-directory render OUT="$tmp/changed.png"
check "make render says nothing of the header once it is as shipped (exit $status)" \
    sh -c "[ $status -eq 0 ] && ! grep -q 'is not the one the kit came with' '$tmp/out'"

# ---- the reference stage files in labs/: full marks, identical renders ----
cp solutions/*.c "$kit/labs/"
run_in "$kit" make grade
if crashed; then
    fail "make grade with the reference crashed"
elif [ "$status" -ne 0 ]; then
    fail "make grade with the reference: exit $status (grader $ran), want 0"
elif ! grep -q '^Score: 100 / 100' "$tmp/out"; then
    fail "make grade with the reference: no 'Score: 100 / 100'"
else
    pass
fi
for p in 1 2 3a 3b; do
    set -- $(part_points "$p")
    if [ $# -ne 2 ] || [ "$1" != "$2" ]; then
        fail "make grade with the reference: Part $p scores '${1:-}' / '${2:-}', want full marks"
    else
        pass
    fi
done
# The render in the sandbox at the scene's own size matches the stored
# reference render exactly.
check "the report page with the reference: its picture is exactly the stored reference's" \
    grep -q 'Your picture is exactly the reference' "$kit/out/report/index.html"
for s in "$kit"/labs/scenes/*.scene; do
    name=$(basename "$s")
    run_in "$kit" make compare SUBMISSION=labs SCENE="labs/scenes/$name"
    check "make compare SUBMISSION=labs SCENE=labs/scenes/$name with the reference: exit $status, not identical" \
        sh -c "[ $status -eq 0 ] && grep -q '^identical$' '$tmp/out'"
done

# The lecture's Part 2 and the textbook's Part 4 (tests/selftest/textbook-
# ground), right but for rounding where the wall meets the ground and along
# the box's outline: identical, with the stored pixels on an edge.
if [ -d "$selftest/textbook-ground" ]; then
    mkdir -p "$tmp/textbook"
    cp solutions/*.c "$tmp/textbook/"
    cp "$selftest"/textbook-ground/*.c "$tmp/textbook/"
    for name in ground cracks; do
        run_in "$kit" make compare SUBMISSION="$tmp/textbook" SCENE="labs/scenes/$name.scene"
        check "make compare in the kit: the textbook's $name.scene is identical to the stored reference (exit $status)" \
            sh -c "[ $status -eq 0 ] && grep -q 'on an edge' '$tmp/out' && grep -q '^identical$' '$tmp/out'"
    done
fi

# The textbook's Part 3a: every core point, some hard cases (the extra
# credit) lost, so make ends with Error 1 below "Score: 30 / 30"; the line
# above make's says why, so that it does not read as a broken build.
# Made a repository (a GitHub Classroom template), the kit's builds stay
# out of it: a student's `git add -A` adds no file of out/.
if command -v git >/dev/null 2>&1; then
    (cd "$kit" && HOME=$tmp GIT_CONFIG_NOSYSTEM=1 GIT_CONFIG_GLOBAL=/dev/null git init -q &&
        HOME=$tmp GIT_CONFIG_NOSYSTEM=1 GIT_CONFIG_GLOBAL=/dev/null git add -A -n) >"$tmp/out" 2>&1
    status=$?
    built=$(ls "$kit/out" | wc -l | tr -d ' ')
    check "git add -A in the kit adds none of its builds ($built entries in out/; exit $status)" \
        sh -c "[ $status -eq 0 ] && [ $built -gt 0 ] && grep -q \"^add 'labs/\" '$tmp/out' &&
               ! grep -q \"^add 'out/\" '$tmp/out'"
    rm -rf "$kit/.git"
else
    echo "skipped: git is not installed (the kit as a repository keeps its builds out)"
fi

cp "$selftest"/textbook/part3a_sphere_intersect.c "$kit/labs/"
run_in "$kit" make grade PART=3a
check "make grade with the textbook's Part 3a: full core points, and why make says Error 1 (exit $status, grader $ran)" \
    sh -c "[ $ran -eq 1 ] && grep -q '^Score: 30 / 30 ' '$tmp/out' &&
           grep -q '^All the core points. Some hard cases failed, which count only as extra credit:' '$tmp/out' &&
           grep -q '^that is why the grader exits with status 1 (make says Error 1)' '$tmp/out'"
cp solutions/part3a_sphere_intersect.c "$kit/labs/"
run_in "$kit" make grade PART=3a
check "... and with the reference's, not a word of it (exit $status)" \
    sh -c "[ $status -eq 0 ] && ! grep -q 'All the core points' '$tmp/out'"

# A helper defined, not static, in Parts 3a and 3b (tests/selftest/
# link-shared-helper): here Part 3b's program links the student's own Part
# 3a, and the linker refuses two dot()s; the grader builds it with each
# file's dot its own, as the instructor's grader does (with the
# reference's Part 3a), and says what make render says: write static.
cp "$selftest"/link-shared-helper/part*.c "$kit/labs/"
run_in "$kit" make grade PART=3b
check "a non-static helper in Parts 3a and 3b: Part 3b keeps its 30 points, and is told to write static (exit $status, grader $ran)" \
    sh -c "grep -q '^Part 3b: .*  30 / 30' '$tmp/out' && ! grep -q 'did not build' '$tmp/out' &&
           grep -q 'dot is defined in part3b_ray_color.c and part3a_sphere_intersect.c' '$tmp/out' &&
           grep -q 'Write static in front of each definition of dot' '$tmp/out'"
run_in "$kit" make render
check "... which make render stops at, saying the same (exit $status)" \
    sh -c "[ $status -ne 0 ] && grep -q 'write static in front of each' '$tmp/out'"
cp solutions/part3a_sphere_intersect.c solutions/part3b_ray_color.c "$kit/labs/"

finish
