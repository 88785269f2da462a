/* What a plane of interest's lit front shadows (plane_cover.h). */
#include "plane_cover.h"
#include "plane_optimal.h"
#include <math.h>
#include <string.h>

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
	return ext[a] * LX_SLAB_FLATNESS <= lx_fmin(ext[(a + 1) % 3], ext[(a + 2) % 3]) ? a : -1;
}

bool lx_slab_front(const struct lx_frame *f, int id, vec3 *c, vec3 *e1, vec3 *e2, vec3 *t)
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
	*t = v3_along(a, above ? ext[a] : -ext[a]);
	return true;
}

/* Whether the part of box [lo, hi] where h.w > LX_COVER_TOUCH has rays crossing the
 * plane inside r (u0, v0, u1, v1 in the parallelogram's coordinates): that part is the box
 * cut by the plane, whose corners are the box's corners beyond it and its edges'
 * crossings; the light's projection of it, the hull of theirs (h.z >= 1 there, or 1 for a
 * directional light). */
static bool beyond_meets_in(const mat4 *m, vec3 lo, vec3 hi, const double r[4])
{
	vec4 h[8];
	bool beyond = false;
	for (int k = 0; k < 8; k++) {
		h[k] = m4_mul_point(m, v3_box_corner(lo, hi, k));
		beyond |= h[k].w > LX_COVER_TOUCH;
		h[k].w -= LX_COVER_TOUCH; /* a box touching the plane (the floor's edge at the wall's foot) is not beyond it */
	}
	if (!beyond)
		return false; /* a box above a floor or a table top: the loop below would find nothing */
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
			u0 = lx_fmin(u0, x.x / x.z), u1 = lx_fmax(u1, x.x / x.z);
			v0 = lx_fmin(v0, x.y / x.z), v1 = lx_fmax(v1, x.y / x.z);
		}
	return u0 <= r[2] && u1 >= r[0] && v0 <= r[3] && v1 >= r[1];
}

/* beyond_meets_in the parallelogram's own bounds. */
static bool beyond_meets(const mat4 *m, vec3 lo, vec3 hi)
{
	static const double unit[4] = {0, 0, 1, 1};
	return beyond_meets_in(m, lo, hi, unit);
}

bool lx_plane_cover_shadows(const mat4 *m, vec3 x)
{
	vec4 h = m4_mul_point(m, x);
	return h.w > 0 && h.x >= 0 && h.y >= 0 && h.x <= h.z && h.y <= h.z;
}

static bool listed(const int *of, int n, int p)
{
	for (int k = 0; k < n; k++)
		if (of[k] == p)
			return true;
	return false;
}

/* Whether some of box [lo, hi] lies below flat box bottom p's top with rays that may pass
 * through the box: crossing the top's plane within the box's outline there (the top, and
 * the bottom's shadow on that plane: rays in and out by the thin sides included). */
static bool meets_box(const struct lx_plane_covers *c, int p, vec3 lo, vec3 hi)
{
	return c->top[p] >= 0 && beyond_meets_in(&c->m[c->top[p]], lo, hi, c->outline[p]);
}

/* Object id's of[]: the lit fronts whose shadow may fall on its box, in the fronts'
 * order, LX_MAX_COVERS at most; never its own. A flat box's bottom whose box the object's
 * rays may pass through comes with its top, where there is room for both (the pair
 * decides every such ray; the bottom alone, only those that cross it). And whether they
 * pair. */
static void object_covers(const struct lx_frame *f, const struct lx_plane_covers *c, int id, int *of, bool *paired)
{
	int n = 0;
	vec3 lo = f->bmin[id], hi = f->bmax[id];
	for (int p = 0; p < c->count && n < LX_MAX_COVERS; p++) {
		if (c->owner[p] == id || !c->lit[p] || listed(of, n, p))
			continue;
		int t = c->top[p];
		if (t >= 0 && c->owner[t] != id && (listed(of, n, t) || n + 2 <= LX_MAX_COVERS) && meets_box(c, p, lo, hi)) {
			if (!listed(of, n, t))
				of[n++] = t;
			of[n++] = p;
		} else if (beyond_meets(&c->m[p], lo, hi))
			of[n++] = p;
	}
	for (int k = n; k < LX_MAX_COVERS; k++)
		of[k] = -1;
	*paired = n == 2 && (c->top[of[1]] == of[0] || c->top[of[0]] == of[1]);
}

/* Front p: parallelogram c, e1, e2 of object `owner`, lit towards the light. */
static void set_front(struct lx_plane_covers *out, int p, int owner, const struct lx_light *light, vec3 c, vec3 e1,
		      vec3 e2)
{
	vec3 *pc = out->corner[p];
	pc[0] = c, pc[1] = v3_add(c, e1), pc[2] = v3_add(pc[1], e2), pc[3] = v3_add(c, e2);
	out->owner[p] = owner, out->top[p] = -1;
	out->lit[p] = front_matrix(light, c, e1, e2, &out->m[p]);
}

/* The lit plane front lying on a flat box's top face (bottom front c, e1, e2, thickness
 * t towards the light), or -1: its parallelogram is the top face's, moved at most
 * |t| / LX_SLAB_FLATNESS further towards the light (the table top, 1 mm over its slab).
 * Then the bottom takes that plane's corner and edges, moved down to its own plane, so
 * that the two fronts' coordinates are one (the pair's test, lx_slab_sides_shadow). */
static int plane_on_top(const struct lx_plane_covers *cv, int np, vec3 *c, vec3 *e1, vec3 *e2, vec3 t)
{
	double th = v3_len(t), tol = 1e-6 * (v3_len(*e1) + v3_len(*e2) + th); /* meshes hold floats */
	if (!(th > 0))
		return -1;
	vec3 u = v3_scale(t, 1 / th), top = v3_add(*c, t); /* th > 0 */
	vec3 face[4] = {top, v3_add(top, *e1), v3_add(v3_add(top, *e1), *e2), v3_add(top, *e2)};
	for (int q = 0; q < np; q++) {
		const vec3 *pc = cv->corner[q];
		double gap = v3_dot(v3_sub(pc[0], top), u);
		if (!cv->lit[q] || gap < -tol || gap > th / LX_SLAB_FLATNESS + tol)
			continue;
		int matched = 0;
		for (int i = 0; i < 4; i++) {
			vec3 x = v3_sub(pc[i], v3_scale(u, gap)); /* onto the top face's plane */
			for (int j = 0; j < 4; j++)
				if (v3_len(v3_sub(x, face[j])) <= tol) {
					matched++;
					break;
				}
		}
		if (matched < 4)
			continue;
		*c = v3_sub(pc[0], v3_scale(u, gap + th));
		*e1 = v3_sub(pc[1], pc[0]), *e2 = v3_sub(pc[3], pc[0]);
		return q;
	}
	return -1;
}

/* Bottom p's box as the light sees it on its top's plane, in the top's coordinates: the
 * bounds of the top (the unit square) and of the bottom's corners' shadows there (they lie
 * beyond the top: h.z >= 1). No pair where they cannot be found. */
static void box_outline(struct lx_plane_covers *c, int p)
{
	int t = c->top[p];
	double *r = c->outline[p];
	r[0] = r[1] = 0, r[2] = r[3] = 1;
	for (int k = 0; t >= 0 && k < 4; k++) {
		vec4 h = m4_mul_point(&c->m[t], c->corner[p][k]);
		if (!(h.z > 0) || !(h.w > 0)) {
			c->top[p] = -1;
			return;
		}
		r[0] = lx_fmin(r[0], h.x / h.z), r[1] = lx_fmin(r[1], h.y / h.z); /* h.z > 0 */
		r[2] = lx_fmax(r[2], h.x / h.z), r[3] = lx_fmax(r[3], h.y / h.z);
	}
}

void lx_plane_covers(const struct lx_frame *f, struct lx_plane_covers *out)
{
	int np = f->scene->plane_count;
	out->count = out->slabs = 0;
	for (int p = 0; p < np && p < LX_MAX_PLANES; p++) {
		vec3 pc[4];
		lx_frame_plane_corners(f, p, pc);
		set_front(out, p, p, &f->light, pc[0], v3_sub(pc[1], pc[0]), v3_sub(pc[3], pc[0]));
		out->count++;
	}
	vec3 thick[LX_MAX_SLAB_FRONTS];
	for (int id = np; id < f->object_count && out->slabs < LX_MAX_SLAB_FRONTS; id++) {
		vec3 c, e1, e2, t;
		if (!lx_slab_front(f, id, &c, &e1, &e2, &t))
			continue;
		int p = out->count++, on_top = plane_on_top(out, np, &c, &e1, &e2, t);
		thick[out->slabs++] = t;
		set_front(out, p, id, &f->light, c, e1, e2);
		out->top[p] = out->lit[p] ? on_top : -1;
	}
	for (int k = 0; k < out->slabs; k++) { /* the tops no plane lies on, after every bottom */
		int p = np + k;
		if (!out->lit[p] || out->top[p] >= 0)
			continue;
		const vec3 *pc = out->corner[p];
		int q = out->count++;
		set_front(out, q, out->owner[p], &f->light, v3_add(pc[0], thick[k]), v3_sub(pc[1], pc[0]),
			  v3_sub(pc[3], pc[0]));
		out->top[p] = out->lit[q] ? q : -1;
	}
	for (int p = np; p < np + out->slabs; p++) /* each pair's outline on its top's plane */
		box_outline(out, p);
	for (int id = 0; id < f->object_count; id++)
		object_covers(f, out, id, out->of[id], &out->paired[id]);
}

void lx_plane_covers_none(struct lx_plane_covers *out)
{
	out->count = out->slabs = 0;
	for (int id = 0; id < LX_MAX_PLANES + LX_MAX_CASTERS; id++) {
		for (int k = 0; k < LX_MAX_COVERS; k++)
			out->of[id][k] = -1;
		out->paired[id] = false;
	}
}

int lx_plane_cover_count(const struct lx_plane_covers *c, int id)
{
	int n = 0;
	while (n < LX_MAX_COVERS && c->of[id][n] >= 0)
		n++;
	return n;
}

static bool in_unit(double x, double y) { return x >= 0 && x <= 1 && y >= 0 && y <= 1; }

bool lx_slab_sides_shadow(const mat4 *top, const mat4 *bottom, vec3 x)
{
	vec4 hb = m4_mul_point(bottom, x), ht = m4_mul_point(top, x);
	if (!(hb.w > 0) || !(ht.w > 0) || !(hb.z > 0) || !(ht.z > 0))
		return false; /* not beyond the bottom (beyond it, h.z >= 1 for both) */
	double ax = hb.x / hb.z, ay = hb.y / hb.z, bx = ht.x / ht.z, by = ht.y / ht.z; /* z > 0 */
	if (in_unit(ax, ay) || in_unit(bx, by) || lx_fmin(ax, bx) > 1 || lx_fmax(ax, bx) < 0 || lx_fmin(ay, by) > 1 ||
	    lx_fmax(ay, by) < 0)
		return false;
	/* the square's corners on both sides of the segment's line, or on it */
	double dx = bx - ax, dy = by - ay, e0 = dy * ax - dx * ay;
	double e1 = e0 - dy, e2 = e0 + dx, e3 = e0 + dx - dy;
	return lx_fmin(lx_fmin(e0, e1), lx_fmin(e2, e3)) <= 0 && lx_fmax(lx_fmax(e0, e1), lx_fmax(e2, e3)) >= 0;
}

bool lx_plane_covers_shadow(const struct lx_plane_covers *c, int id, vec3 x)
{
	for (int k = 0; k < LX_MAX_COVERS && c->of[id][k] >= 0; k++)
		if (lx_plane_cover_shadows(&c->m[c->of[id][k]], x))
			return true;
	return c->paired[id] && lx_slab_sides_shadow(&c->m[c->of[id][0]], &c->m[c->of[id][1]], x);
}

bool lx_plane_cover_complete(const struct lx_frame *f, const struct lx_plane_covers *c, int p)
{
	if (p < 0 || p >= c->count || !c->lit[p])
		return false;
	for (int id = 0; id < f->object_count; id++)
		if (id != c->owner[p] && !listed(c->of[id], LX_MAX_COVERS, p) &&
		    beyond_meets(&c->m[p], f->bmin[id], f->bmax[id]))
			return false; /* it needs p's test and does not get it */
	return true;
}

/* Whether every object whose box reaches below bottom front p's top, with rays that can
 * pass through the box (crossing the top's plane within the bounds of the top and of the
 * bottom's shadow on that plane: the box's outline from the light, rays through its thin
 * sides included), tests the pair, and has no corner between the two faces' planes,
 * where the bottom's test is off. */
static bool pair_complete(const struct lx_frame *f, const struct lx_plane_covers *c, int p)
{
	int t = c->top[p];
	if (t < 0 || !c->lit[p] || !c->lit[t])
		return false;
	for (int id = 0; id < f->object_count; id++) {
		if (id == c->owner[p] || id == c->owner[t] || !meets_box(c, p, f->bmin[id], f->bmax[id]))
			continue;
		if (!c->paired[id] || (c->of[id][0] != p && c->of[id][1] != p))
			return false;
		for (int k = 0; k < 8; k++) {
			vec3 x = v3_box_corner(f->bmin[id], f->bmax[id], k);
			if (m4_mul_point(&c->m[p], x).w < -LX_COVER_TOUCH && m4_mul_point(&c->m[t], x).w > LX_COVER_TOUCH)
				return false;
		}
	}
	return true;
}

void lx_slab_faces_left_out(const struct lx_frame *f, const struct lx_plane_covers *cv, vec4 *front, bool *has,
			    bool *whole)
{
	for (int id = 0; id < f->object_count; id++)
		has[id] = whole[id] = false;
	int np = f->scene->plane_count;
	for (int p = np; p < np + cv->slabs; p++) {
		int id = cv->owner[p];
		const vec3 *q = cv->corner[p];
		vec3 n, c = v3_sub(q[0], f->offset[id]); /* object space */
		if (!cv->lit[p] || !lx_plane_cover_complete(f, cv, p) ||
		    !v3_normalize(v3_cross(v3_sub(q[1], q[0]), v3_sub(q[3], q[0])), &n))
			continue;
		front[id] = (vec4){n.x, n.y, n.z, -v3_dot(n, c)}, has[id] = true;
		whole[id] = pair_complete(f, cv, p);
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
		pts[i] = lx_view_window_point(&f->view, c);
	}
	/* the corners' shadows bound the shadow (a central projection of the parallelogram,
	 * every corner in front of the light and of the eye, keeps it convex) */
	lx_poly_hull(pts, 4, win);
	return win->n >= 3;
}

bool lx_plane_cover_pair_image(const struct lx_frame *f, const struct lx_plane_covers *cv, int q, struct lx_poly *img0,
			       struct lx_poly *img1, struct lx_poly *win)
{
	win->n = img0->n = img1->n = 0;
	if (q < 0 || q >= f->scene->plane_count || !cv->paired[q] ||
	    !lx_plane_cover_image(f, cv, cv->of[q][0], q, img0) || !lx_plane_cover_image(f, cv, cv->of[q][1], q, img1))
		return false;
	vec2 pts[8]; /* two quadrilaterals' corners */
	memcpy(pts, img0->v, (size_t)img0->n * sizeof(vec2));
	memcpy(pts + img0->n, img1->v, (size_t)img1->n * sizeof(vec2));
	lx_poly_hull(pts, img0->n + img1->n, win);
	return win->n >= 3;
}

int lx_scene_covers_needed(const struct lx_scene *s, const struct lx_scene_meshes *m)
{
	int n = lx_scene_object_count(s), most = 0;
	for (int id = 0; id < n && id < m->count; id++) {
		vec3 lo = m->mesh[id].bmin, hi = m->mesh[id].bmax;
		if (id >= s->plane_count) { /* its box over its bounce (lx_caster_bottom) */
			const struct lx_caster *c = &s->casters[id - s->plane_count];
			lo = v3_add(lo, v3(c->x, lx_fmin(c->low, c->high), c->z));
			hi = v3_add(hi, v3(c->x, lx_fmax(c->low, c->high), c->z));
		}
		int beyond = 0;
		for (int c = 0; c < s->caster_count; c++) /* a flat box's two fronts, any light */
			beyond += 2 * (s->plane_count + c != id && s->casters[c].shape == LX_BOX &&
				  s->plane_count + c < m->count &&
				  thin_axis(m->mesh[s->plane_count + c].bmin, m->mesh[s->plane_count + c].bmax) >= 0);
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
