# classroom.sh - GitHub Classroom's grading reporter: its rules total the
# runners `make grade CLASSROOM=file` writes, the student kit's through its
# workflow (tests/suites/student_kit.sh) and the instructor's kit's straight
# from the file (tests/suites/classroom.sh).  Sourced after checks.sh and
# need_selftests "$tmp/selftest", it writes the submissions $tmp/full,
# $tmp/partial and $tmp/broken (below) and defines:
#   decode RUNNERS ENVFILE   each runner's results as the reporter reads them
#   reporter DUMP            the reporter's totals, by its source's rules
#   totals LABEL KIT_OUTPUT RUNNERS ENVFILE WANT_WORKFLOW
#                            checks that both of the reporter's totals -- the
#                            points it shows, (tests passed / tests) x
#                            max_score added over the runners, and the points
#                            it sends the classroom, the tests' scores added
#                            up -- are the kit's core score (its "Score: X / Y"
#                            line, and each part's line), out of the core total
#   js_checks                with node installed, the totals of every case
#                            totals() saw worked out again in JavaScript
#                            (Node's own base64 and JSON)
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
# renders through the faulty Part 3a); one with a part that does not
# compile.  The suites add the untouched skeleton.
mkdir -p "$tmp/full" "$tmp/partial" "$tmp/broken"
cp solutions/*.c "$tmp/full/"
cp solutions/*.c "$tmp/partial/"
cp "$selftest"/p1-aspect-inverted/*.c "$selftest"/p3a-tangent-miss/*.c "$tmp/partial/"
cp solutions/*.c "$tmp/broken/"
cp "$selftest"/hostile-compile-error/*.c "$selftest"/p1-aspect-inverted/*.c "$tmp/broken/"
chmod -R a+rX "$tmp/full" "$tmp/partial" "$tmp/broken"
