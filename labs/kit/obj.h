/*
 * obj.h - reading the triangles of a Wavefront OBJ file, for the scene
 * keyword "mesh".
 *
 * The subset read: "v x y z [w]" (a vertex; w is ignored) and
 * "f i j k ..." (a face of three or more vertices, fan-triangulated; each
 * index may be written i, i/vt, i//vn or i/vt/vn, and a negative index
 * counts back from the last vertex read).  The statements vt, vn, vp, o,
 * g, s, usemtl, mtllib and l are ignored; anything else is refused, as are
 * indices out of range, NaN and infinite coordinates.
 *
 * Every vertex is transformed once, to s v + t, before any triangle uses
 * it: triangles that share a vertex share its coordinates exactly, which a
 * watertight triangle test needs.
 */
#ifndef KIT_OBJ_H
#define KIT_OBJ_H

#include <stddef.h>
#include "../raytracer.h"

/* Appends the triangles of the OBJ file at path, transformed to s v + t
 * and coloured color, to (*tris)[*ntris ...], growing *tris (capacity
 * *cap) as needed, up to max triangles in all.  Returns 0, or -1 with
 * "path:line: reason" (or "path: reason") in err; the triangles appended
 * before the error stay in *tris, which the caller frees either way. */
int obj_load(const char *path, double s, Vec3 t, Vec3 color, Triangle **tris, int *ntris,
             int *cap, int max, char *err, size_t errlen);

#endif
