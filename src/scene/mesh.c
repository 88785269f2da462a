#include "mesh.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SEGMENTS 32 /* around a sphere, cylinder or cone */
#define RINGS 16    /* pole to pole on a sphere */

struct builder {
	float *v;
	int count, cap;
	bool oom;
};

static void emit(struct builder *b, vec3 p, vec3 n, vec3 fn)
{
	if (b->count == b->cap) {
		int cap = b->cap ? b->cap * 2 : 192;
		float *v = realloc(b->v, (size_t)cap * LX_VERTEX_FLOATS * sizeof(float));
		if (!v) {
			b->oom = true;
			return;
		}
		b->v = v;
		b->cap = cap;
	}
	float *o = b->v + (size_t)b->count++ * LX_VERTEX_FLOATS;
	o[0] = (float)p.x, o[1] = (float)p.y, o[2] = (float)p.z;
	o[3] = (float)n.x, o[4] = (float)n.y, o[5] = (float)n.z;
	o[6] = (float)fn.x, o[7] = (float)fn.y, o[8] = (float)fn.z;
}

/* A triangle with given smooth normals, or (flat) each its face normal, the very same
 * floats (the renderer tells a flat-shaded mesh by them); degenerate ones (sphere poles)
 * are dropped. */
static void tri_normals(struct builder *b, bool flat, vec3 a, vec3 na, vec3 c1, vec3 n1, vec3 c2, vec3 n2)
{
	vec3 fn, e1, e2;
	/* the edges normalised first: a tiny caster's cross product would underflow */
	if (!v3_normalize(v3_sub(c1, a), &e1) || !v3_normalize(v3_sub(c2, a), &e2) || !v3_normalize(v3_cross(e1, e2), &fn))
		return;
	emit(b, a, flat ? fn : na, fn);
	emit(b, c1, flat ? fn : n1, fn);
	emit(b, c2, flat ? fn : n2, fn);
}

static void tri(struct builder *b, vec3 a, vec3 na, vec3 c1, vec3 n1, vec3 c2, vec3 n2)
{
	tri_normals(b, false, a, na, c1, n1, c2, n2);
}

static void flat_quad(struct builder *b, vec3 p0, vec3 p1, vec3 p2, vec3 p3)
{
	vec3 n = v3(0, 0, 0); /* unused: flat */
	tri_normals(b, true, p0, n, p1, n, p2, n);
	tri_normals(b, true, p0, n, p2, n, p3, n);
}

static vec3 ring(double r, double y, int i)
{
	double a = 2 * M_PI * i / SEGMENTS;
	return v3(r * cos(a), y, -r * sin(a));
}

static void build_caster(struct builder *b, const struct lx_caster *c)
{
	vec3 s = c->size;
	switch (c->shape) {
	case LX_SPHERE:
		for (int j = 0; j < RINGS; j++)
			for (int i = 0; i < SEGMENTS; i++) {
				vec3 n[4];
				for (int k = 0; k < 4; k++) {
					int ii = i + (k == 1 || k == 2), jj = j + (k >= 2);
					double th = M_PI * jj / RINGS, ph = 2 * M_PI * ii / SEGMENTS;
					n[k] = v3(sin(th) * cos(ph), cos(th), -sin(th) * sin(ph));
				}
				vec3 p[4];
				for (int k = 0; k < 4; k++)
					p[k] = v3(s.x * n[k].x, s.x + s.x * n[k].y, s.x * n[k].z);
				/* From the top (y = 2r) down; CCW seen from outside. */
				tri(b, p[0], n[0], p[3], n[3], p[2], n[2]);
				tri(b, p[0], n[0], p[2], n[2], p[1], n[1]);
			}
		break;
	case LX_BOX: {
		double x0 = -s.x / 2, x1 = s.x / 2, z0 = -s.z / 2, z1 = s.z / 2, y1 = s.y;
		vec3 c000 = v3(x0, 0, z0), c100 = v3(x1, 0, z0), c010 = v3(x0, y1, z0), c110 = v3(x1, y1, z0);
		vec3 c001 = v3(x0, 0, z1), c101 = v3(x1, 0, z1), c011 = v3(x0, y1, z1), c111 = v3(x1, y1, z1);
		flat_quad(b, c001, c101, c111, c011); /* +z */
		flat_quad(b, c100, c000, c010, c110); /* -z */
		flat_quad(b, c101, c100, c110, c111); /* +x */
		flat_quad(b, c000, c001, c011, c010); /* -x */
		flat_quad(b, c011, c111, c110, c010); /* +y */
		flat_quad(b, c000, c100, c101, c001); /* -y */
		break;
	}
	case LX_CYLINDER:
	case LX_CONE: {
		double top_r = c->shape == LX_CYLINDER ? s.x : 0.0, h = s.y;
		double slope = (s.x - top_r) / h; /* h > 0 by validation */
		vec3 up = v3(0, 1, 0), down = v3(0, -1, 0), apex = v3(0, h, 0), base = v3(0, 0, 0);
		for (int i = 0; i < SEGMENTS; i++) {
			vec3 b0 = ring(s.x, 0, i), b1 = ring(s.x, 0, i + 1);
			vec3 t0 = ring(top_r, h, i), t1 = ring(top_r, h, i + 1);
			vec3 n0 = v3(0, 0, 0), n1 = n0;
			v3_normalize(v3(b0.x, slope * s.x, b0.z), &n0);
			v3_normalize(v3(b1.x, slope * s.x, b1.z), &n1);
			tri(b, b0, n0, b1, n1, t1, n1);
			if (top_r > 0) {
				tri(b, b0, n0, t1, n1, t0, n0);
				tri(b, apex, up, t0, up, t1, up);
			}
			tri(b, base, down, b1, down, b0, down);
		}
		break;
	}
	default:
		break;
	}
}

static bool finish(struct builder *b, struct lx_mesh *m)
{
	if (b->oom || b->count == 0) {
		free(b->v);
		return false;
	}
	m->v = b->v;
	m->vertex_count = b->count;
	m->bmin = v3(INFINITY, INFINITY, INFINITY);
	m->bmax = v3(-INFINITY, -INFINITY, -INFINITY);
	for (int i = 0; i < b->count; i++) {
		const float *p = m->v + (size_t)i * LX_VERTEX_FLOATS;
		m->bmin = v3_min(m->bmin, v3(p[0], p[1], p[2])), m->bmax = v3_max(m->bmax, v3(p[0], p[1], p[2]));
	}
	return true;
}

bool lx_meshes_build(const struct lx_scene *s, struct lx_scene_meshes *out)
{
	out->count = lx_scene_object_count(s);
	out->mesh = calloc((size_t)out->count, sizeof(struct lx_mesh));
	if (!out->mesh)
		return false;
	for (int id = 0; id < out->count; id++) {
		struct builder b = {0};
		if (id < s->plane_count) {
			const struct lx_plane *p = &s->planes[id];
			vec3 p1 = v3_add(p->corner, p->edge1), p3 = v3_add(p->corner, p->edge2);
			flat_quad(&b, p->corner, p1, v3_add(p1, p->edge2), p3);
		} else
			build_caster(&b, &s->casters[id - s->plane_count]);
		if (!finish(&b, &out->mesh[id])) {
			lx_meshes_free(out);
			return false;
		}
	}
	return true;
}

bool lx_mesh_is_flat(const struct lx_mesh *m)
{
	for (int i = 0; i < m->vertex_count; i++)
		if (memcmp(m->v + (size_t)i * LX_VERTEX_FLOATS + 3, m->v + (size_t)i * LX_VERTEX_FLOATS + 6, 3 * sizeof(float)))
			return false;
	return true;
}

void lx_meshes_free(struct lx_scene_meshes *m)
{
	if (m->mesh)
		for (int i = 0; i < m->count; i++)
			free(m->mesh[i].v);
	free(m->mesh);
	m->mesh = NULL;
	m->count = 0;
}

vec3 lx_object_offset(const struct lx_scene *s, int id, double t)
{
	if (id < s->plane_count)
		return v3(0, 0, 0);
	return lx_caster_position(&s->casters[id - s->plane_count], t);
}
