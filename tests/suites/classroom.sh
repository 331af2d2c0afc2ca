#!/bin/sh
# GitHub Classroom: the student kit's workflow and the runner results that
# `make grade CLASSROOM=file` appends, totalled by the grading reporter's
# own rules (reporter(), below, which cites the action's source), for a full-marks, a partial and a zero submission.  Each time,
# both of the reporter's totals -- the points it shows, (tests passed /
# tests) x max_score added over the runners, and the points it sends the
# classroom, the tests' scores added up -- must be the kit's own core score
# (its "Score: X / Y" line, and each part's line), out of the core total.
#
#   - in the unpacked student kit (no hidden tests), through its workflow:
#     the runner ids of its "runners:" input, the environment variables its
#     reporter step sets from the grade step's outputs, the CLASSROOM file
#     standing in for $GITHUB_OUTPUT (a line already in it is kept);
#   - in the instructor's kit (hidden tests, points such as 30/14), with
#     the runners straight from the file, and a part that does not compile;
#   - the workflow itself: the reporter action, the grade step, one
#     environment variable per runner, runner ids the action accepts;
#     parsed as YAML too when python3 has its yaml module;
#   - with node installed, the totals worked out again in JavaScript from
#     the same environment, by Node's own base64 and JSON.
#
# Usage: sh tests/suites/classroom.sh   (from the kit's top directory, after
# make).  KEEP=1 keeps the temporary directory.
set -u
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES
top=$(pwd)
. tests/lib/checks.sh
temp_dir rtclassroom
chmod 755 "$tmp"
# The self-test submissions, a folder each.
selftest=$tmp/selftest
need_selftests "$selftest"

# ---- the reporter's rules -----------------------------------------------------
# decode RUNNERS ENVFILE: each runner's results as the reporter reads them,
# "ID JSON" one runner a line: the runner id of the comma-separated RUNNERS,
# trimmed, in capitals, with _RESULTS, names the variable of ENVFILE
# ("NAME=VALUE" lines) holding base64 of the JSON.  awk decodes it (base64's
# option to decode differs between Linux and macOS).
decode() {
    printf '%s\n' "$1" | tr ',' '\n' | LC_ALL=C awk '
        BEGIN { a = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/"
                for (i = 0; i < 64; i++) v[substr(a, i + 1, 1)] = i }
        NR == FNR { gsub(/^ +| +$/, ""); id[++n] = $0; next }
        { k = index($0, "="); if (k > 1) val[substr($0, 1, k - 1)] = substr($0, k + 1) }
        END { for (r = 1; r <= n; r++) {
                  s = val[toupper(id[r]) "_RESULTS"]; out = ""; bits = 0; nb = 0
                  for (i = 1; i <= length(s); i++) {
                      c = substr(s, i, 1)
                      if (c == "=") break
                      bits = bits * 64 + v[c]; nb += 6
                      if (nb >= 8) { nb -= 8; b = int(bits / 2 ^ nb); bits -= b * 2 ^ nb; out = out sprintf("%c", b) }
                  }
                  print id[r], out } }' - "$2"
}
# reporter DUMP: the reporter's totals from decode's lines, by the rules of
# the action's source (classroom-resources/autograding-grading-reporter, v1):
# a runner's points are its tests with status "pass" over its tests, times
# its max_score (src/helpers/test-helpers.js), added over the runners for
# the table (src/aggregate-results.js); what it sends the classroom adds the
# "score" of each test of the runners whose max_score is not 0
# (src/notify-classroom.js); the step fails when a runner's status is "fail"
# or "error" (src/main.js).  One line per runner, then the totals:
#   runner ID status S tests N passed P max M shown X counted C
#   shown_total X / shown_max M / counted_total T / counted_max N / workflow W
# Each runner's JSON is the kit's own (one object, "status" and "max_score"
# first, then "tests"): these patterns read that and nothing more.
reporter() {
    LC_ALL=C awk '
        function num(name, s) { return match(s, "\"" name "\":[^,}]*") ? substr(s, RSTART + length(name) + 3, RLENGTH - length(name) - 3) + 0 : 0 }
        { st = $0; sub(/^[^ ]* {"version":1,"status":"/, "", st); sub(/".*/, "", st)
          max = num("max_score", $0)
          t = $0; ntests = gsub(/"name":/, "", t)
          t = $0; npass = gsub(/"status":"pass","score":/, "", t)
          shown = ntests ? npass / ntests * max : 0
          counted = 0
          if (max) { t = $0; sub(/^.*"tests":/, "", t)
                     while (match(t, /"score":[^,}]*/)) { counted += substr(t, RSTART + 8, RLENGTH - 8); t = substr(t, RSTART + RLENGTH) } }
          printf "runner %s status %s tests %d passed %d max %.17g shown %.17g counted %.17g\n", $1, st, ntests, npass, max, shown, counted
          if (st == "fail" || st == "error") wf = "fail"
          st_total += shown; st_max += max; c_total += counted; c_max += max }
        END { printf "shown_total %.17g\nshown_max %.17g\ncounted_total %.17g\ncounted_max %.17g\nworkflow %s\n", st_total, st_max, c_total, c_max, wf == "" ? "pass" : wf }' "$1"
}
have_node=
if command -v node >/dev/null 2>&1; then
    have_node=1
else
    echo "node is not installed: skipped the JavaScript check of the totals"
fi

# The JavaScript check: the reporter's rules again, written from its source
# in JavaScript, reading the same environment file with Node's own base64
# and JSON.  One run of node does every case totals() listed (node takes a
# quarter of a second to start): each line of the list is "N<tab>RUNNERS
# <tab>ENVFILE"; it writes the four totals to js.N.out, or why not to js.N.err.
cat >"$tmp/totals.js" <<'EOF_JS'
const fs = require("fs");
const path = require("path");
function totals(runnersInput, envFile) {
  const env = {};
  for (const line of fs.readFileSync(envFile, "utf-8").split("\n")) {
    const at = line.indexOf("=");
    if (at > 0) env[line.slice(0, at)] = line.slice(at + 1);
  }
  let shown = 0, shownMax = 0, counted = 0, countedMax = 0;  // portable: JavaScript
  for (const id of runnersInput.split(",")) {
    const r = JSON.parse(Buffer.from(env[id.trim().toUpperCase() + "_RESULTS"], "base64").toString("utf-8"));
    const max = r.max_score || 0;
    const passing = r.tests.filter((t) => t.status === "pass").length;
    shown += (passing / r.tests.length) * max;
    shownMax += max;
    if (r.max_score) {
      countedMax += r.max_score;
      for (const t of r.tests) counted += t.score;
    }
  }
  return `shown_total ${shown}\nshown_max ${shownMax}\ncounted_total ${counted}\ncounted_max ${countedMax}\n`;
}
const list = process.argv[2], dir = path.dirname(list);
for (const line of fs.readFileSync(list, "utf-8").split("\n")) {
  if (!line) continue;
  const [n, runnersInput, envFile] = line.split("\t");
  try {
    fs.writeFileSync(`${dir}/js.${n}.out`, totals(runnersInput, envFile));
  } catch (e) {
    fs.writeFileSync(`${dir}/js.${n}.err`, String(e && e.stack || e) + "\n");
  }
}
EOF_JS
: >"$tmp/js.list"
njs=0

# value NAME FILE: the number after NAME in the checker's output
value() { sed -n "s/^$1 //p" "$2"; }
# The kit prints points rounded to two decimals, without trailing zeros
# (points_text, tests/grader/cases.c): pts in awk, g in the shell.
pts='function pts(x,   s) { s = sprintf("%.2f", x); sub(/0+$/, "", s); sub(/[.]$/, "", s)
                          return s == "-0" ? "0" : s }'
g() { awk -v x="$1" "$pts"' BEGIN { printf "%s", pts(x + 0) }'; }

# totals LABEL KIT_OUTPUT RUNNERS ENVFILE WANT_WORKFLOW: runs the checker and
# compares both totals with the kit's score and each part's points.
totals() {
    label=$1 kitout=$2 runners=$3 envfile=$4 want_workflow=$5
    decode "$runners" "$envfile" >"$tmp/totals.dump"
    reporter "$tmp/totals.dump" >"$tmp/totals.out"
    score=$(sed -n 's/^Score: \([^ ]*\) \/ \([^ ]*\).*/\1/p' "$kitout")
    max=$(sed -n 's/^Score: \([^ ]*\) \/ \([^ ]*\).*/\2/p' "$kitout")
    shown=$(value shown_total "$tmp/totals.out")
    counted=$(value counted_total "$tmp/totals.out")
    check "$label: the kit printed its score" [ -n "$score" ]
    check "$label: the points shown ($shown) are the kit's core score ($score)" [ "$(g "$shown")" = "$score" ]
    check "$label: the points sent to the classroom ($counted) are the kit's core score ($score)" \
        [ "$(g "$counted")" = "$score" ]
    check "$label: both totals are the same number ($shown, $counted)" [ "$shown" = "$counted" ]
    check "$label: the maximum shown is the core total ($max)" \
        [ "$(g "$(value shown_max "$tmp/totals.out")")" = "$max" ]
    check "$label: the maximum sent is the core total ($max)" \
        [ "$(g "$(value counted_max "$tmp/totals.out")")" = "$max" ]
    check "$label: the reporter's step ends with '$want_workflow'" \
        [ "$(value workflow "$tmp/totals.out")" = "$want_workflow" ]
    # Each part: its runners' points against the kit's line for the part.
    for p in 1 2 3a 3b 4 5; do
        line=$(sed -n "s/^Part $p: .*   \([^ ]*\) \/ \([^ ]*\).*/\1 \2/p" "$kitout" | head -n 1)
        [ -n "$line" ] || continue
        got=$(awk -v p="$p" "$pts"' $1 == "runner" && $2 ~ ("^part" p "test") { s += $12; m += $10 }
                             END { printf "%s %s", pts(s), pts(m) }' "$tmp/totals.out")
        check "$label: Part $p's runners add up to the kit's $line (got $got)" [ "$got" = "$line" ]
    done
    hard=$(awk '$1 == "runner" && $2 == "hard" { print $10, $12, $14 }' "$tmp/totals.out")
    check "$label: the runner 'hard' is there and worth 0 ($hard)" [ "$hard" = "0 0 0" ]
    # The JavaScript check, for js_checks at the end.
    njs=$((njs + 1))
    grep -E '_(total|max) ' "$tmp/totals.out" >"$tmp/c.$njs.out"
    printf '%s\t%s\t%s\n' "$njs" "$runners" "$envfile" >>"$tmp/js.list"
    printf '%s\n' "$label" >"$tmp/js.$njs.label"
}

# js_checks: node's totals of every case totals() listed, each against
# reporter()'s (to two decimals, as the kit prints points).
js_checks() {
    [ -n "$have_node" ] || return 0
    node "$tmp/totals.js" "$tmp/js.list" >"$tmp/node.out" 2>&1 ||
        fail "the JavaScript check did not run: $(head -n 3 "$tmp/node.out")"
    k=0
    while [ "$k" -lt "$njs" ]; do
        k=$((k + 1))
        label=$(cat "$tmp/js.$k.label")
        if [ -f "$tmp/js.$k.out" ]; then
            awk "$pts"' { print $1, pts($2) }' "$tmp/js.$k.out" >"$tmp/js.$k.pts"
            awk "$pts"' { print $1, pts($2) }' "$tmp/c.$k.out" >"$tmp/c.$k.pts"
            check_output "$label: JavaScript's totals are reporter()'s" diff "$tmp/c.$k.pts" "$tmp/js.$k.pts"
        else
            fail "$label: the JavaScript check failed: $(head -n 3 "$tmp/js.$k.err" 2>/dev/null)"
        fi
    done
}

# Submissions: the reference; a partial one (two mistakes in two parts,
# each losing some of its part's tests, and in the student kit Part 3b's
# renders through the faulty Part 3a); nothing but the untouched skeleton.
mkdir -p "$tmp/full" "$tmp/partial" "$tmp/broken"
cp solutions/*.c "$tmp/full/"
cp solutions/*.c "$tmp/partial/"
cp "$selftest"/p1-aspect-inverted/*.c "$selftest"/p3a-tangent-miss/*.c "$tmp/partial/"
cp solutions/*.c "$tmp/broken/"
cp "$selftest"/hostile-compile-error/*.c "$selftest"/p1-aspect-inverted/*.c "$tmp/broken/"
chmod -R a+rX "$tmp/full" "$tmp/partial" "$tmp/broken"

# ---- the student kit: its workflow, its grader ------------------------------
make -s student-kit >"$tmp/kit.log" 2>&1
check "make student-kit" [ -f out/student-kit/Makefile ]
kit="$tmp/kit"
cp -R out/student-kit "$kit"
wf="$kit/.github/workflows/classroom.yml"
check "the student kit has .github/workflows/classroom.yml" [ -s "$wf" ]
check "the student kit has no hidden tests" [ ! -e "$kit/tests/hidden" ]
[ -s "$wf" ] || finish

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

(cd "$kit" && make -s grader) >"$tmp/build.log" 2>&1
check "the student kit's grader builds" [ -x "$kit/out/build/bin/grade" ]
[ -x "$kit/out/build/bin/grade" ] || { tail -n 20 "$tmp/build.log"; finish; }

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

# grade_kit LABEL SUBMISSION: make grade in the kit, CLASSROOM standing in
# for $GITHUB_OUTPUT (with an earlier step's line in it), then the
# environment the workflow gives the reporter.
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
}
grade_kit student-full "$tmp/full"
totals "student kit, reference" "$tmp/student-full.kit" "$runners" "$tmp/student-full.env" pass
check "student kit, reference: full marks" grep -q '^Score: 100 / 100' "$tmp/student-full.kit"
grade_kit student-partial "$tmp/partial"
totals "student kit, partial" "$tmp/student-partial.kit" "$runners" "$tmp/student-partial.env" fail
check "student kit, partial: partial credit" \
    sh -c "grep '^Score: ' '$tmp/student-partial.kit' | grep -Eqv '^Score: (0|100) '"
grade_kit student-zero "$kit/labs"
totals "student kit, skeleton" "$tmp/student-zero.kit" "$runners" "$tmp/student-zero.env" fail
check "student kit, skeleton: 0 points" grep -q '^Score: 0 / 100' "$tmp/student-zero.kit"

# With Parts 4 and 5 turned on, the workflow written for that kit lists
# their runners too, and the totals are out of 140.
sed 's/^parts .*/parts 1 2 3a 3b 4 5/' "$kit/tests/weights.conf" >"$tmp/weights.all"
cp "$tmp/weights.all" "$kit/tests/weights.conf"
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

# ---- the instructor's kit: hidden tests, a part that does not build --------
# The runners are those the file holds (the workflow is the student kit's).
for case in full partial broken zero; do
    sub=$tmp/$case
    [ "$case" = zero ] && sub=labs
    : >"$tmp/i-$case.outputs"
    out/build/bin/grade --submission "$sub" --classroom "$tmp/i-$case.outputs" >"$tmp/i-$case.kit" 2>&1
    ids=$(cut -d= -f1 "$tmp/i-$case.outputs" | paste -s -d, -)
    awk -F= '{ id = $1; sub(/^[^=]*=/, ""); print toupper(id) "_RESULTS=" $0 }' \
        "$tmp/i-$case.outputs" >"$tmp/i-$case.env"
    want=fail
    [ "$case" = full ] && want=pass
    totals "instructor's kit, $case" "$tmp/i-$case.kit" "$ids" "$tmp/i-$case.env" "$want"
    cp "$tmp/totals.out" "$tmp/i-$case.totals"
done
# The partial submission (p1-aspect-inverted with p3a-tangent-miss): each
# runner's points as committed (Part 1 at 2.5 / 20, Part 3a at 28.33 / 30).
check_output "instructor's kit, partial: the reporter's view is tests/classroom/expected/partial.totals" \
    diff tests/classroom/expected/partial.totals "$tmp/i-partial.totals"
decode "$(cut -d= -f1 "$tmp/i-full.outputs" | paste -s -d, -)" "$tmp/i-full.env" >"$tmp/i-full.dump"
check "instructor's kit: hidden tests are among the runners" grep -q '"name":"Part 3a: hidden: ' "$tmp/i-full.dump"
decode part2test1 "$tmp/i-broken.env" >"$tmp/broken.json"
check "a part that does not build: its runners are errors that say so" \
    sh -c "grep -q '\"status\":\"error\"' '$tmp/broken.json' && grep -q 'did not build' '$tmp/broken.json'"

# ---- bad input ---------------------------------------------------------------
out/build/bin/grade --submission "$tmp/full" --classroom "$tmp/no/such/dir/file" --quiet >"$tmp/bad.out" 2>&1
status=$?
check "an unwritable CLASSROOM file: status 2 (got $status)" [ "$status" -eq 2 ]
check "an unwritable CLASSROOM file: the error names it" grep -q 'no/such/dir/file' "$tmp/bad.out"

js_checks
finish
