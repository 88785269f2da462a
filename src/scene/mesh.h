/* Triangle meshes of the scene's objects, GL-free. One vertex array per object, in
 * object space (planes are already in world space); the renderer draws exactly these
 * triangles and the reference ray caster intersects exactly these. Non-indexed so each
 * vertex can carry its triangle's face normal (the shadow decision uses the geometric
 * facing, shading uses the smooth normal). Counter-clockwise front faces. */
#ifndef LX_MESH_H
#define LX_MESH_H
#include "scene.h"

#define LX_VERTEX_FLOATS 9 /* position xyz, smooth normal xyz, face normal xyz */

struct lx_mesh {
	float *v;         /* vertex_count * LX_VERTEX_FLOATS */
	int vertex_count; /* 3 per triangle */
	vec3 bmin, bmax;  /* object-space bounds */
};

struct lx_scene_meshes {
	int count; /* lx_scene_object_count() */
	struct lx_mesh *mesh;
};

bool lx_meshes_build(const struct lx_scene *s, struct lx_scene_meshes *out);
/* Whether a mesh is flat-shaded: every vertex's shading normal is its face's, the very
 * same floats (the builder writes them so for planes and boxes), so that its Lambert term
 * is 0 wherever its face is turned away from the light. */
bool lx_mesh_is_flat(const struct lx_mesh *m);
void lx_meshes_free(struct lx_scene_meshes *m);
/* World translation of object id at time t (zero for planes). */
vec3 lx_object_offset(const struct lx_scene *s, int id, double t);

#endif
