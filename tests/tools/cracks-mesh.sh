#!/bin/sh
# cracks-mesh.sh - writes the closed mesh of labs/scenes/cracks.scene (an
# OBJ file) to standard output:
#
#     sh tests/tools/cracks-mesh.sh >labs/scenes/cracks.obj
#
# A box seen from the eye at the origin, whose every edge lies along the
# rays through pixel centres of the scene's image (320 x 240, fov 60,
# d = 1), so that a triangle test that is not watertight lets many of them
# through, front and back.  Its front face is the grid of pixel centres
# i = 64, 80, ..., 256 and j = 48, 64, ..., 192, moved out to z = -4 (times 4,
# exactly), its back face the same grid at z = -8 (times 8); each cell of
# a grid is two triangles, split along a diagonal that also runs through
# pixel centres; four side walls close the box, each in a plane through
# the eye.
#
# The pixel centres are those of the reference (solutions/), computed here
# with the same operations in double (awk's numbers):
#     h = 2 d tan(30 deg) = 1.1547005383792515, w = (320 / 240) h,
#     x = (2 i + 1 - 320) (w / 640),  y = (240 - 1 - 2 j) (h / 480).
# make test checks that the committed labs/scenes/cracks.obj is this
# script's output.
set -eu
awk 'BEGIN {
    nx = 320; ny = 240; h = 1.1547005383792515; w = (nx / ny) * h;
    step = 16; i0 = 64; i1 = 256; j0 = 48; j1 = 192;
    ci = (i1 - i0) / step; cj = (j1 - j0) / step;       # cells across and down
    print "# The closed box of cracks.scene: written by tests/tools/cracks-mesh.sh, do not edit.";
    print "# Its edges lie along the rays through pixel centres of a 320 x 240 image, fov 60.";
    n = 0;
    for (depth = 4; depth <= 8; depth += 4)              # front, then back
        for (b = 0; b <= cj; b++)
            for (a = 0; a <= ci; a++) {
                i = i0 + a * step; j = j0 + b * step;
                x = (2 * i + 1 - nx) * (w / (2 * nx));
                y = (ny - 1 - 2 * j) * (h / (2 * ny));
                printf "v %.17g %.17g %.17g\n", depth * x, depth * y, -depth;
                n++;
            }
    per = (ci + 1) * (cj + 1);                          # vertices per face
    # grid faces: vertex (a, b) of face f (0 front, 1 back) is 1 + f per + b (ci + 1) + a
    for (f = 0; f <= 1; f++)
        for (b = 0; b < cj; b++)
            for (a = 0; a < ci; a++) {
                p = 1 + f * per + b * (ci + 1) + a; q = p + 1; r = p + ci + 1; s = r + 1;
                if ((a + b) % 2 == 0) { quad(p, q, s, r, f) } else { quad(q, s, r, p, f) }
            }
    # side walls: the rims of the two faces, joined
    for (a = 0; a < ci; a++) {                           # top and bottom
        side(1 + a, 2 + a);
        side(1 + cj * (ci + 1) + a + 1, 1 + cj * (ci + 1) + a);
    }
    for (b = 0; b < cj; b++) {                           # left and right
        side(1 + (b + 1) * (ci + 1), 1 + b * (ci + 1));
        side(1 + b * (ci + 1) + ci, 1 + (b + 1) * (ci + 1) + ci);
    }
}
# Two triangles of the quad p q s r (in order around it, clockwise as the
# eye sees it), split along p s, wound so that their normals (b - a) x
# (c - a) point out of the box: towards the eye on the front face, away
# from it on the back.
function quad(p, q, s, r, back) {
    if (back) { printf "f %d %d %d\nf %d %d %d\n", p, q, s, p, s, r }
    else      { printf "f %d %d %d\nf %d %d %d\n", p, s, q, p, r, s }
}
# The wall between the front rim edge p q and its copy on the back face.
function side(p, q) {
    printf "f %d %d %d\nf %d %d %d\n", p, q, q + per, p, q + per, p + per;
}'
