# The class page (OUT/index.html) and OUT/causes.csv that grade --all
# writes (tests/grader/report_class.h), read here with awk readers of the
# kit's own and checked against the results files (OUT/<name>.json) and the
# gradebook:
#   - causes.csv holds exactly the causes of the results' extra_data, each
#     under exactly the submissions that have it, with their number;
#   - so does the page's table of causes, most common first in each part,
#     each name linked to its own page and written as the page escapes it;
#     a cause the part's handout lists says so, and no other;
#   - the tests most failed: how many passed and failed, their order, and
#     the submissions named for the most common wrong answer;
#   - the submissions that need a person, and for which part;
#   - the scores' medians, quartiles and full points, from the gradebook.
# Each of these checks is shown to fail on a copy with one count, link or
# name changed.
# Sourced by tests/suites/grader.sh, which grades the self-test class once
# and calls check_class_page on it, and by tests/suites/class_page.sh
# (regrades and small classes), after tests/lib/checks.sh and pages.sh.
tab=$(printf '\t')

# ---- what the results files say, read here -----------------------------------
# A CSV line into F[1..n] (Q[k]: the field was quoted), as RFC 4180 has it.
csv_awk='
function parse(line,   i, c, f, q, n) {
    n = 0; f = ""; q = 0; Q[1] = 0
    for (i = 1; i <= length(line); i++) {
        c = substr(line, i, 1)
        if (q && c == "\"" && substr(line, i + 1, 1) == "\"") { f = f c; i++ }
        else if (q && c == "\"") q = 0
        else if (q) f = f c
        else if (c == "\"") { q = 1; Q[n + 1] = 1 }
        else if (c == ",") { F[++n] = unx(f); f = ""; Q[n + 1] = 0 }
        else f = f c
    }
    F[++n] = unx(f)
    return n
}
function unx(s,   out, i) {  # the kit writes control bytes and the backslash as \xHH
    out = ""
    while ((i = index(s, "\\x")) > 0) { out = out substr(s, 1, i - 1) chr[toupper(substr(s, i + 2, 2))]; s = substr(s, i + 4) }
    return out s
}
function unguard(k) {     # the apostrophe the kit writes before a formula
    if (Q[k] && F[k] ~ /^\047[-=+@\t\r]/) F[k] = substr(F[k], 2)
    return F[k]
}
BEGIN { for (i = 1; i < 256; i++) chr[sprintf("%02X", i)] = sprintf("%c", i) }
function unpercent(s,   out, i) {
    out = ""
    while ((i = index(s, "%")) > 0) { out = out substr(s, 1, i - 1) chr[toupper(substr(s, i + 1, 2))]; s = substr(s, i + 3) }
    return out s
}
function esc(s) {         # a name as the page writes it (markup.h, mk_text)
    gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); gsub(/>/, "\\&gt;", s)
    gsub(/"/, "\\&quot;", s); gsub(/\047/, "\\&#39;", s)
    gsub("[\001-\010\013-\037\177]", "\357\277\275", s)
    return s
}
function subname(file,   n) { n = file; sub(/.*\//, "", n); sub(/\.json$/, "", n); return n }'

# json_causes JSON...: "part TAB key TAB name" for each cause in each
# results file's extra_data, sorted.
json_causes() {
    awk "$csv_awk"'
        FNR == 1 { name = subname(FILENAME); inside = 0 }
        /^    "causes": \{$/ { inside = 1; next }
        inside && /^    \}/ { inside = 0 }
        inside && /^      "/ {
            part = $0; sub(/^ *"/, "", part); sub(/".*/, "", part)
            keys = $0; sub(/^[^:]*: "/, "", keys); sub(/",?$/, "", keys)
            n = split(keys, k, " ")
            for (i = 1; i <= n; i++) printf "%s\t%s\t%s\n", part, k[i], name
        }' "$@" | sort
}
# csv_causes CSV: the same from causes.csv (its names %20 and %25 read
# back), and a line "count ..." for a row whose count is not its names'.
csv_causes() {
    awk "$csv_awk"'
        NR == 1 { if ($0 != "part,cause,text,count,submissions") print "header " $0; next }
        {
            if (parse($0) != 5) { print "fields " $0; next }
            n = split(unguard(5), names, " ")
            if (F[4] != n) print "count " F[1] " " F[2] " " F[4] " for " n " names"
            for (i = 1; i <= n; i++) printf "%s\t%s\t%s\n", F[1], F[2], unpercent(names[i])
        }' "$1" | sort
}
# page_causes PAGE: the same from the page's table of causes (each name
# read from its link), and a line for a count that is not the number of
# links, or a name not written as the page escapes it.
page_causes() {
    awk "$csv_awk"'
        function attr(s, a,   v) { v = s; if (!sub(".*" a "=\"", "", v)) return ""; sub(/".*/, "", v); return v }
        /<tr class="cause"/ {
            part = attr($0, "data-part"); key = attr($0, "data-cause"); count = attr($0, "data-count")
            shown = $0; sub(/^[^>]*><td class="num">/, "", shown); sub(/<.*/, "", shown)
            s = $0; n = 0
            while (match(s, /<a href="[^"]*">[^<]*<\/a>/)) {
                a = substr(s, RSTART, RLENGTH); s = substr(s, RSTART + RLENGTH)
                href = a; sub(/^<a href="/, "", href); sub(/".*/, "", href)
                text = a; sub(/^[^>]*>/, "", text); sub(/<\/a>$/, "", text)
                name = unpercent(href); sub(/\.html$/, "", name)
                if (text != esc(name)) print "name " part " " key ": " text " links to " href
                printf "%s\t%s\t%s\n", part, key, name; n++
            }
            if (count != n || shown != n) print "count " part " " key " " count " " shown " for " n " links"
        }' "$1" | sort
}

# The handout's tables of mistakes ("what went wrong starts"), read here:
# each cause row says it is listed exactly when its sentence begins with
# one of the backquoted starts of its part's handout.
handout_starts() {   # handout_starts: "part TAB start" of every handout
    for md in handouts/part*.md; do
        part=${md#handouts/part}
        part=${part%%_*}
        awk -v part="$part" '/^\|/ && /what went wrong starts/ { t = 1; next }
            !/^\|/ { t = 0 }
            t && !/^\|---/ { n = split($0, c, "|"); s = c[n - 1]
                while (match(s, /`[^`]*`/)) { printf "%s\t%s\n", part, substr(s, RSTART + 1, RLENGTH - 2); s = substr(s, RSTART + RLENGTH) } }' "$md"
    done
}

# ---- the tests most failed ------------------------------------------------------
# json_tests JSON...: "T TAB test TAB built TAB failed" for every test, over
# the submissions whose file of its part built (its results' output does
# not say "Part P: ..., so none of its tests could run"), and "F TAB test
# TAB name" for each of them that failed it.
json_tests() {
    awk "$csv_awk"'
        FNR == 1 { name = subname(FILENAME); split("", broken) }
        /^  "output": / {
            s = $0
            while (match(s, /u000aPart [0-9ab]+: [^\\]*, so none of its tests could run:/)) {
                p = substr(s, RSTART + 10, RLENGTH); sub(/:.*/, "", p); broken[p] = 1
                s = substr(s, RSTART + RLENGTH)
            }
        }
        /^      "name": "/ { t = $0; sub(/^      "name": "/, "", t); sub(/",$/, "", t); gsub(/\\"/, "\"", t); gsub(/\\\\/, "\\", t)
                             p = t; sub(/^Part /, "", p); sub(/:.*/, "", p) }
        /^      "status": "/ && !(p in broken) { built[t]++; if ($0 ~ /failed/) { failedt[t]++; printf "F\t%s\t%s\n", t, name } }
        END { for (t in built) printf "T\t%s\t%d\t%d\n", t, built[t], failedt[t] + 0 }' "$@" | sort
}
# page_tests PAGE: "test TAB built TAB failed TAB passed-shown TAB built-shown"
# per article, in the page's order, then "C TAB test TAB name" for each
# submission named for its most common wrong answer.
page_tests() {
    awk "$csv_awk"'
        /<article class="test" id="most-/ { b = $0; sub(/.*data-built="/, "", b); sub(/".*/, "", b)
                                            f = $0; sub(/.*data-failed="/, "", f); sub(/".*/, "", f); next }
        /^<h4>/ && b != "" { t = $0; sub(/^<h4>/, "", t); sub(/<span.*|<\/h4>.*/, "", t)
            gsub(/&lt;/, "<", t); gsub(/&gt;/, ">", t); gsub(/&quot;/, "\"", t); gsub(/&#39;/, "\047", t); gsub(/&amp;/, "\\&", t) }
        /^<p>Passed by <strong>/ && b != "" { s = $0; sub(/^<p>Passed by <strong>/, "", s); split(s, w, " ")
            printf "%s\t%s\t%s\t%s\t%s\n", t, b, f, w[1], w[3] }
        /^<p>The |^<p>No two / && b != "" { s = $0
            while (match(s, /<a href="[^"]*">/)) { h = substr(s, RSTART + 9, RLENGTH - 11); s = substr(s, RSTART + RLENGTH)
                h = unpercent(h); sub(/\.html$/, "", h); printf "C\t%s\t%s\n", t, h } }
        /^<\/article>/ { b = "" }' "$1"
}
tests_agree() {   # tests_agree PAGE-TESTS: each listed test's counts are the results files'
    awk -F'\t' 'FNR == NR { if ($1 == "T") { built[$2] = $3; failed[$2] = $4 } else fails[$2 "\t" $3] = 1; next }
        $1 == "C" { if (!(($2 "\t" $3) in fails)) { print "named for a wrong answer, but passed: " $3 " in " $2; bad = 1 } next }
        {   n++
            if (!($1 in built) || built[$1] != $2 || failed[$1] != $3 || $4 != $2 - $3 || $5 != $2 "</strong>") {
                print "counts: " $0 " (want built " built[$1] ", failed " failed[$1] ")"; bad = 1 }
            if (n > 1 && $3 + 0 > last) { print "order: " $1; bad = 1 }
            last = $3 + 0; listed[$1] = 1
        }
        END {   # every test failed by more than the last one listed is listed
            for (t in failed) if (failed[t] > last && !(t in listed)) { print "missing: " t " (" failed[t] ")"; bad = 1 }
            exit bad || n == 0 }' "$tmp/tests.want" "$1"
}

# ---- the submissions that need a person ---------------------------------------------
# json_people GRADEBOOK JSON...: "what TAB part TAB name" for each, from
# the gradebook's status and the results' output: a part that did not
# build, or that the grader did not compile (refused: ..., missing: ...),
# and tests that did not finish in time.
json_people() {
    awk "$csv_awk"'
        FNR == NR { if (FNR > 1) { n = parse($0); name = unguard(1)
                        if (F[n] == "no stage file") { print "no stage file\t-\t" name; empty[name] = 1 }
                        if (F[n] ~ /^grader error/) print "grader error\t-\t" name }
                    next }
        FNR == 1 { name = subname(FILENAME) }
        name in empty { next }
        /^  "output": / { s = $0
            while (match(s, /u000aPart [0-9ab]+: [^\\]*, so none of its tests could run:(\\u000a(refused|missing):)?/)) {
                m = substr(s, RSTART, RLENGTH); s = substr(s, RSTART + RLENGTH)
                p = m; sub(/^u000aPart /, "", p); sub(/:.*/, "", p)
                what = m ~ /missing:$/ ? "file missing" : m ~ /refused:$/ ? "refused" : m ~ /did not build/ ? "did not build" : "refused"
                print what "\t" p "\t" name
            } }
        /^      "name": "Part / { p = $0; sub(/^      "name": "Part /, "", p); sub(/:.*/, "", p) }
        /^      "output": .*did not finish within/ { late[p "\t" name] = 1 }
        END { for (k in late) print "out of time\t" k }' "$@" | sort
}
page_people() {
    awk "$csv_awk"'/<tr class="person"/ {
            what = $0; sub(/.*data-need="/, "", what); sub(/".*/, "", what)
            name = $0; sub(/^[^>]*><td><a href="/, "", name); sub(/".*/, "", name); name = unpercent(name); sub(/\.html$/, "", name)
            part = $0; sub(/.*<\/td><td>[^<]*<\/td><td>/, "", part)
            if (part ~ /^Part [0-9ab]+: /) { sub(/^Part /, "", part); sub(/:.*/, "", part) } else part = "-"
            print what "\t" part "\t" name }' "$1" | sort
}

# ---- the scores ----------------------------------------------------------------------
# From the gradebook and the weights: each histogram's count, median,
# quartiles (interpolated between ranks: the (n-1)q-th of the sorted
# points) and full points, and the class's full core marks.
scores_agree() {   # scores_agree PAGE
    awk "$csv_awk"'
        FILENAME ~ /\.conf$/ { if ($1 == "part") { core["part" $2] = $4; hp[$2] = $6 }
                               if ($1 == "parts") for (k = 2; k <= NF; k++) graded[$k] = 1
                               next }
        FILENAME ~ /\.csv$/ && FNR == 1 { for (k in graded) hard += hp[k] }
        FILENAME ~ /\.csv$/ && FNR == 1 { n = parse($0); for (k = 1; k <= n; k++) col[F[k]] = k; next }
        FILENAME ~ /\.csv$/ { n = parse($0); rows++; if (F[col["total"]] == "") next
            full = 1
            for (c in col) if (c ~ /^part|^hard$/) { v[c, ++cnt[c]] = F[col[c]] + 0; if (c in core && F[col[c]] + 0 < core[c]) full = 0 }
            fullcore += full; next }
        /data-submissions=/ { s = $0; sub(/.*data-submissions="/, "", s); sub(/".*/, "", s)
            f = $0; sub(/.*data-full="/, "", f); sub(/".*/, "", f)
            if (s != rows || f != fullcore) { print "glance: " s " " f " want " rows " " fullcore; bad = 1 } }
        /<tr data-scores="/ { id = $0; sub(/.*data-scores="/, "", id); sub(/".*/, "", id)
            c = id == "hard" ? "hard" : "part" id; max = id == "hard" ? hard : core[c]; m = cnt[c]
            for (i = 1; i <= m; i++) x[i] = v[c, i]
            for (i = 2; i <= m; i++) for (j = i; j > 1 && x[j - 1] > x[j]; j--) { t = x[j]; x[j] = x[j - 1]; x[j - 1] = t }
            nf = 0; for (i = 1; i <= m; i++) nf += x[i] >= max
            split("n median q1 q3 full", names, " ")
            want["n"] = m; want["median"] = q(x, m, 0.5); want["q1"] = q(x, m, 0.25); want["q3"] = q(x, m, 0.75); want["full"] = nf
            for (k = 1; k <= 5; k++) { a = $0; sub(".*data-" names[k] "=\"", "", a); sub(/".*/, "", a)
                if ((a - want[names[k]]) ^ 2 > 1e-12) { print id " " names[k] ": " a " want " want[names[k]]; bad = 1 } }
            seen++ }
        function q(x, m, p,   h, lo) { h = (m - 1) * p; lo = int(h); return lo >= m - 1 ? x[m] : x[lo + 1] + (h - lo) * (x[lo + 2] - x[lo + 1]) }
        END { exit bad || seen != 7 }' "$conf" "$out/gradebook.csv" "$1"
}

seen() {   # seen WHAT COMMAND...: one check that COMMAND fails
    what=$1
    shift
    if "$@" >/dev/null 2>&1; then fail "$what is not seen"; else pass; fi
}

# check_class_page OUT CONF LOG CLASS: the checks above on the class in
# the folder CLASS that grade --all --weights CONF wrote to OUT, its output
# in LOG.  The class
# must hold submissions named p1-degrees-to-tan and p1-float, and the
# names in $hostile1 and "=50% <i>".
check_class_page() {
    out=$1 conf=$2 log=$3 class=$4
    page=$out/index.html
    csv=$out/causes.csv
    check "it says where the class page is" grep -q "^the class at a glance: $out/index.html" "$log"
    check "the class page and causes.csv are written" test -f "$page" -a -f "$csv"
    check "OUT, made by grade --all, is its owner's alone ($(ls -ld "$out" | cut -c1-10))" \
        sh -c "ls -ld '$out' | grep -q '^drwx------'"
    for f in "$page" "$csv" "$out/gradebook.csv"; do
        check "${f##*/} is readable by its owner alone ($(ls -l "$f" | cut -c1-10))" \
            sh -c "ls -l '$f' | grep -q '^-rw-------'"
    done
    check_output "the page is safe (links included: each to a file beside it)" page_safe "$page" ||
        sed 's/^/    | /' "$log" | head -n 20
    json_causes "$out"/*.json >"$tmp/causes.want"
    check "the self-test class has causes to count ($(wc -l <"$tmp/causes.want" | tr -d ' ') in all)" \
        [ "$(wc -l <"$tmp/causes.want")" -ge 40 ]
    csv_causes "$csv" >"$tmp/causes.csv.got"
    check_output "causes.csv: each cause of each results file, under exactly its submissions, counted right" \
        diff "$tmp/causes.want" "$tmp/causes.csv.got"
    page_causes "$page" >"$tmp/causes.page.got"
    check_output "the page's causes: the same, each name linked to its page and escaped" \
        diff "$tmp/causes.want" "$tmp/causes.page.got"
    check "causes.csv's text is each cause's sentence, as the results file words it" \
        sh -c "grep -q '^1,degrees-as-radians,\"tan was given the angle in degrees: ' '$csv'"
    check "a hostile name is in causes.csv as it is (quoted, its space written %20, its control byte \\x01)" \
        grep -qF -e "$(printf '%s' "$hostile1" | sed 's/"/""/g; s/ /%20/g' | tr '\001' '@' | sed 's/@/\\x01/')" "$csv"
    check "a name that starts like a formula is in causes.csv after an apostrophe, its percent sign written %25" \
        grep -qF -e "\"'=50%25%20<i> " "$csv"

    # Most common first in each part: a row's count is at most the one above.
    check "the page's causes are most common first within each part" \
        awk -F'"' '/<tr class="cause"/ { if ($4 == part && $8 + 0 > last) bad = 1; part = $4; last = $8 + 0 }
                   END { exit bad }' "$page"
    handout_starts >"$tmp/starts"
    check "the handouts list mistakes to match ($(wc -l <"$tmp/starts" | tr -d ' '))" [ "$(wc -l <"$tmp/starts")" -ge 20 ]
    check "a cause says it is one of the handout's listed mistakes exactly when its sentence begins like one" \
        awk -F'\t' 'FNR == NR { s[++n] = $2; p[n] = $1; next }
            /<tr class="cause"/ {
                part = $0; sub(/.*data-part="/, "", part); sub(/".*/, "", part)
                said = $0; sub(/.*<p class="said">/, "", said); sub(/<\/p>.*/, "", said)
                gsub(/&lt;/, "<", said); gsub(/&gt;/, ">", said); gsub(/&quot;/, "\"", said); gsub(/&#39;/, "\047", said); gsub(/&amp;/, "\\&", said)
                listed = 0
                for (i = 1; i <= n; i++) if (p[i] == part && index(said, s[i]) == 1) listed = 1
                if (listed != (index($0, "One of the handout") > 0)) { print "handout: " part ": " said; bad = 1 }
                listed_any += listed
            }
            END { exit bad || !listed_any }' "$tmp/starts" "$page"

    json_tests "$out"/*.json >"$tmp/tests.want"
    page_tests "$page" >"$tmp/tests.page"
    check "the page lists the tests most failed (10)" [ "$(grep -cv "^C$tab" "$tmp/tests.page")" -eq 10 ]
    check_output "the tests most failed: built, failed and passed as the results files say, most failed first" \
        tests_agree "$tmp/tests.page"
    check "each test most failed has the figure of a wrong answer" \
        [ "$(grep -c '^<figure class="case">' "$page")" -ge 10 ]

    json_people "$out/gradebook.csv" "$out"/*.json >"$tmp/people.want"
    page_people "$page" >"$tmp/people.got"
    kinds=0
    for w in 'no stage file' 'did not build' refused 'file missing' 'out of time'; do
        grep -q "^$w$tab" "$tmp/people.want" && kinds=$((kinds + 1))
    done
    check "the class has submissions that need a person of each kind but a grader error ($kinds of 5)" [ "$kinds" -eq 5 ]
    check_output "the submissions that need a person: exactly those the results files say, for the part they say" \
        diff "$tmp/people.want" "$tmp/people.got"

    # The files handed to the compiler: the graded parts' stage files in
    # the class's folders, less those the grader refused.
    handed=0
    for p in $(sed -n 's/^parts //p' "$conf"); do
        handed=$((handed + $(find "$class" -mindepth 2 -maxdepth 2 -name "part${p}_*.c" | wc -l)))
    done
    refused=$(grep -c "^refused$tab" "$tmp/people.want")
    check "the cost: $((handed - refused)) stage files compiled ($handed in the class's folders, $refused refused)" \
        grep -q "<tr><td>compiled</td><td class=\"num\">$((handed - refused))</td>" "$page"

    check_output "the scores: each part's and the hard cases' median, quartiles and full points, and the class's full core marks, as the gradebook has them" \
        scores_agree "$page"

    # ---- the checks fail where the page or causes.csv is wrong ------------------------------
    # One count, one link, one name changed, each in a copy: the check that
    # reads it must see it.
    awk "$csv_awk"'NR == 2 { n = parse($0); F[4]++; line = ""    # every field written quoted
            for (k = 1; k <= n; k++) { f = F[k]; gsub(/"/, "\"\"", f); line = line (k > 1 ? "," : "") "\"" f "\"" }
            $0 = line }
        { print }' "$csv" >"$tmp/bad-count.csv"
    csv_causes "$tmp/bad-count.csv" >"$tmp/bad.got"
    check "a count changed in causes.csv is seen" grep -q '^count 1 ' "$tmp/bad.got"
    sed 's/href="p1-degrees-to-tan.html">p1-degrees-to-tan/href="p1-float.html">p1-degrees-to-tan/' \
        "$page" >"$tmp/bad-link.html"
    page_causes "$tmp/bad-link.html" >"$tmp/bad.got"
    check "a link to another submission's page is seen" sh -c "! cmp -s '$tmp/causes.want' '$tmp/bad.got'"
    sed 's/href="p1-degrees-to-tan.html">p1-degrees-to-tan</href="p1-degrees-to-tan.html">p1-degrees-to-tax</' \
        "$page" >"$tmp/bad-name.html"
    page_causes "$tmp/bad-name.html" >"$tmp/bad.got"
    check "a name written wrong is seen" grep -q '^name 1 degrees-as-radians: p1-degrees-to-tax ' "$tmp/bad.got"
    sed 's/\(data-cause="degrees-as-radians" data-count="\)\([0-9]*\)"><td class="num">[0-9]*</\1\2"><td class="num">99</' \
        "$page" >"$tmp/bad-shown.html"
    page_causes "$tmp/bad-shown.html" >"$tmp/bad.got"
    check "a count shown wrong on the page is seen" grep -q '^count 1 degrees-as-radians [0-9]* 99 ' "$tmp/bad.got"
    awk '/data-failed="/ && !done { sub(/data-failed="[0-9]*"/, "data-failed=\"0\""); done = 1 } { print }' \
        "$page" >"$tmp/bad-tests.html"
    page_tests "$tmp/bad-tests.html" >"$tmp/bad.tests"
    seen "a test's count of failures changed" tests_agree "$tmp/bad.tests"
    sed 's/data-median="[0-9.]*"/data-median="1"/' "$page" >"$tmp/bad-median.html"
    seen "a median changed" scores_agree "$tmp/bad-median.html"
    grep -v 'data-need="out of time"' "$page" >"$tmp/bad-people.html"
    page_people "$tmp/bad-people.html" >"$tmp/bad.got"
    check "a submission left out of those that need a person is seen" sh -c "! cmp -s '$tmp/people.want' '$tmp/bad.got'"
}
