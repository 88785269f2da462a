#include "reference.h"
#include "light_image.h"
#include <math.h>
#include <stdio.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

struct tri {
	vec3 a, e1, e2, n; /* vertex, two edges, unit face normal */
	int object;
	const float *v; /* its first vertex in the mesh (LX_VERTEX_FLOATS each): the normals to shade with */
};

struct node {
	vec3 lo, hi;
	int first, count; /* leaf: triangles [first, first + count); inner: count = 0, first = right child */
};

struct lx_raycaster {
	struct tri *tris;
	int ntris;
	struct node *nodes;
	int nnodes;
	double scale; /* scene size, for relative epsilons */
	int depth;    /* the deepest node's depth */
};


static vec3 centroid(const struct tri *t) { return v3_add(t->a, v3_scale(v3_add(t->e1, t->e2), 1.0 / 3)); }

/* The triangle's box. */
static void tri_box(const struct tri *t, vec3 *lo, vec3 *hi)
{
	vec3 b = v3_add(t->a, t->e1), c = v3_add(t->a, t->e2);
	*lo = v3_min(t->a, v3_min(b, c));
	*hi = v3_max(t->a, v3_max(b, c));
}

static double half_area(vec3 lo, vec3 hi)
{
	vec3 e = v3_sub(hi, lo);
	return e.x * e.y + e.y * e.z + e.z * e.x;
}

/* The split plane of triangles [first, first + count) by the surface area heuristic over
 * LX_SAH_BINS bins of their centroids on each axis: the one that minimises the children's
 * box areas weighted by their triangle counts. An axis whose centroids coincide is skipped;
 * when all do, the longest axis's midpoint (build() then halves the range). */
enum { LX_SAH_BINS = 16 };
static void sah_split(const struct lx_raycaster *rc, int first, int count, vec3 clo, vec3 chi, int *axis_out,
		      double *split_out)
{
	vec3 ext = v3_sub(chi, clo);
	*axis_out = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
	*split_out = ((&clo.x)[*axis_out] + (&chi.x)[*axis_out]) / 2;
	/* every axis's bins in one pass over the triangles: each box and centroid once */
	vec3 blo[3][LX_SAH_BINS], bhi[3][LX_SAH_BINS];
	int n[3][LX_SAH_BINS] = {{0}};
	for (int axis = 0; axis < 3; axis++)
		for (int b = 0; b < LX_SAH_BINS; b++)
			blo[axis][b] = v3(INFINITY, INFINITY, INFINITY), bhi[axis][b] = v3(-INFINITY, -INFINITY, -INFINITY);
	for (int i = first; i < first + count; i++) {
		vec3 lo, hi, m = centroid(&rc->tris[i]);
		tri_box(&rc->tris[i], &lo, &hi);
		for (int axis = 0; axis < 3; axis++) {
			double len = (&ext.x)[axis];
			if (!(len > 0))
				continue;
			int b = (int)(LX_SAH_BINS * (((&m.x)[axis] - (&clo.x)[axis]) / len)); /* len > 0 */
			b = b < 0 ? 0 : b >= LX_SAH_BINS ? LX_SAH_BINS - 1 : b;
			n[axis][b]++;
			blo[axis][b] = v3_min(blo[axis][b], lo);
			bhi[axis][b] = v3_max(bhi[axis][b], hi);
		}
	}
	double best = INFINITY;
	for (int axis = 0; axis < 3; axis++) {
		double lo = (&clo.x)[axis], len = (&ext.x)[axis];
		if (!(len > 0))
			continue; /* the centroids coincide on it */
		/* the cost of cutting after bin k: left bins' area x count + right bins' */
		double right_cost[LX_SAH_BINS];
		vec3 rlo = v3(INFINITY, INFINITY, INFINITY), rhi = v3(-INFINITY, -INFINITY, -INFINITY);
		int rn = 0;
		for (int b = LX_SAH_BINS - 1; b > 0; b--) {
			rlo = v3_min(rlo, blo[axis][b]), rhi = v3_max(rhi, bhi[axis][b]), rn += n[axis][b];
			right_cost[b] = rn ? half_area(rlo, rhi) * rn : 0;
		}
		vec3 llo = v3(INFINITY, INFINITY, INFINITY), lhi = v3(-INFINITY, -INFINITY, -INFINITY);
		int ln = 0;
		for (int b = 0; b < LX_SAH_BINS - 1; b++) {
			llo = v3_min(llo, blo[axis][b]), lhi = v3_max(lhi, bhi[axis][b]), ln += n[axis][b];
			if (!ln || ln == count)
				continue;
			double cost = half_area(llo, lhi) * ln + right_cost[b + 1];
			if (cost < best) {
				best = cost;
				*axis_out = axis;
				*split_out = lo + len * (b + 1) / LX_SAH_BINS;
			}
		}
	}
}

/* Inner nodes at most this deep: a leaf takes whatever is left below it (correct, only
 * slower), so the traversal's stack of LX_BVH_MAX_DEPTH + 2 entries never overflows
 * whatever the scene (the 16-bin splits of casters spaced 1, 16, 256, ... go one level
 * per caster). */
static int build(struct lx_raycaster *rc, int first, int count, int depth)
{
	int idx = rc->nnodes++;
	struct node *n = &rc->nodes[idx];
	rc->depth = depth > rc->depth ? depth : rc->depth;
	n->lo = v3(INFINITY, INFINITY, INFINITY);
	n->hi = v3(-INFINITY, -INFINITY, -INFINITY);
	vec3 clo = n->lo, chi = n->hi;
	for (int i = first; i < first + count; i++) {
		const struct tri *t = &rc->tris[i];
		vec3 lo, hi;
		tri_box(t, &lo, &hi);
		n->lo = v3_min(n->lo, lo);
		n->hi = v3_max(n->hi, hi);
		vec3 m = centroid(t);
		clo = v3_min(clo, m);
		chi = v3_max(chi, m);
	}
	if (count <= 4 || depth >= LX_BVH_MAX_DEPTH) {
		n->first = first;
		n->count = count;
		return idx;
	}
	int axis;
	double split;
	sah_split(rc, first, count, clo, chi, &axis, &split);
	int mid = first;
	for (int i = first; i < first + count; i++) {
		vec3 m = centroid(&rc->tris[i]);
		if ((&m.x)[axis] < split) {
			struct tri t = rc->tris[i];
			rc->tris[i] = rc->tris[mid];
			rc->tris[mid++] = t;
		}
	}
	if (mid == first || mid == first + count) /* all centroids coincide: split in half */
		mid = first + count / 2;
	build(rc, first, mid - first, depth + 1);
	int right = build(rc, mid, first + count - mid, depth + 1);
	n = &rc->nodes[idx]; /* nodes is preallocated, the pointer stays valid; re-take for clarity */
	n->first = right;
	n->count = 0;
	return idx;
}

struct lx_raycaster *lx_raycaster_create(const struct lx_frame *f)
{
	struct lx_raycaster *rc = calloc(1, sizeof(*rc));
	if (!rc)
		return NULL;
	for (int id = 0; id < f->meshes->count; id++)
		rc->ntris += f->meshes->mesh[id].vertex_count / 3;
	rc->tris = malloc((size_t)rc->ntris * sizeof(struct tri));
	rc->nodes = malloc((size_t)(2 * rc->ntris + 1) * sizeof(struct node));
	if (!rc->tris || !rc->nodes) {
		lx_raycaster_destroy(rc);
		return NULL;
	}
	int k = 0;
	for (int id = 0; id < f->meshes->count; id++) {
		const struct lx_mesh *m = &f->meshes->mesh[id];
		for (int i = 0; i < m->vertex_count; i += 3) {
			vec3 p[3];
			/* the same float vertices the GL draws, translated in double */
			for (int j = 0; j < 3; j++) {
				const float *v = m->v + (size_t)(i + j) * LX_VERTEX_FLOATS;
				p[j] = v3_add(v3(v[0], v[1], v[2]), f->offset[id]);
			}
			struct tri *t = &rc->tris[k++];
			t->a = p[0];
			t->e1 = v3_sub(p[1], p[0]);
			t->e2 = v3_sub(p[2], p[0]);
			t->n = v3(0, 0, 0);
			v3_normalize(v3_cross(t->e1, t->e2), &t->n); /* meshes hold no degenerate triangles */
			t->object = id;
			t->v = m->v + (size_t)i * LX_VERTEX_FLOATS;
		}
	}
	rc->scale = v3_len(v3_sub(f->scene_max, f->scene_min)) + 1e-300;
	if (rc->ntris)
		build(rc, 0, rc->ntris, 0);
	return rc;
}

void lx_raycaster_destroy(struct lx_raycaster *rc)
{
	if (!rc)
		return;
	free(rc->tris);
	free(rc->nodes);
	free(rc);
}

int lx_raycaster_depth(const struct lx_raycaster *rc) { return rc->depth; }

int lx_raycaster_object(const struct lx_raycaster *rc, int tri) { return tri >= 0 ? rc->tris[tri].object : LX_NO_OBJECT; }

/* Moller-Trumbore; edges count as inside so neighbouring triangles leave no crack. */
static bool hit_tri(const struct tri *t, vec3 o, vec3 d, double tmin, double tmax, double *tout)
{
	vec3 p = v3_cross(d, t->e2);
	double det = v3_dot(t->e1, p);
	if (fabs(det) < 1e-300) /* ray parallel to the triangle */
		return false;
	double inv = 1.0 / det;
	vec3 s = v3_sub(o, t->a);
	double u = v3_dot(s, p) * inv;
	if (u < 0 || u > 1)
		return false;
	vec3 q = v3_cross(s, t->e1);
	double v = v3_dot(d, q) * inv;
	if (v < 0 || u + v > 1)
		return false;
	double tt = v3_dot(t->e2, q) * inv;
	if (!(tt > tmin && tt < tmax))
		return false;
	*tout = tt;
	return true;
}

/* Whether the ray o + t d, t in [tmin, tmax] (inv = 1 / d per axis), meets the box
 * [lo - r, hi + r]: the slab test. */
static bool slabs_meet(vec3 o, vec3 inv, vec3 lo, vec3 hi, double r, double tmin, double tmax)
{
	for (int k = 0; k < 3; k++) {
		double oo = (&o.x)[k], iv = (&inv.x)[k];
		double t0 = ((&lo.x)[k] - r - oo) * iv, t1 = ((&hi.x)[k] + r - oo) * iv;
		if (t0 > t1) {
			double t = t0;
			t0 = t1;
			t1 = t;
		}
		/* NaN from 0 * inf (ray in the slab's plane) must not reject: a comparison with NaN
		 * is false, so the bound stays (as fmax/fmin would, without their calls) */
		if (t0 > tmin)
			tmin = t0;
		if (t1 < tmax)
			tmax = t1;
		if (tmin > tmax)
			return false;
	}
	return true;
}

static bool hit_box(const struct node *n, vec3 o, vec3 inv, double tmin, double tmax)
{
	return slabs_meet(o, inv, n->lo, n->hi, 0, tmin, tmax);
}

/* The first (or with `any`, some) triangle hit with t in (tmin, tmax), leaving out
 * triangle `skip` and every triangle of object `skip_object` (LX_NO_OBJECT: none). */
static int traverse(const struct lx_raycaster *rc, vec3 o, vec3 d, double tmin, double tmax, bool any, int skip,
		    int skip_object, double *tbest)
{
	if (!rc->ntris)
		return -1;
	vec3 inv = v3(1.0 / d.x, 1.0 / d.y, 1.0 / d.z); /* +-inf for axis-parallel rays is what the slab test wants */
	int stack[LX_BVH_MAX_DEPTH + 2], sp = 0, best = -1; /* one more entry per level at most */
	stack[sp++] = 0;
	while (sp) {
		const struct node *n = &rc->nodes[stack[--sp]];
		if (!hit_box(n, o, inv, tmin, tmax))
			continue;
		if (n->count) {
			for (int i = n->first; i < n->first + n->count; i++) {
				double t;
				if (i != skip && rc->tris[i].object != skip_object && hit_tri(&rc->tris[i], o, d, tmin, tmax, &t)) {
					best = i;
					tmax = t;
					if (any)
						return best;
				}
			}
		} else {
			if (sp + 2 > LX_BVH_MAX_DEPTH + 2) { /* cannot happen: build() caps the depth */
				fprintf(stderr, "lixel: reference BVH deeper than its cap of %d\n", LX_BVH_MAX_DEPTH);
				abort();
			}
			stack[sp++] = n->first;
			stack[sp++] = (int)(n - rc->nodes) + 1;
		}
	}
	*tbest = tmax;
	return best;
}

int lx_raycast_first(const struct lx_raycaster *rc, vec3 o, vec3 d, double tmin, double tmax, double *t)
{
	return traverse(rc, o, d, tmin, tmax, false, -1, LX_NO_OBJECT, t);
}

bool lx_raycast_any(const struct lx_raycaster *rc, vec3 o, vec3 d, double tmin, double tmax, int skip)
{
	double t;
	return traverse(rc, o, d, tmin, tmax, true, skip, LX_NO_OBJECT, &t) >= 0;
}

bool lx_raycast_blocked(const struct lx_raycaster *rc, vec3 o, vec3 d, double tmin, double tmax, int skip_object)
{
	double t;
	return traverse(rc, o, d, tmin, tmax, true, -1, skip_object, &t) >= 0;
}

bool lx_raycast_blocked_hint(const struct lx_raycaster *rc, vec3 o, vec3 d, double tmin, double tmax, int skip_object,
			     int *hint)
{
	double t;
	int h = *hint;
	if (h >= 0 && h < rc->ntris && rc->tris[h].object != skip_object && hit_tri(&rc->tris[h], o, d, tmin, tmax, &t))
		return true;
	int hit = traverse(rc, o, d, tmin, tmax, true, -1, skip_object, &t);
	if (hit >= 0)
		*hint = hit;
	return hit >= 0;
}

/* Whether segment a + s (b - a), s in [0, 1], meets the box [lo - r, hi + r]. */
static bool segment_meets_box(vec3 a, vec3 inv, vec3 lo, vec3 hi, double r)
{
	return slabs_meet(a, inv, lo, hi, r, 0, 1);
}

bool lx_raycast_near(const struct lx_raycaster *rc, vec3 a, vec3 b, double r, int skip_object)
{
	if (!rc->ntris)
		return false;
	vec3 d = v3_sub(b, a), inv = v3(1.0 / d.x, 1.0 / d.y, 1.0 / d.z);
	int stack[LX_BVH_MAX_DEPTH + 2], sp = 0;
	stack[sp++] = 0;
	while (sp) {
		const struct node *n = &rc->nodes[stack[--sp]];
		if (!segment_meets_box(a, inv, n->lo, n->hi, r))
			continue;
		if (!n->count) { /* build() caps the depth: the stack holds */
			stack[sp++] = n->first;
			stack[sp++] = (int)(n - rc->nodes) + 1;
			continue;
		}
		for (int i = n->first; i < n->first + n->count; i++) {
			vec3 lo, hi;
			tri_box(&rc->tris[i], &lo, &hi);
			if (rc->tris[i].object != skip_object && segment_meets_box(a, inv, lo, hi, r))
				return true;
		}
	}
	return false;
}

vec3 lx_raycaster_normal(const struct lx_raycaster *rc, int tri) { return rc->tris[tri].n; }

double lx_raycaster_scale(const struct lx_raycaster *rc) { return rc->scale; }

/* The pixel's decision at p on triangle tri: LX_REF_EDGE_ON where the light grazes it
 * (|cos| of its incidence at most LX_EDGE_ON_COS: there the lit and the shadowed shading
 * differ by less than one 8-bit step, and float rounding, the renderer's or this caster's
 * for a light lying in the plane, decides the side, so neither decision is wrong; no ray
 * is cast), else 1 where shadowed, 0 where lit. */
static int decide(const struct lx_raycaster *rc, const struct lx_light *light, vec3 p, int tri, bool edge_on)
{
	vec3 to_light = light->directional ? v3_scale(light->direction, -1) : v3_sub(light->position, p);
	double cos_len = v3_dot(rc->tris[tri].n, to_light), len = v3_len(to_light); /* n is unit */
	if (edge_on && fabs(cos_len) <= LX_EDGE_ON_COS * len)
		return LX_REF_EDGE_ON;
	if (!(cos_len > 0))
		return 1; /* faces away from the light (or the light lies in its plane) */
	/* For a point light the segment ends at the light (s = 1); start a hair off the surface. */
	double smin = 1e-9 * rc->scale / len; /* len > 0: the dot product above was positive */
	/* and end a hair before a point light: a surface through the light (a light lying on
	 * the floor) does not hide the light from points off that surface */
	double smax = light->directional ? INFINITY : 1.0 - 1e-9;
	return lx_raycast_any(rc, p, to_light, smin, smax, tri);
}

bool lx_reference_shadowed(const struct lx_raycaster *rc, const struct lx_light *light, vec3 p, int tri)
{
	return decide(rc, light, p, tri, false);
}

/* One light of a job: the light (frames[i]'s, as its frame set it up), its projective
 * matrix and image when it is projective, and where its decisions go. */
struct job_light {
	const struct lx_light *light;
	bool projective;
	mat4 beam;
	const struct lx_image *image;
	uint8_t *shadowed;
};

struct job {
	const struct lx_frame *f; /* the view, scene and meshes: the first light's frame */
	const struct lx_raycaster *rc;
	int16_t *object;
	int n;
	struct job_light lights[LX_MAX_LIGHTS];
	uint8_t *rgba; /* the shaded colours too, or NULL */
};

/* The view ray through a pixel's centre, from the near plane (t = 0) to the far (t = 1). */
static void pixel_ray(const struct lx_view *v, int x, int y, vec3 *o, vec3 *d)
{
	double nx = (x + 0.5) / v->width * 2 - 1, ny = (y + 0.5) / v->height * 2 - 1;
	vec4 a = m4_mul_v4(&v->inv_view_proj, (vec4){nx, ny, -1, 1});
	vec4 b = m4_mul_v4(&v->inv_view_proj, (vec4){nx, ny, 1, 1});
	/* inside the frustum w > 0 for both */
	*o = v3(a.x / a.w, a.y / a.w, a.z / a.w);
	*d = v3_sub(v3(b.x / b.w, b.y / b.w, b.z / b.w), *o);
}

/* What a visible point's shading starts from: the object's colour and the vertex normals
 * interpolated across its triangle (not normalised). */
struct surface {
	vec3 color, n;
};

static struct surface surface_at(const struct job *j, int tri, vec3 p)
{
	const struct tri *t = &j->rc->tris[tri];
	const struct lx_scene *s = j->f->scene;
	int id = t->object;
	struct surface out = {.n = v3(0, 0, 0)};
	out.color = id < s->plane_count ? s->planes[id].color : s->casters[id - s->plane_count].color;
	/* barycentric (u, v) of p: p - a = u e1 + v e2 (the triangle is not degenerate) */
	vec3 r = v3_sub(p, t->a);
	double e11 = v3_dot(t->e1, t->e1), e12 = v3_dot(t->e1, t->e2), e22 = v3_dot(t->e2, t->e2);
	double det = e11 * e22 - e12 * e12, r1 = v3_dot(r, t->e1), r2 = v3_dot(r, t->e2);
	double u = det > 0 ? (r1 * e22 - r2 * e12) / det : 0, w = det > 0 ? (r2 * e11 - r1 * e12) / det : 0;
	for (int k = 0; k < 3; k++) {
		const float *vn = t->v + (size_t)k * LX_VERTEX_FLOATS + 3;
		double b = k == 0 ? 1 - u - w : k == 1 ? u : w;
		out.n = v3_add(out.n, v3_scale(v3(vn[0], vn[1], vn[2]), b));
	}
	return out;
}

/* The renderer's shading at p by one light, exactly: main.frag's diffuse term with the
 * light's colour (for a projective light its image and range too, which
 * lx_projective_light_at already multiplies by the colour), plus the ambient term for the
 * first light only, as the additive passes make it [Segal]. */
static vec3 shade(const struct job_light *L, const struct surface *s, vec3 p, int decision, bool first)
{
	const struct lx_light *l = L->light;
	vec3 to_light = l->directional ? v3_scale(l->direction, -1) : v3_sub(l->position, p), nn, ln;
	double lambert = v3_normalize(s->n, &nn) && v3_normalize(to_light, &ln) ? fmax(v3_dot(nn, ln), 0) : 0;
	vec3 light = L->projective ? lx_projective_light_at(l, &L->beam, L->image, p) : l->color;
	/* shadowed (1): no diffuse term; grazed (2): lambert is ~0 either way; unlit (3): the light
	 * sends nothing there */
	double lit = decision == 1 ? 0 : 0.78 * lambert, amb = first ? 0.22 : 0;
	vec3 c = s->color;
	return v3(c.x * (amb + lit * light.x), c.y * (amb + lit * light.y), c.z * (amb + lit * light.z));
}

static uint8_t level(double c) { return (uint8_t)lround(255 * fmin(fmax(c, 0), 1)); }

int lx_reference_pixel(const struct lx_frame *f, const struct lx_raycaster *rc, int x, int y, vec3 *p)
{
	vec3 o, d;
	pixel_ray(&f->view, x, y, &o, &d);
	double t;
	int tri = lx_raycast_first(rc, o, d, 0.0, 1.0, &t);
	if (tri >= 0)
		*p = v3_add(o, v3_scale(d, t));
	return tri;
}

/* Light k's decision at p on triangle tri (-1: the background). */
static uint8_t job_decision(const struct job *j, int k, int tri, vec3 p)
{
	const struct job_light *L = &j->lights[k];
	if (tri < 0)
		return 0;
	if (L->projective && !lx_light_reaches(L->light, &L->beam, p))
		return LX_REF_UNLIT;
	return (uint8_t)decide(j->rc, L->light, p, tri, true);
}

/* One row of a job: each pixel's object, every light's decision, and its colour when asked,
 * from the one ray that finds what the pixel sees. Each light's pass is quantised to
 * 8 bits and the sum clamps at 255, as additive blending into RGBA8 does. */
static void job_row(void *ctx, int y)
{
	const struct job *j = ctx;
	const struct lx_view *v = &j->f->view;
	for (int x = 0; x < v->width; x++) {
		vec3 o, d, p = v3(0, 0, 0);
		pixel_ray(v, x, y, &o, &d);
		size_t i = (size_t)y * v->width + x;
		double t;
		int tri = lx_raycast_first(j->rc, o, d, 0.0, 1.0, &t);
		if (tri >= 0)
			p = v3_add(o, v3_scale(d, t));
		j->object[i] = (int16_t)lx_raycaster_object(j->rc, tri);
		struct surface s = {{0.08, 0.09, 0.11}, {0, 0, 0}}; /* the background: the clear colour */
		if (j->rgba && tri >= 0)
			s = surface_at(j, tri, p);
		int sum[3] = {0, 0, 0};
		for (int k = 0; k < j->n; k++) {
			uint8_t dec = job_decision(j, k, tri, p);
			j->lights[k].shadowed[i] = dec;
			if (!j->rgba || (tri < 0 && k > 0))
				continue;
			vec3 c = tri >= 0 ? shade(&j->lights[k], &s, p, dec, k == 0) : s.color;
			sum[0] += level(c.x), sum[1] += level(c.y), sum[2] += level(c.z);
		}
		if (j->rgba) {
			uint8_t *q = j->rgba + i * 4;
			for (int ch = 0; ch < 3; ch++)
				q[ch] = (uint8_t)(sum[ch] < 255 ? sum[ch] : 255);
			q[3] = 255;
		}
	}
}

/* Rows row0, row0 + step, ... of an image, each by the row function. */
struct rows {
	void (*row)(void *ctx, int y);
	void *ctx;
	int row0, step, height;
};

static void *run_rows(void *arg)
{
	struct rows *j = arg;
	for (int y = j->row0; y < j->height; y += j->step)
		j->row(j->ctx, y);
	return NULL;
}

void lx_reference_rows(int height, int threads, void (*row)(void *ctx, int y), void *ctx)
{
	threads = threads < 1 ? 1 : threads > 16 ? 16 : threads;
	pthread_t th[16];
	struct rows jobs[16];
	int started = 0;
	for (int i = 0; i < threads; i++) {
		jobs[i] = (struct rows){row, ctx, i, threads, height};
		if (i > 0 && pthread_create(&th[i], NULL, run_rows, &jobs[i]) == 0)
			started |= 1 << i;
	}
	run_rows(&jobs[0]);
	for (int i = 1; i < threads; i++) {
		if (started & (1 << i))
			pthread_join(th[i], NULL);
		else
			run_rows(&jobs[i]); /* thread could not start: do its rows here */
	}
}

bool lx_reference_lights(const struct lx_frame *const *frames, const struct lx_image *const *images, int n,
			 int16_t *object, uint8_t *const *shadowed, uint8_t *rgba, int threads)
{
	if (n < 1 || n > LX_MAX_LIGHTS)
		return false;
	struct job job = {.f = frames[0], .object = object, .n = n, .rgba = rgba};
	for (int k = 0; k < n; k++) {
		struct job_light *L = &job.lights[k];
		L->light = &frames[k]->light;
		L->projective = lx_light_projection(L->light, &L->beam);
		L->image = L->projective && images ? images[k] : NULL;
		L->shadowed = shadowed[k];
		if (L->projective && rgba && !L->image)
			return false; /* a projective light's colours need its image */
	}
	struct lx_raycaster *rc = lx_raycaster_create(frames[0]);
	if (!rc)
		return false;
	job.rc = rc;
	lx_reference_rows(frames[0]->view.height, threads, job_row, &job);
	lx_raycaster_destroy(rc);
	return true;
}

bool lx_reference_image_shaded(const struct lx_frame *f, const struct lx_image *light_image, int16_t *object,
				uint8_t *shadowed, uint8_t *rgba, int threads)
{
	return lx_reference_lights(&f, &light_image, 1, object, &shadowed, rgba, threads);
}

bool lx_reference_image(const struct lx_frame *f, int16_t *object, uint8_t *shadowed, int threads)
{
	return lx_reference_image_shaded(f, NULL, object, shadowed, NULL, threads);
}
