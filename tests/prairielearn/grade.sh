#!/bin/sh
# PrairieLearn runs this in the grading container (prairielearn/grader-c,
# which has a C compiler and make) for every submission.  It builds the
# kit's grader from the question's tests/kit, finds the stage files the
# student uploaded, grades them (the parts of tests/weights.conf's "parts"
# line) and leaves results/results.json, written by the grader through a
# temporary file renamed into place.  If the grader cannot be built or
# cannot run, this script leaves a results.json saying so (gradable false:
# the student loses no attempt).  It always exits 0: PrairieLearn reads
# results.json only from a container that exited 0.
#
# GRADE_ROOT (default /grade) is where PrairieLearn mounts the job: tests/
# (this question's tests folder), student/ (the uploads), results/.
# GRADE_WORK (default a new temporary directory, removed afterwards) is
# where the kit is copied and built; a directory given here is kept, and
# a kit already in it is used as it is (to try the question locally
# without building the grader for every run).
root=${GRADE_ROOT:-/grade}
results="$root/results/results.json"
mkdir -p "$root/results"

# results_error MESSAGE: results.json for a submission that was not graded.
results_error() {
    message=$(printf '%s' "$1" | tr '\t' ' ' | tr -d '\000-\010\013-\037' |
        sed 's/\\/\\\\/g; s/"/\\"/g' | awk '{ printf "%s%s", sep, $0; sep = "\\n" }')
    printf '{"gradable": false, "score": 0, "message": "%s", "format_errors": "%s", "output": "%s", "tests": []}\n' \
        "The autograder could not grade this submission. Please tell the course staff." \
        "$message" "$message" >"$results.tmp" && mv "$results.tmp" "$results"
}

if [ -n "${GRADE_WORK:-}" ]; then
    work=$GRADE_WORK
    mkdir -p "$work"
else
    work=$(mktemp -d "${TMPDIR:-/tmp}/raytracer.XXXXXX") || { results_error "no temporary directory"; exit 0; }
    trap 'rm -rf "$work"' EXIT
fi
# The kit, out of reach of student code (which the grader runs in its jail:
# in a container that refuses namespaces, as a user id of its own).
if [ ! -f "$work/kit/Makefile" ]; then
    rm -rf "$work/kit"
    cp -R "$root/tests/kit" "$work/kit" || { results_error "cannot copy the kit"; exit 0; }
fi
chmod -R go-rwx "$work/kit"
chmod go+x "$work" "$work/kit" 2>/dev/null

jobs=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
if ! (cd "$work/kit" && make -s -j"$jobs" grader) >"$work/build.log" 2>&1; then
    results_error "the grader did not build: $(tail -n 20 "$work/build.log")"
    exit 0
fi

# The stage files, wherever they are under student/ (the first by name;
# not a path with a newline, which would split find's line in two, the
# second a path of the student's choosing).
rm -rf "$work/submission"
mkdir "$work/submission"
found=""
nl='
'
for stage in part1_image_plane part2_pixel_coordinates part3a_sphere_intersect part3b_ray_color \
             part4_plane_intersect part5_triangle_intersect; do
    file=$(find "$root/student" -type f -name "$stage.c" ! -path "*$nl*" 2>/dev/null | sort | head -n 1)
    if [ -n "$file" ]; then
        cp "$file" "$work/submission/$stage.c"
        found="$found $stage.c"
    fi
done
chmod 755 "$work/submission"
chmod 644 "$work/submission"/*.c 2>/dev/null
echo "found:${found:- none of the stage files}"

rm -f "$results"
(cd "$work/kit" && out/build/bin/grade --submission "$work/submission" --results "$results" \
    --format prairielearn)
status=$?
if [ "$status" -ge 2 ] && [ ! -s "$results" ]; then
    results_error "the grader stopped with status $status"
elif [ ! -s "$results" ]; then
    results_error "the grader wrote no results"
fi
exit 0
