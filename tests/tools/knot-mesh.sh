#!/bin/sh
# knot-mesh.sh - writes a closed mesh, a tube around a trefoil knot, as an
# OBJ file to standard output:
#
#     sh tests/tools/knot-mesh.sh >labs/scenes/knot.obj          (10,000 triangles)
#     sh tests/tools/knot-mesh.sh U V >big.obj                   (2 U V triangles)
#
# The knot is the (2, 3) torus knot, (R + r cos 3u) (cos 2u, sin 2u) in x
# and y and r sin 3u in z, with R = 1 and r = 0.45; the tube around it has
# radius 0.14.  U rings of V vertices each (U, V >= 3; by default 250 and
# 20) are joined by U V quads, each of which the OBJ reader splits into two
# triangles: 2 U V triangles, every edge shared by two of them, so that a
# watertight triangle test lets no ray through.  A ring lies in the plane
# square to the knot, its vertices at angles 2 pi k / V about the knot from
# the direction that points away from the torus's core circle.
#
# The numbers are written with 6 significant digits: a quad's vertices
# are indices, so triangles that share a vertex share its coordinates
# whatever they are.  make test checks that the committed
# labs/scenes/knot.obj is this script's output with no arguments.
set -eu
U=${1:-250}
V=${2:-20}
case $U$V in
*[!0-9]*) echo "usage: knot-mesh.sh [U V]: whole numbers, at least 3 each" >&2; exit 2 ;;
esac
if [ "$U" -lt 3 ] || [ "$V" -lt 3 ]; then
    echo "usage: knot-mesh.sh [U V]: whole numbers, at least 3 each" >&2
    exit 2
fi
awk -v U="$U" -v V="$V" 'BEGIN {
    pi = atan2(0, -1); R = 1; r = 0.45; rho = 0.14; du = 1e-4;
    printf "# A tube around a trefoil knot: %d triangles, written by tests/tools/knot-mesh.sh %d %d, do not edit.\n", 2 * U * V, U, V;
    for (i = 0; i < U; i++) {
        u = 2 * pi * i / U;
        knot(u); px = kx; py = ky; pz = kz;
        knot(u + du); tx = kx - px; ty = ky - py; tz = kz - pz;       # along the knot
        knot(u - du); tx -= kx - px; ty -= ky - py; tz -= kz - pz;
        t = sqrt(tx * tx + ty * ty + tz * tz); tx /= t; ty /= t; tz /= t;
        # away from the core circle (R cos 2u, R sin 2u, 0), made square to the knot
        nx = px - R * cos(2 * u); ny = py - R * sin(2 * u); nz = pz;
        d = nx * tx + ny * ty + nz * tz; nx -= d * tx; ny -= d * ty; nz -= d * tz;
        n = sqrt(nx * nx + ny * ny + nz * nz); nx /= n; ny /= n; nz /= n;
        bx = ty * nz - tz * ny; by = tz * nx - tx * nz; bz = tx * ny - ty * nx;
        for (k = 0; k < V; k++) {
            a = 2 * pi * k / V; c = rho * cos(a); s = rho * sin(a);
            printf "v %.6g %.6g %.6g\n", px + c * nx + s * bx, py + c * ny + s * by, pz + c * nz + s * bz;
        }
    }
    # vertex k of ring i is 1 + i V + k; ring U is ring 0 again
    for (i = 0; i < U; i++) {
        j = (i + 1) % U;
        for (k = 0; k < V; k++) {
            l = (k + 1) % V;
            printf "f %d %d %d %d\n", 1 + i * V + k, 1 + j * V + k, 1 + j * V + l, 1 + i * V + l;
        }
    }
}
function knot(u) {
    kx = (R + r * cos(3 * u)) * cos(2 * u);
    ky = (R + r * cos(3 * u)) * sin(2 * u);
    kz = r * sin(3 * u);
}'
