# pages.sh - what must hold on every page the grader writes: its pages show
# what students' code printed and students' folder names, and instructors
# open them in a browser.  A suite sources it after tests/lib/checks.sh:
#     . tests/lib/pages.sh
#   page_tags PAGE      each tag of PAGE on a line, without its < and >
#                       (the kit escapes every < of text, so each < starts
#                       a tag): `page_tags P | grep -c '^figure class="case"'`
#   page_safe PAGE...   prints each problem, "PAGE: what", and fails if any:
#                       a <script>, an on...= event attribute, a javascript:
#                       address, an id used twice, or a src or href that is
#                       not a PNG data: URI, a #id of the page or a file
#                       beside the page (its %XX read as the byte XX, as a
#                       browser does): never a scheme: or a // address; nor
#                       a style sheet that loads something (url(), @import)
#   page_normal PAGE TMP    PAGE as tests/pages/ holds it: the folder TMP
#                       written TMP, times T, a PNG's base64 "..." (page_safe
#                       checks that it is a PNG's), and no style sheet (the
#                       grader's constant, the same on every page)
page_tags() {
    LC_ALL=C awk 'BEGIN { RS = "<" } NR > 1 { gsub(/\n/, " "); sub(/>.*/, ""); print }' "$1"
}
page_safe() {
    for _page in "$@"; do
        [ -s "$_page" ] || { echo "$_page: no such page"; return 1; }
        if sed -n '/<style>/,/<\/style>/p' "$_page" | grep -qiE 'url\(|@import'; then
            echo "$_page: the style sheet loads something (url() or @import)"
            return 1
        fi
        page_tags "$_page" | LC_ALL=C awk -v page="$_page" -v dir="${_page%/*}" '
        function bad(what) { print page ": " what; n++ }
        function unpercent(s,   out, i) {
            out = ""
            while ((i = index(s, "%")) > 0) {
                out = out substr(s, 1, i - 1) chr[toupper(substr(s, i + 1, 2))]
                s = substr(s, i + 3)
            }
            return out s
        }
        BEGIN { for (i = 1; i < 256; i++) chr[sprintf("%02X", i)] = sprintf("%c", i) }
        tolower($0) ~ /^script/ { bad("a <script>") }
        / on[a-z]+ *=/ { bad("an event attribute: <" $0 ">") }
        tolower($0) ~ /javascript:/ { bad("a javascript: address: <" $0 ">") }
        match($0, / id="[^"]*"/) {
            id = substr($0, RSTART + 5, RLENGTH - 6)
            if (id in ids) bad("an id used twice: " id)
            ids[id] = 1
        }
        {
            tag = $0
            while (match(tag, / (src|href|xlink:href)="[^"]*"/)) {
                v = substr(tag, RSTART, RLENGTH)
                tag = substr(tag, RSTART + RLENGTH)
                sub(/^[^"]*"/, "", v)
                sub(/"$/, "", v)
                if (v ~ /^data:/) {
                    if (v !~ /^data:image\/png;base64,iVBORw0KGgo[A-Za-z0-9+\/]*=*$/)
                        bad("a data: URI that is not a PNG in base64: " substr(v, 1, 40))
                } else if (v ~ /^#/) {
                    frag[substr(v, 2)] = 1
                } else if (v ~ /^\/\// || v ~ /^[^\/?#]*:/ || v == "") {
                    bad("an address on the network or with a scheme: \"" v "\"")
                } else {
                    file = dir "/" unpercent(v)
                    if ((getline line <file) < 0)
                        bad("a file the page links to is missing: " v)
                    close(file)
                }
            }
        }
        END {
            for (f in frag)
                if (!(f in ids)) bad("a link to an id the page does not have: #" f)
            exit n > 0
        }' || return 1
    done
}
page_normal() {
    sed -e "s|$2|TMP|g" -e 's/(graded in [0-9.]* s)/(graded in T s)/' -e 's/"num">[0-9.]* s</"num">T s</' \
        -e 's/: [0-9.]* s a submission/: T s a submission/' -e 's|;base64,[A-Za-z0-9+/=]*|;base64,...|g' \
        -e '/^<style>$/,/^<\/style>$/{/^</!d;}' "$1"
}
