#!/bin/sh
# The grader's jail (tests/grader/jail.h) against the attacks of
# tests/attacks (its README says what each tries, and what holding it
# means): each is graded in every mode the grader runs in here, and gains
# nothing in any.  The modes: as root in the namespace jail, as root in the
# fallback (GRADE_JAIL=fallback, as where the system refuses namespaces),
# and as an ordinary user (nobody) in the namespace jail, where the system
# lets users make user namespaces; a mode the system cannot give is said to
# be skipped.  As root the grader runs from a copy of the kit in a private
# folder (0700), as in a container; as nobody, from one it may read.
set -u
grade_built=${GRADE:-out/build/bin/grade}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rtjail.XXXXXX") || { echo "0 passed, 1 failed"; exit 1; }
# A course's shared folder, open to all, in a folder that is not: three
# levels below /, where the fallback's sweep must find it.
course=$(mktemp -d /tmp/rtcourse.XXXXXX) || { echo "0 passed, 1 failed"; exit 1; }
trap '[ -n "${KEEP_TMP:-}" ] || rm -rf "$tmp" "$course"' EXIT
chmod 755 "$tmp" "$course"
shared=$course/shared
mkdir -m 1777 "$shared" && chmod 1777 "$shared"
. tests/lib/checks.sh
need_built "$grade_built"

# What an attack must not read, marked as this run's alone (other suites
# running beside this one have the kit's files in folders anyone may read,
# which the fallback's user may read too): the copies' seed, and a line of
# their reference.
mark=$$-$(date +%s)
seed_line="seed     7$$"
reference_line="REFERENCE-MARKER-$mark"
# copy_kit DIR: the grader and what it reads (not the kit's own tests' builds).
copy_kit() {
    mkdir -p "$1/out/build"
    cp -R Makefile labs solutions tests "$1/" &&
        cp -R out/build/grader out/build/bin "$1/out/build/" &&
        { [ ! -d out/build/report ] || cp -R out/build/report "$1/out/build/"; } &&
        sed "s/^seed .*/$seed_line/" tests/weights.conf >"$1/tests/weights.conf" &&
        echo "/* $reference_line */" >>"$1/solutions/part1_image_plane.c"
    [ -z "${GRADE:-}" ] || cp "$GRADE" "$1/out/build/bin/grade"     # make sanitize-grader's
}
mkdir -m 700 "$tmp/private"
copy_kit "$tmp/private/kit" || { fail "cannot copy the kit"; finish; }
copy_kit "$tmp/open-kit" && chmod -R a+rX "$tmp/open-kit"

# A file only root may read, which plant-links points the build at.
secret=$tmp/private/secret
echo "ROOT-ONLY-SECRET-$$-e41b" >"$secret"
chmod 600 "$secret"

# attacks KIT DIR: the attacks as submissions in DIR, their placeholders
# filled in for the kit at KIT; readable by all (the grader copies them).
attacks() {
    mkdir -p "$2"
    for a in tests/attacks/*/; do
        a=${a%/}
        name=${a##*/}
        mkdir -p "$2/$name"
        for f in "$a"/*.c; do
            sed -e "s|@KIT@|$1|g" -e "s|@SECRET@|$secret|g" -e "s|@SHARED@|$shared|g" "$f" \
                >"$2/$name/${f##*/}"
        done
    done
    # Beside a core part of their own, the reference's other core parts.
    for name in plant-links render-hog kill-all; do
        for f in solutions/part1_image_plane.c solutions/part2_pixel_coordinates.c \
                 solutions/part3a_sphere_intersect.c solutions/part3b_ray_color.c; do
            [ -f "$2/$name/${f##*/}" ] || cp "$f" "$2/$name/"
        done
    done
    mkdir -p "$2/class-leak" "$2/class-read" "$2/class-deep/plain"
    mv "$2/record-answers" "$2/class-leak/a-record"
    mv "$2/look-up-answers" "$2/class-leak/b-look-up"
    mv "$2/read-kit" "$2/class-read/a-read-kit"
    mv "$2/classmate" "$2/class-read/b-classmate"
    mv "$2/deep-folder" "$2/class-deep/deep-folder"
    cp solutions/part1_image_plane.c "$2/class-deep/plain/"
    chmod -R a+rX "$2"
}

# left_behind: names an attack leaves where anyone may write, still there.
left_behind() {
    for place in /tmp /var/tmp /dev/shm "$shared"; do
        ls -d "$place"/rtleak_* "$place"/rtseen_* "$place"/rtdeep 2>/dev/null
    done
    if [ -r /proc/sysvipc/shm ]; then          # portable: Linux only, guarded
        awk '$1 == 1381255756 { print "shared memory segment " $2 }' /proc/sysvipc/shm   # portable: as above
    fi
}

# run_attacks MODE KIT AS ENV: every attack, graded by the kit's grader at
# KIT, as AS (root: the user running this; else the user to become), with
# the environment ENV (GRADE_JAIL=...).
run_attacks() {
    mode=$1 kit=$2 as=$3 env=$4
    out=$tmp/out-$mode
    mkdir -p "$out"
    chmod 777 "$out"
    subs=$tmp/subs-$mode
    attacks "$kit" "$subs"
    sed 's/^parts .*/parts 1/' "$kit/tests/weights.conf" >"$out/part1.conf"
    sed 's/^parts .*/parts 1 2/' "$kit/tests/weights.conf" >"$out/parts12.conf"
    printf 'part-time 5\n' >>"$out/part1-short.conf"
    cat "$out/part1.conf" >>"$out/part1-short.conf"
    chmod 644 "$out"/*.conf
    # as_grader ARGS...: the grader of KIT, run from KIT, as AS.
    as_grader() {
        if [ "$as" = root ]; then
            (cd "$kit" && env $env out/build/bin/grade "$@")
        else
            (cd "$kit" && setpriv --reuid="$as" --regid="$(id -g "$as")" --clear-groups \
                env $env out/build/bin/grade "$@")    # portable: guarded by the caller
        fi
    }
    echo "   $mode: $(as_grader --jail)"

    # Answers left behind for the next run, and for the next submission.
    as_grader --all "$subs/class-leak" --out "$out/leak" --weights "$out/part1.conf" --jobs 1 \
        >"$out/leak.out" 2>&1
    check_has "$mode: answers recorded by one submission do not reach the next: it scores 0" \
        "$out/leak/gradebook.csv" '^a-record,20,' '^b-look-up,0,'
    as_grader --submission "$subs/class-leak/b-look-up" --weights "$out/part1.conf" --summary \
        >"$out/look-up.out" 2>&1
    check "$mode: ... nor the same submission graded again" grep -q '^summary 0 ' "$out/look-up.out"

    # Hidden inputs named where a visible test's run alone may find them.
    as_grader --submission "$subs/leak-hidden" --part 1 --results "$out/hidden.json" --quiet >/dev/null 2>&1
    names=$(grep -o 'seen rtseen_[0-9a-fx.p+_-]*' "$out/hidden.json" | sort -u)
    check "$mode: a visible test's output names its own input alone (seen: $(echo "$names" | wc -l | tr -d ' '))" \
        sh -c "[ '$names' = 'seen rtseen_0x1.68p+6_0x1p+1_0x1p+0' ]"

    # Links to a file only root may read, for the report page to copy.
    as_grader --submission "$subs/plant-links" --results "$out/links.json" --report-file "$out/links.html" \
        --summary >"$out/links.out" 2>&1
    check "$mode: links planted in the build: the file they name appears nowhere" \
        sh -c "! grep -rq 'ROOT-ONLY-SECRET' '$out/links.json' '$out/links.html' '$out/links.out'"
    check "$mode: ... and the submission keeps full marks, its picture drawn" \
        sh -c "grep -q '^summary 20 20 30 30 ' '$out/links.out' && grep -q 'data:image/png' '$out/links.html'"

    # The kit and a classmate, read and printed on a failed test.
    as_grader --all "$subs/class-read" --out "$out/read" --weights "$out/part1.conf" --jobs 1 \
        >"$out/read.out" 2>&1
    check "$mode: the reference, the hidden tests' seed and a classmate's file appear nowhere in its results" \
        sh -c "[ -s '$out/read/a-read-kit.json' ] && ! grep -q -e '$seed_line' -e '$reference_line' -e CLASSMATE-WORK-7f3a9c '$out/read/a-read-kit.json'"

    # A folder 5,000 deep.
    as_grader --all "$subs/class-deep" --out "$out/deep" --weights "$out/part1.conf" --jobs 1 >"$out/deep.out" 2>&1
    check "$mode: a folder 5,000 deep: its results written, its row graded, and the next submission graded" \
        sh -c "grep -q -e '^deep-folder,[0-9.]*,[0-9.]*,[0-9.]*,full marks\$' -e '^deep-folder,[0-9.]*,[0-9.]*,[0-9.]*,points lost\$' '$out/deep/gradebook.csv' &&
               grep -q '\"tests\": \\[\$' '$out/deep/deep-folder.json' &&
               grep -q '^plain,20,' '$out/deep/gradebook.csv' && [ -s '$out/deep/plain.json' ]"

    # Every test sleeps just under its limit.
    start=$(date +%s)
    as_grader --submission "$subs/sleepy" --weights "$out/part1-short.conf" --results "$out/sleepy.json" \
        --quiet >/dev/null 2>&1
    took=$(( $(date +%s) - start ))
    check "$mode: tests that each sleep nearly 2 s stop at the part's time (5 s here): ${took} s in all" \
        sh -c "[ $took -lt 15 ] && grep -q \"not run: this part's tests took 5 s in all\" '$out/sleepy.json'"

    # The report page's render with a test's memory.
    as_grader --submission "$subs/render-hog" --part 3b --report-file "$out/hog.html" --quiet >/dev/null 2>&1
    check "$mode: the report page's render has a test's memory (300 MB is refused): no picture" \
        sh -c "[ -s '$out/hog.html' ] && grep -q -e 'so there is no picture' -e 'so there is none' '$out/hog.html'"

    # The seed's file read by the assembler.
    as_grader --submission "$subs/incbin-split" --part 1 --results "$out/split.json" --quiet >/dev/null 2>&1
    check "$mode: .incbin split in two strings is refused by the scan" \
        grep -q "refused: the file uses the assembler.s .incbin" "$out/split.json"
    as_grader --submission "$subs/incbin-macro" --part 1 --results "$out/macro.json" --quiet >/dev/null 2>&1
    check "$mode: .incbin made by a macro cannot read the seed's file: it does not build, and the seed appears nowhere" \
        sh -c "grep -q 'did not build' '$out/macro.json' && ! grep -q '$seed_line' '$out/macro.json'"

    # Every input sent over the network.
    as_grader --submission "$subs/send-inputs" --part 1 --summary --quiet >"$out/send.out" 2>&1
    check "$mode: no run can send its inputs over the network: Part 1 keeps full marks" \
        grep -q '^summary 20 ' "$out/send.out"

    # SIGKILL to every process it may signal.
    as_grader --submission "$subs/kill-all" --weights "$out/parts12.conf" --summary >"$out/kill.out" 2>&1
    status=$?
    check "$mode: kill(-1), kill(1) and its parent: grading goes on, every part graded (exit $status)" \
        sh -c "[ $status -le 1 ] && grep -q '^summary 20 20 ' '$out/kill.out'"

    left=$(left_behind)
    check "$mode: nothing any attack made is left in /tmp, /var/tmp, /dev/shm, a shared folder or System V IPC${left:+: $left}" \
        [ -z "$left" ]
    rm -rf /tmp/rtdeep /tmp/rtleak_* /tmp/rtseen_* /var/tmp/rtleak_* /var/tmp/rtseen_* \
        /dev/shm/rtleak_* /dev/shm/rtseen_* "$shared"/rtleak_* 2>/dev/null
}

if [ "$(id -u)" != 0 ]; then
    echo "   skipped: not root, so the grader drops to no user of its own; the attacks run in the mode this user gets"
    run_attacks user "$tmp/open-kit" root ""
    finish
fi
case $(cd "$tmp/private/kit" && out/build/bin/grade --jail) in
namespaces*) run_attacks namespaces "$tmp/private/kit" root "" ;;
*) echo "   skipped namespaces: $(cd "$tmp/private/kit" && out/build/bin/grade --jail)" ;;
esac
if command -v setpriv >/dev/null 2>&1 && id nobody >/dev/null 2>&1 &&
    setpriv --reuid=nobody --regid="$(id -g nobody)" --clear-groups sh -c "cd '$tmp/open-kit' && out/build/bin/grade --jail" |   # portable: guarded
    grep -q '^namespaces'; then
    run_attacks user-namespaces "$tmp/open-kit" nobody ""
else
    echo "   skipped as an ordinary user: no setpriv, or this system gives users no namespaces"
fi
run_attacks fallback "$tmp/private/kit" root "GRADE_JAIL=fallback"
finish
