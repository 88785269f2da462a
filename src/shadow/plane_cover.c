/* What a plane of interest's lit front shadows (plane_cover.h). */
#include "plane_cover.h"
#include "plane_optimal.h"
#include <math.h>

/* Row r of m: h_r = a . (X, 1). */
static void set_row(mat4 *m, int r, vec4 a)
{
	m->m[r] = a.x, m->m[4 + r] = a.y, m->m[8 + r] = a.z, m->m[12 + r] = a.w;
}

/* The cover matrix of parallelogram c + s e1 + t e2 (s, t in [0, 1]), lit on the side
 * e1 x e2 points to (lx_plane_cover_matrix). */
static bool front_matrix(const struct lx_light *light, vec3 c, vec3 e1, vec3 e2, mat4 *out)
{
	vec3 n = v3_cross(e1, e2);
	double nn = v3_dot(n, n), size = v3_len(e1) + v3_len(e2);
	if (!(nn > 0))
		return false; /* no parallelogram (the scene parser refuses one; a box has none flat) */
	/* pi . L: the light's distance in front of the plane, or a directional light's cosine */
	vec3 un = v3_scale(n, 1 / sqrt(nn)); /* nn > 0 */
	vec4 pi = {un.x, un.y, un.z, -v3_dot(un, c)}, L = lx_light_point(light);
	vec3 lv = v3(L.x, L.y, L.z);
	double k = v4_dot(pi, L), reach = L.w != 0 ? v3_len(v3_sub(lv, c)) + size : v3_len(lv);
	if (!(k > LX_COVER_GRAZING * reach))
		return false; /* its back is lit, or the light lies about in it or runs along it */
	/* The light's projection onto the plane, X -> X - (pi . X / k) L (homogeneous), then
	 * the parallelogram's coordinates (the dual basis: a1 . e1 = a2 . e2 = 1, each 0 on
	 * the other edge and on n) and w: each such row r, taken through the projection, is
	 * r - (r . L / k) pi, affine in X. */
	vec3 a1 = v3_scale(v3_cross(e2, n), 1 / nn), a2 = v3_scale(v3_cross(n, e1), 1 / nn); /* nn > 0 */
	vec4 rows[3] = {{a1.x, a1.y, a1.z, -v3_dot(a1, c)}, {a2.x, a2.y, a2.z, -v3_dot(a2, c)}, {0, 0, 0, 1}};
	for (int i = 0; i < 3; i++)
		set_row(out, i, v4_lin(1, rows[i], -v4_dot(rows[i], L) / k, pi)); /* k > 0 */
	/* how far beyond the plane, in the light's distance from it (a directional light's
	 * in the parallelogram's size, > 0): LX_COVER_TOUCH is a share of either */
	double g = -1 / (L.w != 0 ? k : k * size);
	set_row(out, 3, (vec4){g * pi.x, g * pi.y, g * pi.z, g * pi.w});
	return true;
}

bool lx_plane_cover_matrix(const struct lx_frame *f, int p, mat4 *out)
{
	if (p < 0 || p >= f->scene->plane_count)
		return false;
	const struct lx_plane *pl = &f->scene->planes[p]; /* planes do not move: their offset is 0 */
	return front_matrix(&f->light, pl->corner, pl->edge1, pl->edge2, out);
}

static double v3_at(vec3 v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }
static vec3 v3_along(int a, double t) { return a == 0 ? v3(t, 0, 0) : a == 1 ? v3(0, t, 0) : v3(0, 0, t); }

/* The axis along which box [lo, hi] is flat (LX_SLAB_FLATNESS), or -1. */
static int thin_axis(vec3 lo, vec3 hi)
{
	double ext[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
	int a = ext[0] <= ext[1] && ext[0] <= ext[2] ? 0 : ext[1] <= ext[2] ? 1 : 2;
	return ext[a] * LX_SLAB_FLATNESS <= fmin(ext[(a + 1) % 3], ext[(a + 2) % 3]) ? a : -1;
}

bool lx_slab_front(const struct lx_frame *f, int id, vec3 *c, vec3 *e1, vec3 *e2)
{
	const struct lx_scene *s = f->scene;
	if (id < s->plane_count || id >= f->object_count || s->casters[id - s->plane_count].shape != LX_BOX)
		return false;
	vec3 lo = f->bmin[id], hi = f->bmax[id];
	double ext[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
	int a = thin_axis(lo, hi), b = (a + 1) % 3, d = (a + 2) % 3;
	if (a < 0)
		return false; /* not flat: its faces' tests would shadow little beyond the maps' */
	/* the broad face away from the light, facing it: e_b x e_d runs along +a */
	vec4 L = lx_light_point(&f->light);
	bool above = L.w != 0 ? v3_at(v3(L.x, L.y, L.z), a) > (v3_at(lo, a) + v3_at(hi, a)) / 2 : v3_at(v3(L.x, L.y, L.z), a) > 0;
	vec3 eb = v3_along(b, ext[b]), ed = v3_along(d, ext[d]);
	*c = above ? lo : v3_add(lo, v3_along(a, ext[a]));
	*e1 = above ? eb : ed, *e2 = above ? ed : eb;
	return true;
}

/* Whether the part of box [lo, hi] where h.w > LX_COVER_TOUCH has rays crossing inside the
 * parallelogram's bounds: that part is the box cut by the plane, whose corners are the
 * box's corners beyond it and its edges' crossings; the light's projection of it, the
 * hull of theirs (h.z >= 1 there, or 1 for a directional light). */
static bool beyond_meets(const mat4 *m, vec3 lo, vec3 hi)
{
	vec4 h[8];
	for (int k = 0; k < 8; k++) {
		h[k] = m4_mul_point(m, v3_box_corner(lo, hi, k));
		h[k].w -= LX_COVER_TOUCH; /* a box touching the plane (the floor's edge at the wall's foot) is not beyond it */
	}
	double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
	for (int a = 0; a < 8; a++)
		for (int bit = 0; bit < 4; bit++) { /* each corner alone (bit 3), each edge once */
			int b = bit < 3 ? a | 1 << bit : a;
			if (b == a && bit < 3)
				continue;
			vec4 x = h[a];
			if (b != a) {
				if ((h[a].w > 0) == (h[b].w > 0))
					continue;
				x = v4_lin(h[b].w / (h[b].w - h[a].w), h[a], h[a].w / (h[a].w - h[b].w), h[b]);
			} else if (!(x.w > 0))
				continue;
			if (!(x.z > 0))
				continue; /* cannot happen beyond the plane: h.z = 1 + h.w or 1 */
			u0 = fmin(u0, x.x / x.z), u1 = fmax(u1, x.x / x.z);
			v0 = fmin(v0, x.y / x.z), v1 = fmax(v1, x.y / x.z);
		}
	return u0 <= 1 && u1 >= 0 && v0 <= 1 && v1 >= 0;
}

bool lx_plane_cover_shadows(const mat4 *m, vec3 x)
{
	vec4 h = m4_mul_point(m, x);
	return h.w > 0 && h.x >= 0 && h.y >= 0 && h.x <= h.z && h.y <= h.z;
}

/* Object id's of[]: the lit fronts whose shadow may fall on its box, in the fronts'
 * order, LX_MAX_COVERS at most; never its own. */
static void object_covers(const struct lx_frame *f, const struct lx_plane_covers *c, int id, int *of)
{
	int n = 0;
	for (int p = 0; p < c->count && n < LX_MAX_COVERS; p++)
		if (c->owner[p] != id && c->lit[p] && beyond_meets(&c->m[p], f->bmin[id], f->bmax[id]))
			of[n++] = p;
	for (; n < LX_MAX_COVERS; n++)
		of[n] = -1;
}

/* The fronts (the planes', then the flat boxes'), of[] for objects [0, objects) (none
 * for the rest). */
static void covers_of(const struct lx_frame *f, int objects, struct lx_plane_covers *out)
{
	int np = f->scene->plane_count;
	out->count = 0;
	for (int p = 0; p < np && p < LX_MAX_FRONTS; p++) {
		lx_frame_plane_corners(f, p, out->corner[p]);
		out->owner[p] = p;
		out->lit[p] = lx_plane_cover_matrix(f, p, &out->m[p]);
		out->count++;
	}
	for (int id = np; id < f->object_count && out->count < LX_MAX_FRONTS; id++) {
		vec3 c, e1, e2;
		if (!lx_slab_front(f, id, &c, &e1, &e2))
			continue;
		int p = out->count++;
		vec3 *pc = out->corner[p];
		pc[0] = c, pc[1] = v3_add(c, e1), pc[2] = v3_add(pc[1], e2), pc[3] = v3_add(c, e2);
		out->owner[p] = id;
		out->lit[p] = front_matrix(&f->light, c, e1, e2, &out->m[p]);
	}
	for (int id = 0; id < f->object_count; id++)
		if (id < objects)
			object_covers(f, out, id, out->of[id]);
		else
			for (int n = 0; n < LX_MAX_COVERS; n++)
				out->of[id][n] = -1;
}

void lx_plane_covers(const struct lx_frame *f, struct lx_plane_covers *out) { covers_of(f, f->object_count, out); }

void lx_plane_covers_of_planes(const struct lx_frame *f, struct lx_plane_covers *out)
{
	covers_of(f, f->scene->plane_count, out);
}

int lx_plane_cover_count(const struct lx_plane_covers *c, int id)
{
	int n = 0;
	while (n < LX_MAX_COVERS && c->of[id][n] >= 0)
		n++;
	return n;
}

bool lx_plane_covers_shadow(const struct lx_plane_covers *c, int id, vec3 x)
{
	for (int k = 0; k < LX_MAX_COVERS && c->of[id][k] >= 0; k++)
		if (lx_plane_cover_shadows(&c->m[c->of[id][k]], x))
			return true;
	return false;
}

/* Whether box [lo, hi] reaches beyond lit front p, a corner of it: a superset of
 * beyond_meets, 8 products. */
static bool reaches_beyond(const struct lx_plane_covers *c, int p, vec3 lo, vec3 hi)
{
	for (int k = 0; k < 8; k++)
		if (m4_mul_point(&c->m[p], v3_box_corner(lo, hi, k)).w > LX_COVER_TOUCH)
			return true;
	return false;
}

bool lx_plane_cover_complete(const struct lx_frame *f, const struct lx_plane_covers *c, int p)
{
	if (p < 0 || p >= c->count || !c->lit[p])
		return false;
	for (int id = 0; id < f->object_count; id++) {
		/* an object beyond at most LX_MAX_COVERS fronts gets every one it needs */
		int beyond = 0;
		for (int q = 0; q < c->count; q++)
			beyond += c->owner[q] != id && c->lit[q] && reaches_beyond(c, q, f->bmin[id], f->bmax[id]);
		if (beyond <= LX_MAX_COVERS || id == c->owner[p])
			continue;
		int of[LX_MAX_COVERS];
		object_covers(f, c, id, of);
		bool tested = false;
		for (int k = 0; k < LX_MAX_COVERS; k++)
			tested |= of[k] == p;
		if (!tested && beyond_meets(&c->m[p], f->bmin[id], f->bmax[id]))
			return false;
	}
	return true;
}

void lx_slab_faces_left_out(const struct lx_frame *f, vec4 *front, bool *has)
{
	struct lx_plane_covers cv;
	lx_plane_covers_of_planes(f, &cv);
	for (int id = 0; id < f->object_count; id++)
		has[id] = false;
	for (int p = f->scene->plane_count; p < cv.count; p++) {
		int id = cv.owner[p];
		const vec3 *q = cv.corner[p];
		vec3 n, c = v3_sub(q[0], f->offset[id]); /* object space */
		if (!cv.lit[p] || !lx_plane_cover_complete(f, &cv, p) ||
		    !v3_normalize(v3_cross(v3_sub(q[1], q[0]), v3_sub(q[3], q[0])), &n))
			continue;
		front[id] = (vec4){n.x, n.y, n.z, -v3_dot(n, c)}, has[id] = true;
	}
}

bool lx_plane_cover_image(const struct lx_frame *f, const struct lx_plane_covers *cv, int p, int q,
			  struct lx_poly *win)
{
	win->n = 0;
	if (p < 0 || q < 0 || p >= cv->count || q >= f->scene->plane_count || cv->owner[p] == q)
		return false;
	const vec3 *pc = cv->corner[p];
	vec4 pi = lx_plane_equation(&f->scene->planes[q]), L = lx_light_point(&f->light);
	double k = v4_dot(pi, L);
	vec2 pts[4];
	for (int i = 0; i < 4; i++) {
		/* the corner's shadow on q's plane, X - s L with s = pi . X / k (homogeneous): past
		 * the corner from the light where 0 <= s, and s < 1 for a point light */
		vec4 x = {pc[i].x, pc[i].y, pc[i].z, 1};
		double s = v4_dot(pi, x) / k, w = 1 - s * L.w;
		if (!(s >= 0) || !(w > 1e-12) || !isfinite(s))
			return false; /* the light runs along q's plane, or the ray meets it before the corner */
		vec4 y = v4_lin(1 / w, x, -s / w, L);
		vec4 c = m4_mul_point(&f->view.view_proj, (vec3){y.x, y.y, y.z});
		if (!(c.w > 1e-9 * (fabs(c.x) + fabs(c.y) + fabs(c.z))))
			return false; /* at or behind the eye: the shadow's image is not the corners' hull */
		pts[i] = (vec2){(c.x / c.w * 0.5 + 0.5) * f->view.width, (c.y / c.w * 0.5 + 0.5) * f->view.height};
	}
	/* the corners' shadows bound the shadow (a central projection of the parallelogram,
	 * every corner in front of the light and of the eye, keeps it convex) */
	lx_poly_hull(pts, 4, win);
	return win->n >= 3;
}

int lx_scene_covers_needed(const struct lx_scene *s, const struct lx_scene_meshes *m)
{
	int n = lx_scene_object_count(s), most = 0;
	for (int id = 0; id < n && id < m->count; id++) {
		vec3 lo = m->mesh[id].bmin, hi = m->mesh[id].bmax;
		if (id >= s->plane_count) { /* its box over its bounce (lx_caster_bottom) */
			const struct lx_caster *c = &s->casters[id - s->plane_count];
			lo = v3_add(lo, v3(c->x, fmin(c->low, c->high), c->z));
			hi = v3_add(hi, v3(c->x, fmax(c->low, c->high), c->z));
		}
		int beyond = 0;
		for (int c = 0; c < s->caster_count; c++) /* a flat box's front: whichever face, any light */
			beyond += s->plane_count + c != id && s->casters[c].shape == LX_BOX &&
				  s->plane_count + c < m->count &&
				  thin_axis(m->mesh[s->plane_count + c].bmin, m->mesh[s->plane_count + c].bmax) >= 0;
		for (int p = 0; p < s->plane_count; p++) {
			const struct lx_plane *pl = &s->planes[p];
			vec3 nrm = v3_cross(pl->edge1, pl->edge2);
			double touch = LX_COVER_TOUCH * v3_len(nrm) * (v3_len(pl->edge1) + v3_len(pl->edge2));
			bool reaches = false;
			for (int k = 0; id != p && k < 8 && !reaches; k++)
				reaches = v3_dot(nrm, v3_sub(v3_box_corner(lo, hi, k), pl->corner)) < -touch;
			beyond += reaches;
		}
		most = beyond > most ? beyond : most;
	}
	return most < LX_MAX_COVERS ? most : LX_MAX_COVERS;
}
