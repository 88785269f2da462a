#include "lookup_region.h"
#include "convex.h"
#include "plane_optimal.h"
#include <math.h>

#define VOLUME_PLANES 7 /* a caster's six, and the eye's near plane */
#define FACE_MAX 16     /* a quad clipped by VOLUME_PLANES planes: at most 4 + 7 vertices */

bool lx_shadow_map_sees_box(const struct lx_shadow_map *map, vec3 lo, vec3 hi)
{
	int out[5] = {0, 0, 0, 0, 0}, behind = 0;
	for (int k = 0; k < 8; k++) {
		vec4 c = m4_mul_point(&map->light_clip, v3_box_corner(lo, hi, k));
		if (!(c.w > 0)) {
			behind++;
			continue;
		}
		out[0] += c.x < map->bounds[0] * c.w;
		out[1] += c.x > map->bounds[2] * c.w;
		out[2] += c.y < map->bounds[1] * c.w;
		out[3] += c.y > map->bounds[3] * c.w;
		out[4] += c.z > c.w;
	}
	if (behind == 8)
		return false;
	if (behind)
		return true; /* a box crossing the light's plane: keep it */
	for (int i = 0; i < 5; i++)
		if (out[i] == 8)
			return false;
	return true;
}

/* Row r of a matrix: the plane r . (x, y, z, 1) on world points. */
static vec4 row(const mat4 *m, int r) { return (vec4){m->m[r], m->m[4 + r], m->m[8 + r], m->m[12 + r]}; }

/* a p + b q */
static vec4 lin(double a, vec4 p, double b, vec4 q)
{
	return (vec4){a * p.x + b * q.x, a * p.y + b * q.y, a * p.z + b * q.z, a * p.w + b * q.w};
}

/* Adds the half-space p . (x, y, z, 1) >= 0 scaled to a unit normal. One without a
 * normal holds everywhere or nowhere (an orthographic map's w = 1): false when nowhere.
 * One that is not finite is left out, which only makes the volume larger. */
static bool add_plane(vec4 *pl, int *n, vec4 p)
{
	double len = sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
	if (!isfinite(len) || !isfinite(p.w))
		return true;
	if (!(len > 1e-12 * fabs(p.w)))
		return p.w >= 0;
	pl[(*n)++] = (vec4){p.x / len, p.y / len, p.z / len, p.w / len};
	return true;
}

/* A plane of interest is one quad, drawn into a map only where its back faces the
 * light (the pass culls front faces): true when the map sees its front side only. */
static bool plane_culled(const struct lx_shadow_map *map, const struct lx_frame *f, int id)
{
	const struct lx_plane *p = &f->scene->planes[id];
	vec3 q[3] = {p->corner, v3_add(p->corner, p->edge1), v3_add(v3_add(p->corner, p->edge1), p->edge2)};
	double x[3], y[3];
	for (int k = 0; k < 3; k++) {
		vec4 c = m4_mul_point(&map->light_clip, v3_add(q[k], f->offset[id]));
		if (!(c.w > 0))
			return false;
		x[k] = c.x / c.w, y[k] = c.y / c.w;
	}
	double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
	double scale = fabs(x[1] - x[0]) + fabs(x[2] - x[0]) + fabs(y[1] - y[0]) + fabs(y[2] - y[0]);
	return area > 1e-6 * scale * scale; /* counter-clockwise by a clear margin: a front face */
}

bool lx_shadow_map_draws(const struct lx_shadow_map *map, const struct lx_frame *f, int id)
{
	return lx_shadow_map_sees_box(map, f->bmin[id], f->bmax[id]) &&
	       !(id < f->scene->plane_count && plane_culled(map, f, id));
}

/* The volume where caster `id` can shadow a point through `map` (see the header), as
 * half-spaces; returns their count, or -1 when it shadows nothing there. */
static int caster_volume(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_map *map,
			 int id, double margin, vec4 *pl)
{
	vec3 lo = f->bmin[id], hi = f->bmax[id];
	if (!lx_shadow_map_draws(map, f, id))
		return -1;
	const mat4 *m = &map->light_clip;
	vec4 r0 = row(m, 0), r1 = row(m, 1), r2 = row(m, 2), r3 = row(m, 3);
	int n = 0;
	double x0 = INFINITY, y0 = INFINITY, z0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
	for (int k = 0; k < 8; k++) {
		vec4 c = m4_mul_point(m, v3_box_corner(lo, hi, k));
		if (!(c.w > 0) || !isfinite(c.x + c.y + c.z + c.w)) /* it reaches the light's plane */
			return add_plane(pl, &n, r3) ? n : -1;
		x0 = fmin(x0, c.x / c.w), x1 = fmax(x1, c.x / c.w);
		y0 = fmin(y0, c.y / c.w), y1 = fmax(y1, c.y / c.w);
		z0 = fmin(z0, c.z / c.w);
	}
	/* the caster's image and the rays the map serves; regions are at least 1 lixel */
	const struct lx_region *g = &atlas->regions[map->region];
	double ex = margin * 2.0 / (g->w > 1 ? g->w : 1);
	double ey = margin * 2.0 / (g->h > 1 ? g->h : 1);
	x0 = fmax(x0, map->bounds[0]) - ex, x1 = fmin(x1, map->bounds[2]) + ex;
	y0 = fmax(y0, map->bounds[1]) - ey, y1 = fmin(y1, map->bounds[3]) + ey;
	if (!(x0 <= x1 && y0 <= y1))
		return -1;
	/* depth: a few 11-bit codes nearer, for the mediump path's rounding */
	z0 -= 0.01;
	/* x >= x0 w, x <= x1 w, the same in y, z >= z0 w, w >= 0 */
	vec4 h[6] = {lin(1, r0, -x0, r3), lin(x1, r3, -1, r0), lin(1, r1, -y0, r3), lin(y1, r3, -1, r1),
		     lin(1, r2, -z0, r3), r3};
	for (int i = 0; i < 6; i++)
		if (!add_plane(pl, &n, h[i]))
			return -1;
	return n;
}

/* Sutherland-Hodgman: the part of a convex polygon inside a half-space. */
static int clip(const vec3 *in, int n, vec4 p, vec3 *out)
{
	int m = 0;
	for (int i = 0; i < n; i++) {
		vec3 a = in[i], b = in[(i + 1) % n];
		double da = p.x * a.x + p.y * a.y + p.z * a.z + p.w, db = p.x * b.x + p.y * b.y + p.z * b.z + p.w;
		if (da >= 0 && m < FACE_MAX)
			out[m++] = a;
		if ((da >= 0) != (db >= 0) && m < FACE_MAX) /* signs differ: da - db != 0 */
			out[m++] = v3_add(a, v3_scale(v3_sub(b, a), da / (da - db)));
	}
	return m;
}

/* Grows a window bounding box (x0, y0, x1, y1) by a world point in front of the eye. */
static void extend(const struct lx_view *v, vec3 p, double *bb)
{
	vec4 c = m4_mul_point(&v->view_proj, p);
	if (!(c.w > 0)) { /* on the eye's plane (rounding at the near clip): everything */
		bb[0] = bb[1] = -INFINITY, bb[2] = bb[3] = INFINITY;
		return;
	}
	double x = (c.x / c.w + 1) * 0.5 * v->width, y = (c.y / c.w + 1) * 0.5 * v->height;
	bb[0] = fmin(bb[0], x), bb[1] = fmin(bb[1], y);
	bb[2] = fmax(bb[2], x), bb[3] = fmax(bb[3], y);
}

/* The window box of (receiver object) n (volume): the vertices of an intersection of two
 * convex sets lie on a face of one inside the other, so the receiver's faces clipped by
 * the volume, and for a solid receiver the volume's own vertices inside its box. */
static void receiver_in_volume(const struct lx_frame *f, int id, const vec4 *pl, int np, double *bb)
{
	vec3 face[6][4];
	int faces;
	bool solid = id >= f->scene->plane_count;
	if (!solid) {
		const struct lx_plane *p = &f->scene->planes[id];
		vec3 c = v3_add(p->corner, f->offset[id]);
		face[0][0] = c, face[0][1] = v3_add(c, p->edge1);
		face[0][2] = v3_add(face[0][1], p->edge2), face[0][3] = v3_add(c, p->edge2);
		faces = 1;
	} else {
		static const int q[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
		for (int k = 0; k < 6; k++)
			for (int i = 0; i < 4; i++)
				face[k][i] = v3_box_corner(f->bmin[id], f->bmax[id], q[k][i]);
		faces = 6;
	}
	for (int k = 0; k < faces; k++) {
		vec3 a[FACE_MAX], b[FACE_MAX];
		int n = 4;
		for (int i = 0; i < 4; i++)
			a[i] = face[k][i];
		for (int j = 0; j < np && n > 0; j++) {
			n = clip(a, n, pl[j], b);
			for (int i = 0; i < n; i++)
				a[i] = b[i];
		}
		for (int i = 0; i < n; i++)
			extend(&f->view, a[i], bb);
	}
	if (!solid)
		return;
	vec3 corner[64];
	int nc = lx_halfspace_vertices(pl, np, corner, 64);
	vec3 lo = f->bmin[id], hi = f->bmax[id];
	double tol = 1e-9 * (fabs(lo.x) + fabs(lo.y) + fabs(lo.z) + fabs(hi.x) + fabs(hi.y) + fabs(hi.z));
	for (int i = 0; i < nc; i++) {
		vec3 c = corner[i];
		if (c.x >= lo.x - tol && c.y >= lo.y - tol && c.z >= lo.z - tol && c.x <= hi.x + tol && c.y <= hi.y + tol &&
		    c.z <= hi.z + tol)
			extend(&f->view, c, bb);
	}
}

static long area(struct lx_rect r) { return (long)(r.x1 - r.x0) * (r.y1 - r.y0); }

static struct lx_rect hull(struct lx_rect a, struct lx_rect b)
{
	return (struct lx_rect){a.x0 < b.x0 ? a.x0 : b.x0, a.y0 < b.y0 ? a.y0 : b.y0, a.x1 > b.x1 ? a.x1 : b.x1,
				a.y1 > b.y1 ? a.y1 : b.y1};
}

/* Merges rectangles that overlap or touch, then the pair that grows least, until at most
 * LX_LOOKUP_MAX_RECTS are left. */
static int merge(struct lx_rect *r, int n)
{
	for (bool again = true; again;) {
		again = false;
		for (int i = 0; i < n && !again; i++)
			for (int j = i + 1; j < n && !again; j++)
				if (r[i].x0 <= r[j].x1 && r[j].x0 <= r[i].x1 && r[i].y0 <= r[j].y1 && r[j].y0 <= r[i].y1) {
					r[i] = hull(r[i], r[j]);
					r[j] = r[--n];
					again = true;
				}
	}
	while (n > LX_LOOKUP_MAX_RECTS) {
		int bi = 0, bj = 1;
		long best = -1;
		for (int i = 0; i < n; i++)
			for (int j = i + 1; j < n; j++) {
				long grow = area(hull(r[i], r[j])) - area(r[i]) - area(r[j]);
				if (best < 0 || grow < best)
					best = grow, bi = i, bj = j;
			}
		r[bi] = hull(r[bi], r[bj]);
		r[bj] = r[--n];
	}
	return n;
}

int lx_lookup_rects(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
		    int receiver, unsigned mask, struct lx_rect within, double margin_lixels, struct lx_rect *out)
{
	struct lx_rect r[LX_MAX_MAPS * (LX_MAX_PLANES + LX_MAX_CASTERS)];
	int n = 0;
	vec4 near = lin(1, row(&f->view.view_proj, 2), 1, row(&f->view.view_proj, 3)); /* z + w >= 0 */
	for (int m = 0; m < res->map_count && m < LX_MAX_MAPS; m++) {
		const struct lx_shadow_map *map = &res->maps[m];
		if (!(mask & 1u << m) || !map->rendered)
			continue;
		for (int c = 0; c < f->object_count; c++) {
			vec4 pl[VOLUME_PLANES];
			int np = caster_volume(f, atlas, map, c, margin_lixels, pl);
			if (np < 0 || !add_plane(pl, &np, near))
				continue;
			double bb[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
			receiver_in_volume(f, receiver, pl, np, bb);
			if (!(bb[2] >= bb[0]) || !(bb[3] >= bb[1]))
				continue; /* the receiver is outside the volume */
			/* whole pixels whose centres may lie in the box, and one more for rounding */
			struct lx_rect q = within;
			if (bb[0] > within.x0)
				q.x0 = (int)fmin(floor(bb[0]) - 1, within.x1);
			if (bb[1] > within.y0)
				q.y0 = (int)fmin(floor(bb[1]) - 1, within.y1);
			if (bb[2] < within.x1)
				q.x1 = (int)fmax(ceil(bb[2]) + 1, within.x0);
			if (bb[3] < within.y1)
				q.y1 = (int)fmax(ceil(bb[3]) + 1, within.y0);
			q.x0 = q.x0 < within.x0 ? within.x0 : q.x0, q.y0 = q.y0 < within.y0 ? within.y0 : q.y0;
			q.x1 = q.x1 > within.x1 ? within.x1 : q.x1, q.y1 = q.y1 > within.y1 ? within.y1 : q.y1;
			if (q.x1 > q.x0 && q.y1 > q.y0)
				r[n++] = q;
		}
	}
	n = merge(r, n);
	for (int i = 0; i < n; i++)
		out[i] = r[i];
	return n;
}

int lx_plane_in_window(const struct lx_frame *f, int id, struct lx_rect box, vec3 *out)
{
	const struct lx_plane *p = &f->scene->planes[id];
	const struct lx_view *v = &f->view;
	vec3 a[FACE_MAX], b[FACE_MAX];
	int n = 4;
	a[0] = v3_add(p->corner, f->offset[id]);
	a[1] = v3_add(a[0], p->edge1), a[2] = v3_add(a[1], p->edge2), a[3] = v3_add(a[0], p->edge2);
	/* window x >= x0: ndc x >= 2 x0 / width - 1, i.e. x - (that) w >= 0; and so on */
	vec4 r0 = row(&v->view_proj, 0), r1 = row(&v->view_proj, 1), r2 = row(&v->view_proj, 2),
	     r3 = row(&v->view_proj, 3);
	double x0 = 2.0 * box.x0 / v->width - 1, x1 = 2.0 * box.x1 / v->width - 1;
	double y0 = 2.0 * box.y0 / v->height - 1, y1 = 2.0 * box.y1 / v->height - 1;
	vec4 pl[5] = {lin(1, r0, -x0, r3), lin(x1, r3, -1, r0), lin(1, r1, -y0, r3), lin(y1, r3, -1, r1),
		      lin(1, r2, 2, r3)}; /* z >= -2 w: between the eye and the near plane (z = -w) */
	for (int j = 0; j < 5 && n > 0; j++) {
		n = clip(a, n, pl[j], b);
		for (int i = 0; i < n; i++)
			a[i] = b[i];
	}
	for (int i = 0; i < n && i < LX_WINDOW_POLY_MAX; i++)
		out[i] = a[i];
	return n < LX_WINDOW_POLY_MAX ? n : LX_WINDOW_POLY_MAX;
}

unsigned lx_lookup_maps(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
			int receiver, unsigned mask, double margin_lixels)
{
	/* the receiver's part in view: its box clipped to the view frustum */
	vec3 fc[8], pts[LX_CONVEX_MAX_POINTS];
	static const double cx[4] = {-1, 1, 1, -1}, cy[4] = {-1, -1, 1, 1};
	for (int i = 0; i < 8; i++) {
		vec4 p = m4_mul_v4(&f->view.inv_view_proj, (vec4){cx[i % 4], cy[i % 4], i < 4 ? -1 : 1, 1});
		fc[i] = v3(p.x / p.w, p.y / p.w, p.z / p.w); /* w > 0 for a valid perspective frustum */
	}
	int np = lx_frustum_box_points(fc, f->bmin[receiver], f->bmax[receiver], pts, LX_CONVEX_MAX_POINTS);
	if (np == 0)
		return 0; /* not in view */
	unsigned out = 0;
	for (int m = 0; m < res->map_count && m < LX_MAX_MAPS; m++) {
		const struct lx_shadow_map *map = &res->maps[m];
		if (!(mask & 1u << m))
			continue;
		/* inside by a margin the shader's rounding cannot cross (regions >= 1 lixel) */
		const struct lx_region *g = &atlas->regions[map->region];
		double tx = margin_lixels * 2.0 / (g->w > 1 ? g->w : 1), ty = margin_lixels * 2.0 / (g->h > 1 ? g->h : 1);
		int behind = 0, all_in = 0, out_side[4] = {0, 0, 0, 0};
		for (int k = 0; k < np; k++) {
			vec4 c = m4_mul_point(&map->light_clip, pts[k]);
			if (!(c.w > 0)) {
				behind++;
				continue;
			}
			double x = c.x / c.w, y = c.y / c.w;
			all_in += x >= map->bounds[0] + tx && y >= map->bounds[1] + ty && x < map->bounds[2] - tx &&
				  y < map->bounds[3] - ty;
			out_side[0] += x < map->bounds[0] - tx, out_side[1] += y < map->bounds[1] - ty;
			out_side[2] += x >= map->bounds[2] + tx, out_side[3] += y >= map->bounds[3] + ty;
		}
		if (behind == np || (!behind && (out_side[0] == np || out_side[1] == np || out_side[2] == np ||
						   out_side[3] == np)))
			continue; /* serves no point of it */
		out |= 1u << m;
		if (all_in == np)
			break; /* serves every point of it: the later maps are never read */
	}
	return out;
}
