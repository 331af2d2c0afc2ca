# browser.sh - whether a page renders in a headless browser, for the suites
# of the kit's pages.  A suite sources it after tests/lib/checks.sh:
#     . tests/lib/browser.sh
#   page_renders PAGE WHAT TMP
#       one check: PAGE (an absolute path) rendered by chromium makes a
#       screenshot of which at least 10% differs from a blank page's
#       (out/build/bin/compare measures it; TMP is a directory for the
#       screenshots).  Where no chromium is installed it says it skipped,
#       and counts nothing: the kit never needs a browser.
page_renders() {
    browser=
    for b in chromium chromium-browser google-chrome; do
        if command -v "$b" >/dev/null 2>&1; then browser=$b; break; fi
    done
    if [ -z "$browser" ]; then
        echo "   skipped: no headless browser (chromium) installed, so $2 was not rendered"
        return 0
    fi
    printf '<!DOCTYPE html>\n<html><head><title>blank</title></head><body></body></html>\n' >"$3/blank.html"
    browser_shot "file://$3/blank.html" "$3/blank.png" "$3"
    browser_shot "file://$1" "$3/page.png" "$3"
    if [ ! -s "$3/blank.png" ] || [ ! -s "$3/page.png" ]; then
        fail "$browser made no screenshot of $2"
        return 0
    fi
    differ=$(out/build/bin/compare "$3/page.png" "$3/blank.png" 2>&1 |
        sed -n 's/^ *pixels that differ: *\([0-9.]*\)%.*/\1/p')
    check "$2 renders in $browser: ${differ:-?}% of its screenshot differs from a blank page's" \
        awk -v d="${differ:-0}" 'BEGIN { exit !(d >= 10) }'
}

# browser_shot URL PNG TMP: a screenshot with a fresh profile, at most 120 s
# where timeout(1) exists; tried twice, as headless chromium now and then
# exits at start with no screenshot (seen once in make sanitize-grader).
browser_shot() {
    quiet="--disable-background-networking --disable-component-update --disable-sync"  # portable: chromium's flags
    for try in 1 2; do
        profile=$(mktemp -d "$3/profile.XXXXXX")
        within_120s "$browser" --headless --no-sandbox --disable-gpu --no-first-run $quiet \
            --user-data-dir="$profile" --hide-scrollbars --window-size=1280,1600 --screenshot="$2" "$1"
        [ -s "$2" ] && return 0
    done
}
within_120s() {
    if command -v timeout >/dev/null 2>&1; then timeout 120 "$@" >/dev/null 2>&1; else "$@" >/dev/null 2>&1; fi  # portable: guarded
}
