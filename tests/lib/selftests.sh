#!/bin/sh
# selftests.sh - writes the grader's self-test submissions, a folder each,
# as the suites grade them: the folders of tests/selftest copied whole, and
# one folder (expect and one stage file) for each record of the table
# tests/selftest/mistakes, its stage file made from a base by the record's
# changes (tests/selftest/README.md describes the table).
# Usage: sh tests/lib/selftests.sh DIR [KIT]
#   DIR  where to write them (replaced if it exists)
#   KIT  the kit whose tests/selftest and solutions/ to read (default: the
#        one this script is in)
# A change whose lines are not in its base exactly once, and any line the
# table does not allow, stop it with "FILE:LINE: NAME: what is wrong" for
# each, and exit 1 with nothing written: a later edit of solutions/ or of
# a base that undoes a mistake is caught, not graded as the base.
set -u
if [ $# -lt 1 ] || [ $# -gt 2 ] || [ -z "$1" ]; then
    echo "usage: sh tests/lib/selftests.sh DIR [KIT]" >&2
    exit 2
fi
out=$1
if [ $# -eq 2 ]; then
    kit=$2
    where=$kit/tests/selftest/mistakes
else
    kit=$(dirname "$0")/../..
    where=tests/selftest/mistakes
fi
kit=$(cd "$kit" 2>/dev/null && pwd) || { echo "selftests.sh: no folder $kit" >&2; exit 2; }
table=$kit/tests/selftest/mistakes
if [ ! -f "$table" ]; then
    echo "selftests.sh: no table $table" >&2
    exit 2
fi
# Written beside DIR, then moved there.
new=$out.new.$$
rm -rf "$new"
mkdir -p "$new" || exit 2
trap 'rm -rf "$new"' EXIT
# The folders, whole.
set --
for dir in "$kit"/tests/selftest/*/; do
    [ -d "$dir" ] && set -- "$@" "${dir%/}"
done
[ $# -eq 0 ] || cp -R "$@" "$new/" || exit 2
# The records, written from inside the new folder.
(cd "$new" && awk -v ref="$kit/solutions" -v where="$where" '
function err(line, text) {
    printf "%s:%d: %s\n", where, line, text
    errors++
}
# The end of a hunk: its lines in order, "-" and "=" the old, "=" and "+" the new.
function end_hunk(   h) {    # portable: awk
    if (nh_lines > 0) {
        nhunks[rec]++
        h = rec SUBSEP nhunks[rec]
        hunk_line[h] = hunk_start
        hunk_text[h] = hunk_body
        hunk_n[h] = nh_lines
    }
    nh_lines = 0
    hunk_body = ""
}
function end_block() {    # portable: awk
    end_hunk()
    if (in_header)
        err(header_line, rec ": the comment is not closed (*/)")
    in_header = 0
    rec = ""
    base = ""
    skipping = 0
}
BEGIN {
    keys = " core part hard output nooutput cause nocause "
    nrec = 0
}
/^[ \t]*$/ { end_block(); next }
/^base / {
    end_block()
    if (NF != 2 || $2 !~ /^part[1-5][ab]?_[a-z_]+\.c$/) { err(NR, "want: base FILE (a stage file)"); next }
    base = $2
    if (base in base_n) { err(NR, "a second base " base); base = "" ; next }
    base_n[base] = 0
    next
}
/^test / {
    end_block()
    name = $2
    if (!(NF == 3 || (NF == 5 && $4 == "from" && $5 == "reference")) ||
        $3 !~ /^part[1-5][ab]?_[a-z_]+\.c$/)
        bad = "want: test NAME FILE [from reference]"
    else if (name !~ /^[a-z0-9][a-z0-9.-]*$/)
        bad = name ": a name of letters, digits, - and . only"
    else if (name in rec_line)
        bad = name ": a second record of that name (the first at line " rec_line[name] ")"
    else
        bad = ""
    if (bad != "") {
        err(NR, bad)
        skipping = 1
        next
    }
    rec = name
    order[++nrec] = rec
    rec_line[rec] = NR
    rec_file[rec] = $3
    rec_base[rec] = (NF == 5) ? "reference" : "plain"
    nhunks[rec] = 0
    next
}
base != "" {
    if (substr($0, 1, 1) != "|") { err(NR, "a line of base " base " starts with |"); next }
    base_text[base, ++base_n[base]] = substr($0, 2)
    next
}
rec == "" {
    if (!skipping && substr($0, 1, 1) != "#")
        err(NR, "a line outside a record: start one with test NAME FILE, or a comment with #")
    next
}
in_header {
    header[rec] = header[rec] "\n" $0
    if (index($0, "*/"))
        in_header = 0
    next
}
/^\/\*/ {
    if (rec in header) { err(NR, rec ": a second comment"); next }
    header[rec] = $0
    header_line = NR
    in_header = index(substr($0, 3), "*/") == 0
    next
}
/^[-=+]/ {
    c = substr($0, 1, 1)
    if (nh_lines == 0) {
        hunk_start = NR
        if (c == "+") { err(NR, rec ": a line added (+) with no line to change (- or =) before it"); next }
    }
    hunk_body = hunk_body (nh_lines ? "\n" : "") $0
    nh_lines++
    next
}
/^\.\.\.$/ {
    if (nh_lines == 0) err(NR, rec ": ... between two changes, after one")
    end_hunk()
    next
}
{
    if (index(keys, " " $1 " ") == 0 && substr($0, 1, 1) != "#")
        err(NR, rec ": not an expect line (" substr(keys, 2) "or #), a comment (/*) or a change (- = + ...)")
    else
        expect[rec] = expect[rec] $0 "\n"
}
END {
    end_block()
    for (k = 1; k <= nrec; k++) {
        rec = order[k]
        file = rec_file[rec]
        # The base: the reference file or the table base, less its own
        # leading comment.
        n = 0
        if (rec_base[rec] == "reference") {
            path = ref "/" file
            if (!(path in ref_n)) {
                ref_n[path] = 0
                while ((getline line <path) > 0)
                    ref_text[path, ++ref_n[path]] = line
                close(path)
            }
            if (ref_n[path] == 0) {
                err(rec_line[rec], rec ": no reference " file " (or it is empty)")
                continue
            }
            for (i = 1; i <= ref_n[path]; i++)
                cur[++n] = ref_text[path, i]
            what = "the reference " file
        } else if (file in base_n) {
            for (i = 1; i <= base_n[file]; i++)
                cur[++n] = base_text[file, i]
            what = "the base " file
        } else {
            err(rec_line[rec], rec ": no base " file " in the table")
            continue
        }
        first = 1
        if (n > 0 && substr(cur[1], 1, 2) == "/*") {
            while (first <= n && index(cur[first], "*/") == 0)
                first++
            first++
        }
        m = 0
        for (i = first; i <= n; i++)
            text[++m] = cur[i]
        n = m
        # Each hunk: its old lines found together exactly once, then replaced.
        for (j = 1; j <= nhunks[rec]; j++) {
            h = rec SUBSEP j
            split(hunk_text[h], hl, "\n")
            no = nn = 0
            for (i = 1; i <= hunk_n[h]; i++) {
                c = substr(hl[i], 1, 1)
                s = substr(hl[i], 2)
                if (c != "+") old[++no] = s
                if (c != "-") repl[++nn] = s
            }
            found = 0
            for (i = 1; i + no - 1 <= n; i++) {
                for (q = 1; q <= no && text[i + q - 1] == old[q]; q++)
                    ;
                if (q > no) { found++; at = i }
            }
            if (found != 1) {
                lines = (no > 1) ? "the lines to change (" old[1] " ...) are" : "the line to change (" old[1] ") is"
                if (found)
                    err(hunk_line[h], rec ": " lines " in " what " " found " times: say which with a line beside (=)")
                else
                    err(hunk_line[h], rec ": " lines " not in " what)
                n = -1
                break
            }
            m = 0
            for (i = 1; i < at; i++) tmp[++m] = text[i]
            for (i = 1; i <= nn; i++) tmp[++m] = repl[i]
            for (i = at + no; i <= n; i++) tmp[++m] = text[i]
            n = m
            for (i = 1; i <= n; i++) text[i] = tmp[i]
        }
        if (n < 0)
            continue
        body[rec] = ""
        for (i = 1; i <= n; i++)
            body[rec] = body[rec] text[i] "\n"
        if (!(rec in header))
            header[rec] = "/* Self-test of the grader: " rec ". */"
        if (expect[rec] == "")
            err(rec_line[rec], rec ": no expect line")
        names = names " " rec
    }
    if (errors)
        exit 1
    if (names != "" && system("mkdir" names) != 0) {
        printf "%s: a record has the name of a folder of tests/selftest\n", where
        exit 1
    }
    for (k = 1; k <= nrec; k++) {
        rec = order[k]
        path = rec "/expect"
        printf "%s", expect[rec] >path
        close(path)
        path = rec "/" rec_file[rec]
        printf "%s\n%s", header[rec], body[rec] >path
        close(path)
    }
}' "$table" >&2) || exit 1
rm -rf "$out" && mv "$new" "$out" || exit 2
trap - EXIT
