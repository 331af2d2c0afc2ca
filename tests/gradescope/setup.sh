#!/bin/sh
# Gradescope runs this once, in $AUTOGRADER_ROOT/source, when it builds the
# autograder.  It installs nothing: it builds the grader with the image's C
# compiler and make, then hides the kit (the reference, the hidden tests,
# the build) from student code, which the grader runs in its jail: in a
# container that refuses namespaces, as a user id of its own (tests/grader/README.md, "The jail").
# AUTOGRADER_ROOT (default /autograder) lets the bundle be tried locally.
set -eu
root=${AUTOGRADER_ROOT:-/autograder}
cd "$root/source"
make grader
chmod -R go-rwx "$root/source"
chmod go+x "$root" "$root/source" 2>/dev/null || true
