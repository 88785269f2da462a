#include "lookup_region.h"
#include "convex.h"
#include "polygon2d.h"
#include "plane_optimal.h"
#include <math.h>
#include <string.h>

#define VOLUME_PLANES LX_LOOKUP_VOLUME_PLANES
#define FACE_MAX 31 /* a quad clipped by VOLUME_PLANES planes: at most 4 + 26 vertices */
#define MAX_DIRECTIONS 10 /* a caster's image bounded in as many directions (image_directions) */

/* A box's six faces, -x, +x, -y, +y, -z, +z, as v3_box_corner's corners, each wound as a
 * box caster's mesh winds it (counter-clockwise seen from outside, mesh.c), so that a
 * shadow pass's culling can be told from its image. */
static const int box_faces[6][4] = {{0, 4, 6, 2}, {5, 1, 3, 7}, {0, 1, 5, 4}, {6, 7, 3, 2}, {1, 0, 2, 3}, {4, 5, 7, 6}};

/* Whether object id is a box caster, its mesh its box's six faces. */
static bool box_caster(const struct lx_frame *f, int id)
{
	return id >= f->scene->plane_count && f->scene->casters[id - f->scene->plane_count].shape == LX_BOX;
}

static double coordinate(vec3 v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }

/* Whether the light shines on face k (box_faces' order) of box [lo, hi]: its point lies
 * strictly on the face's outer side (a directional light's travels into it). A face in a
 * plane through the light is turned away, as sort_by_facing and the shadow rule have it;
 * over a flat face the answer is one. */
static bool box_face_lit(const struct lx_light *l, vec3 lo, vec3 hi, int k)
{
	int axis = k / 2;
	if (l->directional) {
		double to = -coordinate(l->direction, axis);
		return k % 2 ? to > 0 : to < 0;
	}
	double at = coordinate(l->position, axis);
	return k % 2 ? at > coordinate(hi, axis) : at < coordinate(lo, axis);
}

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
 * light (the pass culls front faces): true when the map sees its front side only. Its
 * first triangle's winding in the map, when in front of the light; else which side of it
 * the light is on (lx_shadow_fix_winding makes faces turned to the light wind
 * counter-clockwise, and the part behind the light is clipped). */
static bool plane_culled(const struct lx_shadow_map *map, const struct lx_frame *f, int id)
{
	const struct lx_plane *p = &f->scene->planes[id];
	vec3 q[3] = {p->corner, v3_add(p->corner, p->edge1), v3_add(v3_add(p->corner, p->edge1), p->edge2)};
	double x[3], y[3];
	bool front = true;
	for (int k = 0; k < 3 && front; k++) {
		vec4 c = m4_mul_point(&map->light_clip, v3_add(q[k], f->offset[id]));
		front = c.w > 0;
		x[k] = c.x / c.w, y[k] = c.y / c.w;
	}
	if (front) {
		double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
		double scale = fabs(x[1] - x[0]) + fabs(x[2] - x[0]) + fabs(y[1] - y[0]) + fabs(y[2] - y[0]);
		/* counter-clockwise by a clear margin: a front face; near zero: edge-on to the
		 * light, a sliver in the map that can hide only points of its own plane, which
		 * the light grazes (drawing it would scatter false shadows along its line) */
		return area > -1e-6 * scale * scale;
	}
	vec3 n = v3_cross(p->edge1, p->edge2); /* the quad's front side (mesh.c's winding) */
	const struct lx_light *l = &f->light;
	vec3 to_light = l->directional ? v3_scale(l->direction, -1) : v3_sub(l->position, v3_add(q[0], f->offset[id]));
	double len = v3_len(n) * v3_len(to_light);
	return v3_dot(n, to_light) > -1e-6 * len; /* the light on the front side, or edge-on */
}

bool lx_shadow_map_draws(const struct lx_shadow_map *map, const struct lx_frame *f, int id)
{
	return lx_shadow_map_sees_box(map, f->bmin[id], f->bmax[id]) &&
	       !(id < f->scene->plane_count && plane_culled(map, f, id));
}

/* The range of (N . X) / (D . X) over a sphere (centre c, radius r) in front of D's
 * plane, from the planes N - k D tangent to it: ((N - k D) . c)^2 = r^2 |n - k d|^2, a
 * quadratic in k whose roots are the two extremes. False when the sphere reaches D's
 * plane or rounding leaves no real root. */
static bool sphere_range(vec4 nn, vec4 dd, vec3 c, double r, double *lo, double *hi)
{
	double a = nn.x * c.x + nn.y * c.y + nn.z * c.z + nn.w, b = dd.x * c.x + dd.y * c.y + dd.z * c.z + dd.w;
	double n2 = nn.x * nn.x + nn.y * nn.y + nn.z * nn.z, d2 = dd.x * dd.x + dd.y * dd.y + dd.z * dd.z;
	double nd = nn.x * dd.x + nn.y * dd.y + nn.z * dd.z;
	double qa = b * b - r * r * d2, qb = a * b - r * r * nd, qc = a * a - r * r * n2;
	if (!(b > 0) || !(qa > 1e-12 * b * b)) /* the sphere reaches the plane w = 0 */
		return false;
	double disc = qb * qb - qa * qc;
	if (!(disc >= 0) || !isfinite(disc))
		return false;
	double sq = sqrt(disc); /* disc >= 0 */
	*lo = (qb - sq) / qa, *hi = (qb + sq) / qa; /* qa > 0 */
	return *lo <= *hi;
}

/* Narrows b0 and b1 (the image's bounds in nd directions, coef as image_directions gives
 * them) to caster id's outline (lx_frame_object_outline), when all of it lies in front of
 * the light. */
static void outline_bounds(const struct lx_frame *f, const mat4 *m, int id, const double (*coef)[2], int nd,
			   double *b0, double *b1)
{
	vec3 x[LX_OUTLINE_POINTS];
	int n = lx_frame_object_outline(f, id, true, x);
	double t0[MAX_DIRECTIONS], t1[MAX_DIRECTIONS];
	for (int d = 0; d < nd; d++)
		t0[d] = INFINITY, t1[d] = -INFINITY;
	for (int k = 0; k < n; k++) {
		vec4 c = m4_mul_point(m, x[k]);
		if (!(c.w > 0) || !isfinite(c.x + c.y))
			return; /* reaches behind the light: the box's bounds stand */
		double u = c.x / c.w, v = c.y / c.w;
		for (int d = 0; d < nd; d++) {
			double p = coef[d][0] * u + coef[d][1] * v;
			t0[d] = lx_fmin(t0[d], p), t1[d] = lx_fmax(t1[d], p);
		}
	}
	for (int d = 0; d < nd; d++)
		b0[d] = lx_fmax(b0[d], t0[d]), b1[d] = lx_fmin(b1[d], t1[d]);
}

/* The directions an image is bounded in, as coefficients of its x and y: x, y, x + y and
 * x - y (an octagon), for a caster (`caster`) those halfway between too (a 16-gon: in a
 * plane map a caster's image is its shadow as the screen sees it, often long and at a
 * slant, which the octagon bounded loosely; at 1920x1080 plane-optimal's lookups fell
 * from 8.18% of the pixels to 4.72% under the light near the wall, from 8.80% to 7.64%
 * under the light facing the camera), and where the image of the n points c (clip
 * coordinates, w > 0) is long and thin, its long axis and the one across it too: a
 * shadow cast low, often at a slant. Returns their count. */
#define LONG_THIN 4.0 /* the ratio of the points' variances along and across the long axis */
static int image_directions(const vec4 *c, int n, bool caster, double (*coef)[2])
{
	static const double sixteen[8][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}, /* and at tan(pi / 8): */
					     {1, 0.41421356237309503}, {0.41421356237309503, 1},
					     {-0.41421356237309503, 1}, {1, -0.41421356237309503}};
	int nd = caster ? 8 : 4;
	memcpy(coef, sixteen, (size_t)nd * sizeof sixteen[0]);
	if (n < 2)
		return nd;
	double mx = 0, my = 0, sxx = 0, syy = 0, sxy = 0;
	for (int k = 0; k < n; k++)
		mx += c[k].x / c[k].w, my += c[k].y / c[k].w;
	mx /= n, my /= n; /* n >= 2 */
	for (int k = 0; k < n; k++) {
		double dx = c[k].x / c[k].w - mx, dy = c[k].y / c[k].w - my;
		sxx += dx * dx, syy += dy * dy, sxy += dx * dy;
	}
	/* the covariance's eigenvalues, half +- root, and its long axis's angle */
	double half = 0.5 * (sxx + syy), root = sqrt(0.25 * (sxx - syy) * (sxx - syy) + sxy * sxy);
	if (!(half + root > LONG_THIN * (half - root)) || !isfinite(half + root))
		return nd;
	double a = 0.5 * atan2(2 * sxy, sxx - syy), ca = cos(a), sa = sin(a);
	coef[nd][0] = ca, coef[nd][1] = sa, coef[nd + 1][0] = -sa, coef[nd + 1][1] = ca;
	return nd + 2;
}

/* The box [lo, hi]'s part inside the rays `map` serves (its bounds), as the map's clip
 * coordinates of its vertices: the box's faces clipped by the four sides, every vertex
 * in front of the light (the sides meet only at the light). Returns the count (0: no
 * part), or -1 when a vertex is not in front (the light inside the box). */
#define SERVED_POINTS (6 * FACE_MAX)
static int served_points(const struct lx_shadow_map *map, vec3 lo, vec3 hi, vec4 *out)
{
	const mat4 *m = &map->light_clip;
	vec4 r0 = m4_row(m, 0), r1 = m4_row(m, 1), r3 = m4_row(m, 3);
	const double *b = map->bounds;
	vec4 side[4] = {v4_lin(1, r0, -b[0], r3), v4_lin(b[2], r3, -1, r0), v4_lin(1, r1, -b[1], r3),
			v4_lin(b[3], r3, -1, r1)};
	int count = 0;
	for (int k = 0; k < 6; k++) {
		vec3 a[FACE_MAX], t[FACE_MAX];
		int n = 4;
		for (int i = 0; i < 4; i++)
			a[i] = v3_box_corner(lo, hi, box_faces[k][i]);
		for (int j = 0; j < 4 && n > 0; j++) {
			n = lx_clip_polygon(a, n, side[j], t, FACE_MAX);
			for (int i = 0; i < n; i++)
				a[i] = t[i];
		}
		for (int i = 0; i < n; i++) {
			vec4 q = m4_mul_point(m, a[i]);
			if (!(q.w > 0) || !isfinite(q.x + q.y + q.z))
				return -1;
			out[count++] = q; /* at most 6 * FACE_MAX */
		}
	}
	return count;
}

/* The image's bounds b0 <= (x, y) . coef[d] <= b1 in each of nd directions and its
 * nearest depth z0, from n points (clip coordinates). With `crosses` the points are a
 * box's 8 corners, some behind the light: where its edges cross the light's plane (w = 0)
 * they are points at infinity in the image, and a bound that such a point exceeds is no
 * bound (-/+ infinity). */
static void image_bounds(const vec4 *c, int n, bool crosses, const double (*coef)[2], int nd, double *b0, double *b1,
			 double *z0)
{
	*z0 = INFINITY;
	for (int d = 0; d < nd; d++)
		b0[d] = INFINITY, b1[d] = -INFINITY;
	for (int k = 0; k < n; k++) {
		if (!(c[k].w > 0))
			continue;
		double x = c[k].x / c[k].w, y = c[k].y / c[k].w; /* w > 0 */
		for (int d = 0; d < nd; d++) {
			double v = coef[d][0] * x + coef[d][1] * y;
			b0[d] = lx_fmin(b0[d], v), b1[d] = lx_fmax(b1[d], v);
		}
		*z0 = lx_fmin(*z0, c[k].z / c[k].w);
	}
	if (!crosses)
		return;
	for (int k = 0; k < 8; k++)
		for (int bit = 1; bit < 8; bit <<= 1) { /* the 12 edges: corners k and k | bit */
			int j = k | bit;
			if (j == k || (c[k].w > 0) == (c[j].w > 0))
				continue;
			double t = c[k].w / (c[k].w - c[j].w); /* signs differ: no zero division */
			double x = c[k].x + t * (c[j].x - c[k].x), y = c[k].y + t * (c[j].y - c[k].y);
			double z = c[k].z + t * (c[j].z - c[k].z);
			for (int d = 0; d < nd; d++) {
				double v = coef[d][0] * x + coef[d][1] * y;
				if (v < 0)
					b0[d] = -INFINITY;
				if (v > 0)
					b1[d] = INFINITY;
			}
			if (z < 0)
				*z0 = -INFINITY;
		}
}

/* The nearest depth of the faces of box caster [lo, hi] that a shadow pass draws into a
 * map (c: its corners' clip coordinates, every w > 0). The pass keeps a face unless its
 * plane lies clearly on the side of the map's centre of projection that winds its image
 * counter-clockwise, which the GL culls (keep_back_faces' rule: second-depth maps), so a
 * lixel of the caster holds a depth of one of the others, no nearer than their nearest
 * corner (z / w over a flat face is least at a corner). */
static double drawn_faces_depth(const mat4 *m, vec3 lo, vec3 hi, const vec4 *c)
{
	vec4 centre = v4_cross3(m4_row(m, 0), m4_row(m, 1), m4_row(m, 3));
	double tolerance = 1e-2 * v4_len(centre), z0 = INFINITY;
	for (int k = 0; k < 6; k++) {
		const int *q = box_faces[k];
		vec3 a = v3_box_corner(lo, hi, q[0]), b = v3_box_corner(lo, hi, q[1]), d = v3_box_corner(lo, hi, q[2]);
		vec4 plane = v4_cross3((vec4){a.x, a.y, a.z, 1}, (vec4){b.x, b.y, b.z, 1}, (vec4){d.x, d.y, d.z, 1});
		double len = v4_len(plane);
		if (len > 0 && !(v4_dot(centre, plane) / len < tolerance))
			continue; /* culled */
		for (int i = 0; i < 4; i++)
			z0 = lx_fmin(z0, c[q[i]].z / c[q[i]].w);
	}
	return z0;
}

/* Box caster [lo, hi]'s faces the light shines on, as the half-spaces on their inner
 * sides (lx_box_halfspaces, in box_faces' order; each a billionth of the box's
 * coordinates out, so that a receiver in a face's plane, as the table top in the slab's
 * top, stays as it was), appended to pl (count *n). False when the box casts nowhere
 * (cannot happen: unit normals). */
static bool behind_lit_faces(const struct lx_frame *f, vec3 lo, vec3 hi, vec4 *pl, int *n)
{
	double slack = 1e-9 * (fabs(lo.x) + fabs(lo.y) + fabs(lo.z) + fabs(hi.x) + fabs(hi.y) + fabs(hi.z));
	vec4 inner[6];
	lx_box_halfspaces(lo, hi, inner);
	for (int k = 0; k < 6; k++)
		if (box_face_lit(&f->light, lo, hi, k) && !add_plane(pl, n, v4_lin(1, inner[k], slack, (vec4){0, 0, 0, 1})))
			return false;
	return true;
}

/* The volume where caster `id` can shadow a point through `map`, as half-spaces: its
 * image bounded in x, y, x + y and x - y (an octagon; a caster's a 16-gon,
 * image_directions), and along and across its long axis where it is long and thin,
 * grown by the margin and cut to the rays the map serves, swept beyond the caster's
 * nearest depth, and a box's behind its lit faces (behind_lit_faces). Returns the count,
 * or -1 when it shadows nothing there. */
static int caster_volume(const struct lx_frame *f, const struct lx_shadow_map *map, int id, const double margin[2],
			 vec4 *pl)
{
	vec3 lo = f->bmin[id], hi = f->bmax[id];
	if (!lx_shadow_map_draws(map, f, id))
		return -1;
	const mat4 *m = &map->light_clip;
	vec4 r0 = m4_row(m, 0), r1 = m4_row(m, 1), r2 = m4_row(m, 2), r3 = m4_row(m, 3);
	int n = 0;
	vec4 corner[8], served[SERVED_POINTS], *c = corner;
	bool crosses = false;
	for (int k = 0; k < 8; k++) {
		c[k] = m4_mul_point(m, v3_box_corner(lo, hi, k));
		if (!isfinite(c[k].x + c[k].y + c[k].z + c[k].w))
			return add_plane(pl, &n, r3) ? n : -1; /* no bound at all */
		crosses |= !(c[k].w > 0);
	}
	/* a box reaching behind the light: its part inside the rays served, whose image is
	 * bounded (where that fails, its corners and their points at infinity) */
	int nc = 8;
	if (crosses) {
		int k = served_points(map, lo, hi, served);
		if (k == 0)
			return -1; /* none of it in the rays served */
		if (k > 0)
			c = served, nc = k, crosses = false;
	}
	double coef[MAX_DIRECTIONS][2], b0[MAX_DIRECTIONS], b1[MAX_DIRECTIONS], z0;
	int nd = image_directions(c, crosses ? 0 : nc, id >= f->scene->plane_count,
				  coef); /* w > 0: served_points', or no crossing */
	image_bounds(c, nc, crosses, coef, nd, b0, b1, &z0);
	if (c == corner && !crosses && box_caster(f, id))
		z0 = lx_fmax(z0, drawn_faces_depth(m, lo, hi, corner)); /* its faces the pass draws: beyond its nearest */
	vec4 dir[MAX_DIRECTIONS];
	for (int d = 0; d < nd; d++)
		dir[d] = v4_lin(coef[d][0], r0, coef[d][1], r1);
	if (id >= f->scene->plane_count && f->scene->casters[id - f->scene->plane_count].shape == LX_SPHERE) {
		/* the sphere itself, not its box (its mesh lies inside it) */
		double r = f->scene->casters[id - f->scene->plane_count].size.x, l, h;
		vec3 centre = v3_add(f->offset[id], v3(0, r, 0));
		for (int d = 0; d < nd; d++)
			if (sphere_range(dir[d], r3, centre, r, &l, &h))
				b0[d] = lx_fmax(b0[d], l), b1[d] = lx_fmin(b1[d], h);
	} else if (id >= f->scene->plane_count && f->scene->casters[id - f->scene->plane_count].shape != LX_BOX)
		outline_bounds(f, m, id, coef, nd, b0, b1); /* a cylinder's or cone's octagons */
	/* grown by the margin and cut to the rays the map serves */
	double ex = margin[0], ey = margin[1];
	double grow[MAX_DIRECTIONS];
	for (int d = 0; d < nd; d++)
		grow[d] = fabs(coef[d][0]) * ex + fabs(coef[d][1]) * ey;
	b0[0] = lx_fmax(b0[0], map->bounds[0]), b1[0] = lx_fmin(b1[0], map->bounds[2]);
	b0[1] = lx_fmax(b0[1], map->bounds[1]), b1[1] = lx_fmin(b1[1], map->bounds[3]);
	for (int d = 0; d < nd; d++) {
		b0[d] -= grow[d], b1[d] += grow[d];
		if (!(b0[d] <= b1[d]))
			return -1; /* nothing of it in front of the light, or outside the rays served */
		/* N >= b0 w and N <= b1 w, where bounded */
		if ((isfinite(b0[d]) && !add_plane(pl, &n, v4_lin(1, dir[d], -b0[d], r3))) ||
		    (isfinite(b1[d]) && !add_plane(pl, &n, v4_lin(b1[d], r3, -1, dir[d]))))
			return -1;
	}
	/* depth: beyond the caster's nearest point, a few 11-bit codes nearer for the mediump
	 * path's rounding; and in front of the light */
	if ((isfinite(z0) && !add_plane(pl, &n, v4_lin(1, r2, -(z0 - 0.01), r3))) || !add_plane(pl, &n, r3))
		return -1;
	return box_caster(f, id) && !behind_lit_faces(f, lo, hi, pl, &n) ? -1 : n;
}

/* The corners of receiver object id, returns how many: a plane's quad in order (4), a
 * caster's box in v3_box_corner's order (8). */
static int receiver_corners(const struct lx_frame *f, int id, vec3 *q)
{
	if (id < f->scene->plane_count) {
		const struct lx_plane *p = &f->scene->planes[id];
		q[0] = v3_add(p->corner, f->offset[id]), q[1] = v3_add(q[0], p->edge1);
		q[2] = v3_add(q[1], p->edge2), q[3] = v3_add(q[0], p->edge2);
		return 4;
	}
	for (int k = 0; k < 8; k++)
		q[k] = v3_box_corner(f->bmin[id], f->bmax[id], k);
	return 8;
}

/* Window points of a volume, for its hull. */
struct window_points {
	int n;
	bool everything; /* a point on the eye's plane (rounding at the near clip): no bound */
	vec2 p[6 * FACE_MAX + 64];
};

static void add_point(const struct lx_view *v, vec3 q, struct window_points *w)
{
	vec4 c = m4_mul_point(&v->view_proj, q);
	double x = (c.x / c.w + 1) * 0.5 * v->width, y = (c.y / c.w + 1) * 0.5 * v->height;
	if (!(c.w > 0) || !isfinite(x) || !isfinite(y))
		w->everything = true;
	else if (w->n < (int)(sizeof w->p / sizeof w->p[0]))
		w->p[w->n++] = (vec2){x, y};
}

/* The window points of (receiver object id) n (volume): the vertices of an intersection
 * of two convex sets lie on a face of one inside the other, so the receiver's faces
 * clipped by the volume, and for a solid receiver the volume's own vertices inside its
 * box. A box caster's faces the light does not shine on are left out, and so are those
 * vertices: the shadow rule darkens such a face whatever a map holds (a flat box's
 * shading gives it no light either), and inside the box nothing is seen. With `first`, it
 * stops at the first face that meets the volume: whether they meet is then known, and the
 * volume's vertices, the most costly part, are not needed. */
static void receiver_in_volume(const struct lx_frame *f, int id, const vec4 *pl, int np, bool first,
			       struct window_points *w)
{
	static const int quad[1][4] = {{0, 1, 2, 3}};
	vec3 corner[8], face[6][4];
	bool solid = receiver_corners(f, id, corner) == 8, box = box_caster(f, id);
	const int(*q)[4] = solid ? box_faces : quad;
	int faces = solid ? 6 : 1;
	for (int k = 0; k < faces; k++)
		for (int i = 0; i < 4; i++)
			face[k][i] = corner[q[k][i]];
	for (int k = 0; k < faces; k++) {
		if (box && !box_face_lit(&f->light, f->bmin[id], f->bmax[id], k))
			continue;
		vec3 a[FACE_MAX], b[FACE_MAX];
		int n = 4;
		for (int i = 0; i < 4; i++)
			a[i] = face[k][i];
		for (int j = 0; j < np && n > 0; j++) {
			n = lx_clip_polygon(a, n, pl[j], b, FACE_MAX);
			for (int i = 0; i < n; i++)
				a[i] = b[i];
		}
		for (int i = 0; i < n; i++)
			add_point(&f->view, a[i], w);
		if (first && (w->n > 0 || w->everything))
			return;
	}
	if (!solid || box)
		return;
	vec3 vertex[64], bounds[2] = {f->bmin[id], f->bmax[id]};
	double tol = 1e-9 * (fabs(bounds[0].x) + fabs(bounds[0].y) + fabs(bounds[0].z) + fabs(bounds[1].x) +
			     fabs(bounds[1].y) + fabs(bounds[1].z));
	int nc = lx_halfspace_vertices(pl, np, bounds, tol, vertex, 64); /* the volume's corners inside its box */
	for (int i = 0; i < nc; i++)
		add_point(&f->view, vertex[i], w);
}

void lx_lookup_prepare(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
		       double margin_lixels, struct lx_lookup_volumes *v)
{
	v->frame = f, v->res = res;
	for (int c = 0; c < f->object_count; c++)
		v->reads[c] = lx_shadow_receiver_maps(res, c);
	lx_view_frustum_corners(&f->view, v->frustum);
	vec4 near = v4_lin(1, m4_row(&f->view.view_proj, 2), 1, m4_row(&f->view.view_proj, 3)); /* z + w >= 0 */
	for (int m = 0; m < res->map_count && m < LX_MAX_MAPS; m++) {
		const struct lx_shadow_map *map = &res->maps[m];
		const struct lx_region *g = &atlas->regions[map->region]; /* regions are >= 1 lixel */
		v->margin[m][0] = margin_lixels * 2.0 / (g->w > 1 ? g->w : 1);
		v->margin[m][1] = margin_lixels * 2.0 / (g->h > 1 ? g->h : 1);
		for (int c = 0; c < f->object_count; c++) {
			int *np = &v->count[m][c];
			/* a flat box in no map (its fronts' tests decide its shadow) casts nowhere */
			*np = map->rendered && !res->slab_out[c] ? caster_volume(f, map, c, v->margin[m], v->plane[m][c]) : -1;
			if (*np >= 0 && !add_plane(v->plane[m][c], np, near))
				*np = -1;
		}
	}
}

/* Whether receiver object id may meet a volume: false only when one of its half-spaces
 * leaves every corner of the receiver's box (a plane's quad) outside, so all of it. A few
 * dot products: the test before receiver_in_volume's clipping, which costs a hundred
 * times more. */
static bool receiver_may_meet(const struct lx_frame *f, int id, const vec4 *pl, int np)
{
	vec3 q[8];
	int n = receiver_corners(f, id, q);
	for (int j = 0; j < np; j++) {
		int out = 0;
		while (out < n && v4_dot_point(pl[j], q[out]) < 0)
			out++;
		if (out == n)
			return false;
	}
	return true;
}

/* Whether receiver object id meets a volume: its faces clipped by it, up to the first
 * that meets it (a box can have corners on the inner side of every half-space and still
 * miss the volume, as the table's slab misses the ball's through the fallback map, seen
 * from close to the floor). A point on the eye's plane counts as meeting it. */
static bool receiver_meets(const struct lx_frame *f, int id, const vec4 *pl, int np)
{
	if (!receiver_may_meet(f, id, pl, np))
		return false;
	struct window_points w; /* its points are written before they are read */
	w.n = 0, w.everything = false;
	receiver_in_volume(f, id, pl, np, true, &w);
	return w.n > 0 || w.everything;
}

/* Per caster and map of `mask`, the window hull of where it can shadow the receiver;
 * returns their count, or -1 when one has no bound (the receiver reaches the eye's plane
 * inside it). */
#define MAX_HULLS (LX_MAX_MAPS * (LX_MAX_PLANES + LX_MAX_CASTERS))
static int shadow_hulls(const struct lx_lookup_volumes *v, int receiver, unsigned mask, struct lx_poly *hull)
{
	const struct lx_frame *f = v->frame;
	int n = 0;
	for (int m = 0; m < v->res->map_count && m < LX_MAX_MAPS; m++) {
		if (!(mask & 1u << m))
			continue;
		for (int c = 0; c < f->object_count && n < MAX_HULLS; c++) {
			if (v->count[m][c] < 0 || c == receiver)
				continue; /* nothing shadows itself where a lookup is drawn (lx_lookup_any) */
			if (!receiver_may_meet(f, receiver, v->plane[m][c], v->count[m][c]))
				continue; /* wholly outside the volume: no point to clip */
			struct window_points w;
			w.n = 0, w.everything = false;
			receiver_in_volume(f, receiver, v->plane[m][c], v->count[m][c], false, &w);
			if (w.everything)
				return -1;
			if (w.n > 0)
				lx_poly_hull(w.p, w.n, &hull[n++]);
		}
	}
	return n;
}

/* The x-range of a convex polygon (1 or more vertices) within y0 <= y <= y1. */
static bool band_range(const struct lx_poly *h, double y0, double y1, double *x0, double *x1)
{
	*x0 = INFINITY, *x1 = -INFINITY;
	for (int i = 0; i < h->n; i++) {
		vec2 a = h->v[i], b = h->v[lx_loop_next(i, h->n)];
		double t0 = 0, t1 = 1;
		if (b.y != a.y) { /* the part of edge ab inside the band */
			double ta = (y0 - a.y) / (b.y - a.y), tb = (y1 - a.y) / (b.y - a.y);
			t0 = lx_fmax(0, lx_fmin(ta, tb)), t1 = lx_fmin(1, lx_fmax(ta, tb));
		} else if (a.y < y0 || a.y > y1) {
			continue;
		}
		if (t0 > t1)
			continue;
		double xa = a.x + (b.x - a.x) * t0, xb = a.x + (b.x - a.x) * t1;
		*x0 = lx_fmin(*x0, lx_fmin(xa, xb)), *x1 = lx_fmax(*x1, lx_fmax(xa, xb));
	}
	return *x0 <= *x1;
}

bool lx_lookup_any(const struct lx_lookup_volumes *v, int receiver, unsigned mask)
{
	const struct lx_frame *f = v->frame;
	for (int m = 0; m < v->res->map_count && m < LX_MAX_MAPS; m++) {
		if (!(mask & 1u << m))
			continue;
		for (int c = 0; c < f->object_count; c++)
			if (v->count[m][c] >= 0 && c != receiver && receiver_meets(f, receiver, v->plane[m][c], v->count[m][c]))
				return true;
	}
	return false;
}

/* Whether box [lo, hi] has a point inside every half-space of a volume: for each, its
 * corner furthest along the half-space's normal is inside. */
static bool box_may_meet(const vec4 *pl, int np, vec3 lo, vec3 hi)
{
	for (int j = 0; j < np; j++) {
		vec3 far = v3(pl[j].x > 0 ? hi.x : lo.x, pl[j].y > 0 ? hi.y : lo.y, pl[j].z > 0 ? hi.z : lo.z);
		if (v4_dot_point(pl[j], far) < 0)
			return false;
	}
	return true;
}

bool lx_lookup_box_may_meet(const struct lx_lookup_volumes *v, int receiver, unsigned mask, vec3 lo, vec3 hi)
{
	const struct lx_frame *f = v->frame;
	for (int m = 0; m < v->res->map_count && m < LX_MAX_MAPS; m++) {
		if (!(mask & 1u << m))
			continue;
		for (int c = 0; c < f->object_count; c++)
			if (v->count[m][c] >= 0 && c != receiver && box_may_meet(v->plane[m][c], v->count[m][c], lo, hi))
				return true;
	}
	return false;
}

unsigned lx_lookup_caster_maps(const struct lx_lookup_volumes *v, int c, bool everywhere)
{
	const struct lx_frame *f = v->frame;
	if (c < 0 || c >= f->object_count)
		return 0;
	/* --lookup-region all reads c's own texels wherever c reads its maps */
	unsigned own = everywhere ? v->reads[c] : 0, out = 0;
	for (int m = 0; m < v->res->map_count && m < LX_MAX_MAPS; m++) {
		unsigned bit = 1u << m;
		if (v->count[m][c] < 0)
			continue; /* it shadows nothing through this map */
		if (own & bit) {
			out |= bit;
			continue;
		}
		for (int r = 0; r < f->object_count; r++)
			if (r != c && (v->reads[r] & bit) && receiver_meets(f, r, v->plane[m][c], v->count[m][c])) {
				out |= bit;
				break;
			}
	}
	return out;
}

/* Window rectangle v (x0, y0, x1, y1 in pixels) within the width x height window, its
 * edges on whole blocks (LX_SPAN_ALIGN), outwards or inwards: a cut inside a block
 * leaves a part-covered block on each side along the whole cut (on the default scene's
 * facing view at 1920x1080, 0.7 of the rasterizer's 85 million instructions a frame). */
static struct lx_rect window_blocks(const double v[4], int width, int height, bool outwards)
{
	double lim[4] = {width, height, width, height};
	int e[4];
	for (int k = 0; k < 4; k++) /* NaN-free: fmin and fmax take the number */
		e[k] = (int)fmax(0, fmin(lim[k], v[k]));
	if (!outwards)
		return (struct lx_rect){lx_align_up(e[0]), lx_align_up(e[1]), lx_align_down(e[2]), lx_align_down(e[3])};
	int x1 = lx_align_up(e[2]), y1 = lx_align_up(e[3]); /* past the window's edge when it is not whole blocks */
	return (struct lx_rect){lx_align_down(e[0]), lx_align_down(e[1]), x1 < width ? x1 : width,
				y1 < height ? y1 : height};
}

bool lx_map_screen_rect(const struct lx_shadow_map *map, int width, int height, struct lx_rect *out)
{
	if (!map->has_screen || !(map->screen[2] >= map->screen[0]) || !(map->screen[3] >= map->screen[1]))
		return false;
	double v[4] = {floor(map->screen[0]) - 1, floor(map->screen[1]) - 1, ceil(map->screen[2]) + 1,
		       ceil(map->screen[3]) + 1};
	*out = window_blocks(v, width, height, true);
	return true;
}

struct lx_rect lx_map_sure_rect(const struct lx_shadow_map *map, int width, int height)
{
	/* lixels per pixel along the map's axes (positive wherever a map is built) */
	double s = fmin(map->lixel_scale / map->lixel_stretch, map->lixel_scale * map->lixel_stretch);
	if (!map->screen_served || !(map->lixel_stretch > 0) || !(s > 0))
		return (struct lx_rect){0, 0, 0, 0};
	double g = 2 + 2 / s;
	double v[4] = {ceil(map->screen[0] + g), ceil(map->screen[1] + g), floor(map->screen[2] - g),
		       floor(map->screen[3] - g)};
	return window_blocks(v, width, height, false);
}

int lx_lookup_spans(const struct lx_lookup_volumes *v, int receiver, unsigned mask, struct lx_rect within,
		    struct lx_span *out, int max)
{
	if (max < 1)
		return -1;
	struct lx_poly hull[MAX_HULLS];
	int nh = shadow_hulls(v, receiver, mask, hull), n = 0;
	if (nh < 0) {
		out[0] = (struct lx_span){within, true};
		return 1;
	}
	/* bands on a fixed grid (so that the cuts move seldom as the casters do): per band
	 * the x-ranges of the hulls, whole pixels whose centres may lie inside and one more
	 * for rounding, out to whole blocks (LX_SPAN_ALIGN), merged; a band cut like the one
	 * before it extends that one */
	int prev_first = -1;
	for (int y = within.y0 - within.y0 % LX_LOOKUP_BAND; y < within.y1; y += LX_LOOKUP_BAND) {
		int y0 = y < within.y0 ? within.y0 : y, y1 = y + LX_LOOKUP_BAND > within.y1 ? within.y1 : y + LX_LOOKUP_BAND;
		int a[MAX_HULLS], b[MAX_HULLS], k = 0;
		for (int h = 0; h < nh; h++) {
			double x0, x1;
			if (!band_range(&hull[h], y0 - 1.0, y1 + 1.0, &x0, &x1))
				continue;
			/* out to whole blocks: clamped a block beyond `within` (so that a range
			 * outside it stays outside), aligned, clamped to it */
			double lo = within.x0 - LX_SPAN_ALIGN, hi = within.x1 + LX_SPAN_ALIGN;
			int i0 = lx_align_down((int)lx_fmax(lo, lx_fmin(hi, floor(x0) - 1)));
			int i1 = lx_align_up((int)lx_fmax(lo, lx_fmin(hi, ceil(x1) + 1)));
			i0 = i0 < within.x0 ? within.x0 : i0 > within.x1 ? within.x1 : i0;
			i1 = i1 < within.x0 ? within.x0 : i1 > within.x1 ? within.x1 : i1;
			if (i1 <= i0)
				continue;
			int j = k++; /* insert by start */
			for (; j > 0 && a[j - 1] > i0; j--)
				a[j] = a[j - 1], b[j] = b[j - 1];
			a[j] = i0, b[j] = i1;
		}
		/* this band's spans: the lookup ranges merged, the gaps between them without */
		struct lx_span band[2 * MAX_HULLS + 1];
		int nb = 0, x = within.x0;
		for (int i = 0; i < k; i++) {
			int lo = a[i], hi = b[i];
			while (i + 1 < k && a[i + 1] <= hi)
				hi = b[i + 1] > hi ? b[i + 1] : hi, i++;
			if (lo > x)
				band[nb++] = (struct lx_span){{x, y0, lo, y1}, false};
			band[nb++] = (struct lx_span){{lo, y0, hi, y1}, true};
			x = hi;
		}
		if (x < within.x1)
			band[nb++] = (struct lx_span){{x, y0, within.x1, y1}, false};
		bool same = prev_first >= 0 && n - prev_first == nb;
		for (int i = 0; same && i < nb; i++)
			same = out[prev_first + i].box.x0 == band[i].box.x0 && out[prev_first + i].box.x1 == band[i].box.x1 &&
			       out[prev_first + i].lookup == band[i].lookup;
		if (same) {
			for (int i = 0; i < nb; i++)
				out[prev_first + i].box.y1 = y1;
			continue;
		}
		if (n + nb + 1 > max) { /* no room (one place is always kept): the rest with a lookup */
			out[n++] = (struct lx_span){{within.x0, y0, within.x1, within.y1}, true};
			return n;
		}
		prev_first = n;
		for (int i = 0; i < nb; i++)
			out[n++] = band[i];
	}
	return n;
}

int lx_plane_in_window(const struct lx_frame *f, int id, struct lx_rect box, vec3 *out)
{
	const struct lx_view *v = &f->view;
	vec3 a[FACE_MAX], b[FACE_MAX];
	int n = 4;
	lx_frame_plane_corners(f, id, a);
	/* window x >= x0: ndc x >= 2 x0 / width - 1, i.e. x - (that) w >= 0; and so on */
	vec4 r0 = m4_row(&v->view_proj, 0), r1 = m4_row(&v->view_proj, 1), r2 = m4_row(&v->view_proj, 2),
	     r3 = m4_row(&v->view_proj, 3);
	double x0 = 2.0 * box.x0 / v->width - 1, x1 = 2.0 * box.x1 / v->width - 1;
	double y0 = 2.0 * box.y0 / v->height - 1, y1 = 2.0 * box.y1 / v->height - 1;
	vec4 pl[5] = {v4_lin(1, r0, -x0, r3), v4_lin(x1, r3, -1, r0), v4_lin(1, r1, -y0, r3), v4_lin(y1, r3, -1, r1),
		      v4_lin(1, r2, 2, r3)}; /* z >= -2 w: between the eye and the near plane (z = -w) */
	for (int j = 0; j < 5 && n > 0; j++) {
		n = lx_clip_polygon(a, n, pl[j], b, FACE_MAX);
		for (int i = 0; i < n; i++)
			a[i] = b[i];
	}
	for (int i = 0; i < n && i < LX_WINDOW_POLY_MAX; i++)
		out[i] = a[i];
	return n < LX_WINDOW_POLY_MAX ? n : LX_WINDOW_POLY_MAX;
}

void lx_plane_window(const struct lx_frame *f, int id, struct lx_poly *out)
{
	const struct lx_view *v = &f->view;
	vec3 a[4], b[FACE_MAX];
	vec2 w[FACE_MAX];
	lx_frame_plane_corners(f, id, a);
	/* beyond the GL's near plane (z >= -w), where w > 0 divides */
	vec4 near = v4_lin(1, m4_row(&v->view_proj, 2), 1 - 1e-6, m4_row(&v->view_proj, 3));
	int n = lx_clip_polygon(a, 4, near, b, FACE_MAX);
	for (int i = 0; i < n; i++)
		w[i] = lx_view_window_point(v, m4_mul_point(&v->view_proj, b[i]));
	lx_poly_hull(w, n, out); /* counter-clockwise */
}

bool lx_plane_window_holds(const struct lx_poly *window, struct lx_rect box)
{
	for (int k = 0; k < 4; k++)
		if (!lx_poly_contains(window, (vec2){k & 1 ? box.x1 : box.x0, k & 2 ? box.y1 : box.y0}, 0.01))
			return false;
	return true;
}

unsigned lx_lookup_maps(const struct lx_lookup_volumes *v, int receiver, unsigned mask)
{
	/* the receiver's part in view: its box clipped to the view frustum */
	const struct lx_frame *f = v->frame;
	vec3 pts[LX_CONVEX_MAX_POINTS];
	int np = lx_frustum_box_points(v->frustum, f->bmin[receiver], f->bmax[receiver], pts, LX_CONVEX_MAX_POINTS);
	if (np == 0)
		return 0; /* not in view */
	unsigned out = 0;
	for (int m = 0; m < v->res->map_count && m < LX_MAX_MAPS; m++) {
		const struct lx_shadow_map *map = &v->res->maps[m];
		if (!(mask & 1u << m))
			continue;
		/* inside by a margin the shader's rounding cannot cross */
		double tx = v->margin[m][0], ty = v->margin[m][1];
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
