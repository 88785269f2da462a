#include "sure_shadow.h"
#include "convex.h"
#include "linalg.h"
#include <math.h>
#include <stdlib.h>

/* Of caster id's box, the farthest normalized depth in the map whose matrix is m (a
 * depth z / w is linear-fractional: over a box in front of the light its largest is at a
 * corner), flattened onto the near plane where `flat`; NAN where a corner lies behind the
 * light, beyond the far plane or (unless flat) nearer than the near one: clipped there,
 * the caster's image need not cover its lixels. */
static double farthest_depth(const mat4 *m, vec3 lo, vec3 hi, bool flat)
{
	double far = -INFINITY;
	for (int k = 0; k < 8; k++) {
		vec4 c = m4_mul_point(m, v3_box_corner(lo, hi, k));
		if (!(c.w > 0) || !(c.z < c.w) || (!flat && !(c.z > -c.w)))
			return NAN;
		far = lx_fmax(far, lx_fmax(c.z / c.w, -1.0)); /* c.w > 0 */
	}
	return far;
}

/* One caster's sure shadow on one plane in one map, as lx_sure_shadow_window is asked it:
 * the map's matrix and region's half sizes in lixels, the lookup's reach (inset) and the
 * depth gap; the plane's depth in the map (plane_depth) once it is asked for. */
struct sure_case {
	const struct lx_frame *f;
	const mat4 *m;
	int id, plane;
	double sx, sy, inset, depth_gap;
	bool flat;      /* the map flattens casters onto its near plane */
	int depth_known; /* abg: 0 not yet asked, 1 known, -1 none */
	double abg[3];
};

/* Plane k->plane's depth in the map as a function of where it is seen: a plane's clip
 * coordinates satisfy one linear relation, z = a x + b y + g w, so its point seen at
 * (x / w, y / w) lies at normalized depth a x / w + b y / w + g (k->abg). False where
 * there is none (the plane through the light, seen edge-on). Solved once a case. */
static bool plane_depth(struct sure_case *k)
{
	if (k->depth_known == 0) {
		const struct lx_plane *P = &k->f->scene->planes[k->plane];
		vec3 o = v3_add(P->corner, k->f->offset[k->plane]);
		vec4 c[3] = {m4_mul_point(k->m, o), m4_mul_point(k->m, v3_add(o, P->edge1)),
			     m4_mul_point(k->m, v3_add(o, P->edge2))};
		double A[9];
		for (int i = 0; i < 3; i++)
			A[3 * i] = c[i].x, A[3 * i + 1] = c[i].y, A[3 * i + 2] = c[i].w, k->abg[i] = c[i].z;
		bool solved = lx_solve(3, A, k->abg, 1e-12);
		k->depth_known = solved && isfinite(k->abg[0] + k->abg[1] + k->abg[2]) ? 1 : -1;
	}
	return k->depth_known > 0;
}

/* Whether a caster lies nearer the light than the plane (depth a u + b v + g where it is
 * seen at (u, v)) by `gap` or more along every ray of the map, and nearer than the far
 * plane by the depth gap: in clip coordinates z <= a x + b y + (g - gap) w and z <= (1 -
 * depth_gap) w where w > 0, each linear, so each holds over the hull of the n points x
 * around the caster when it holds at them. A map that flattens casters onto its near
 * plane stores a vertex nearer than that at depth -1, affine over a triangle as the
 * plane's depth is: there the plane must lie `gap` beyond -1 too. */
static bool before_plane(const struct sure_case *k, const vec3 *x, int n, double gap)
{
	const double *abg = k->abg;
	for (int i = 0; i < n; i++) {
		vec4 c = m4_mul_point(k->m, x[i]);
		double plane = abg[0] * c.x + abg[1] * c.y + abg[2] * c.w; /* the plane's depth on its ray, times w */
		if (!(plane - gap * c.w - c.z >= 0) || !((1 - k->depth_gap) * c.w - c.z >= 0) ||
		    (k->flat && !(plane - (gap - 1) * c.w >= 0)))
			return false;
	}
	return true;
}

/* The sure shadow's depth test ray by ray, where the caster's farthest against the
 * plane's nearest (farthest_depth) fails: a shadow running from a caster's foot far
 * across the plane is sure where the plane lies deep enough behind it, and a caster
 * whose box reaches behind a plane map's light (a light near the wall) may still have
 * its shadow's sure part in front. Tested over the n points x around the caster, or
 * (x NULL) over its box, then over the points lx_frame_object_outline holds it in (a
 * sphere's, cylinder's or cone's octagons, much nearer its surface than its box's
 * corners; not all within the box): a linear test that holds over either holds over
 * the caster. A lookup reads lixels up to `inset` from its own point's image, where the
 * plane lies up to that much nearer. */
static bool sure_ray_by_ray(struct sure_case *k, const vec3 *x, int n)
{
	if (!plane_depth(k))
		return false;
	double gap = k->depth_gap + k->inset * (fabs(k->abg[0]) / k->sx + fabs(k->abg[1]) / k->sy);
	if (x)
		return before_plane(k, x, n, gap);
	vec3 p[LX_OUTLINE_POINTS > 8 ? LX_OUTLINE_POINTS : 8];
	for (int i = 0; i < 8; i++)
		p[i] = v3_box_corner(k->f->bmin[k->id], k->f->bmax[k->id], i);
	if (before_plane(k, p, 8, gap))
		return true;
	n = lx_frame_object_outline(k->f, k->id, false, p);
	return before_plane(k, p, n, gap);
}

/* The corners of the part of box [lo, hi] in front of the map's light (w at least a
 * millionth of the corners' largest |w|), repeats and all: where a box reaches behind a
 * plane map's light, its part in front still casts the shadow the map holds. Returns
 * their count (room: BOX_FRONT_MAX), 0 for none. */
#define BOX_FRONT_MAX 30 /* six faces, each a quad cut by a plane: 5 corners at most */
static int box_in_front(const mat4 *m, vec3 lo, vec3 hi, vec3 *out)
{
	vec4 wrow = m4_row(m, 3);
	double most = 0;
	for (int k = 0; k < 8; k++)
		most = lx_fmax(most, fabs(v4_dot_point(wrow, v3_box_corner(lo, hi, k))));
	vec4 front = {wrow.x, wrow.y, wrow.z, wrow.w - 1e-6 * most};
	return lx_box_clip_points(lo, hi, &front, 1, out, BOX_FRONT_MAX);
}

/* The point of the plane through p with unit normal nrm whose image in the map (matrix
 * m) is (x, y) in normalized coordinates: the light's ray through that lixel point, met.
 * False where the ray runs along the plane or meets it behind the light. */
static bool on_plane(const mat4 *m, double x, double y, vec3 p, vec3 nrm, vec3 *out)
{
	vec4 a = v4_lin(1, m4_row(m, 0), -x, m4_row(m, 3)), b = v4_lin(1, m4_row(m, 1), -y, m4_row(m, 3));
	double A[9] = {a.x, a.y, a.z, b.x, b.y, b.z, nrm.x, nrm.y, nrm.z}, r[3] = {-a.w, -b.w, v3_dot(nrm, p)};
	if (!lx_solve(3, A, r, 1e-12))
		return false;
	*out = v3(r[0], r[1], r[2]);
	return m4_mul_point(m, *out).w > 0;
}

/* The window points of polygon `in`'s corners (lixels about the map's centre) on the
 * plane, into pix: 1; -1 where one's ray meets the plane behind the light or the eye; 0
 * where the plane there lies no deeper than the caster's farthest (*far) by the depth
 * gap and the test ray by ray fails (after which *far is NAN). */
static int window_corners(struct sure_case *k, const struct lx_poly *in, double *far, vec2 *pix)
{
	const struct lx_plane *P = &k->f->scene->planes[k->plane];
	vec3 nrm = lx_plane_normal(P), at = v3_add(P->corner, k->f->offset[k->plane]);
	for (int i = 0; i < in->n; i++) {
		vec3 x;
		if (!on_plane(k->m, in->v[i].x / k->sx, in->v[i].y / k->sy, at, nrm, &x))
			return -1;
		vec4 c = m4_mul_point(k->m, x), e = m4_mul_point(&k->f->view.view_proj, x);
		if (!(e.w > 0))
			return -1;
		/* its depth beyond the caster's farthest (beyond the far plane a receiver's
		 * depth is clamped to it), else the test ray by ray */
		if (!isnan(*far) && !(lx_fmin(c.z / c.w, 1.0) - *far >= k->depth_gap)) {
			if (!sure_ray_by_ray(k, NULL, 0))
				return 0;
			*far = NAN;
		}
		pix[i] = lx_view_window_point(&k->f->view, e);
	}
	return 1;
}

/* Polygon `in` (lixels about the map's centre) cut to where the plane's points lie in
 * front of the map's light and beyond the eye's near plane. Both are linear in where the
 * map sees a point: the plane's point seen at (u, v) is M^-1 (u, v, a u + b v + g, 1)
 * divided by its clip w (plane_depth), a homogeneous point whose w is 1 / that clip w.
 * In front of the light: that w a billionth of the corners' largest or more (nearer 0,
 * the point runs off to infinity). False where M or the plane's depth gives no answer. */
static bool cut_to_front(struct sure_case *k, struct lx_poly *in)
{
	mat4 inv;
	if (!plane_depth(k) || !m4_invert(k->m, &inv))
		return false;
	/* the point's homogeneous coordinates: u U + v V + K (inv's columns, the depth's
	 * column spread over the others) */
	double U[4], V[4], K[4], sx = k->sx, sy = k->sy;
	for (int r = 0; r < 4; r++) {
		double z = inv.m[8 + r];
		U[r] = inv.m[r] + k->abg[0] * z, V[r] = inv.m[4 + r] + k->abg[1] * z, K[r] = inv.m[12 + r] + k->abg[2] * z;
	}
	double most = 0;
	for (int i = 0; i < in->n; i++)
		most = lx_fmax(most, fabs(U[3] * in->v[i].x / sx + V[3] * in->v[i].y / sy + K[3]));
	lx_poly_clip_halfplane(in, U[3] / sx, V[3] / sy, K[3] - 1e-9 * most, in);
	const mat4 *vp = &k->f->view.view_proj;
	vec4 e = v4_lin(1, m4_row(vp, 2), 1, m4_row(vp, 3)); /* z + w >= 0 */
	double eu = e.x * U[0] + e.y * U[1] + e.z * U[2] + e.w * U[3];
	double ev = e.x * V[0] + e.y * V[1] + e.z * V[2] + e.w * V[3];
	double ek = e.x * K[0] + e.y * K[1] + e.z * K[2] + e.w * K[3];
	lx_poly_clip_halfplane(in, eu / sx, ev / sy, ek, in);
	return isfinite(most);
}

bool lx_sure_shadow_window(const struct lx_frame *f, const struct lx_shadow_map *map, int w, int h, int id,
			   const float *pts, const unsigned short *index, int n, int plane, double inset, double depth_gap, struct lx_poly *win)
{
	win->n = 0;
	if (n < 3 || w < 1 || h < 1 || plane < 0 || plane >= f->scene->plane_count || id < f->scene->plane_count ||
	    id >= f->object_count || (!pts && n != 8))
		return false;
	const mat4 *m = &map->light_clip;
	double sx = 0.5 * w, sy = 0.5 * h;
	struct sure_case k = {f, m, id, plane, sx, sy, inset, depth_gap, map->plane < 0, 0, {0, 0, 0}};
	/* the caster's farthest depth, or NAN: then the test ray by ray, once; a box that
	 * reaches behind the light, by its part in front */
	vec3 o = f->offset[id], lo = f->bmin[id], hi = f->bmax[id], front[BOX_FRONT_MAX];
	double far = farthest_depth(m, lo, hi, k.flat);
	int nf = !pts && isnan(far) ? box_in_front(m, lo, hi, front) : 0;
	if (!pts && isnan(far) && nf < 3)
		return false;
	if (isnan(far) && !sure_ray_by_ray(&k, nf ? front : NULL, nf))
		return false;
	if (nf) /* the image of its part in front */
		pts = NULL, n = nf;
	/* the caster's image in lixels about the map's centre */
	enum { ON_STACK = 128 }; /* a fan's corners, a box's 8; a whole mesh (the tests') on the heap */
	vec2 stack[ON_STACK], *img = n <= ON_STACK ? stack : malloc((size_t)n * sizeof(vec2));
	if (!img)
		return false; /* out of memory: no sure part */
	for (int k = 0; k < n; k++) {
		const float *q = pts ? pts + 3 * (index ? index[k] : k) : NULL;
		vec3 x = q ? v3(q[0] + o.x, q[1] + o.y, q[2] + o.z) : nf ? front[k] : v3_box_corner(lo, hi, k);
		vec4 c = m4_mul_point(m, x);
		if (!(c.w > 0)) { /* reaching behind the light: its image is unbounded */
			if (img != stack)
				free(img);
			return false;
		}
		img[k] = (vec2){c.x / c.w * sx, c.y / c.w * sy};
	}
	struct lx_poly hull, in;
	bool fits = lx_poly_hull(img, n, &hull);
	if (img != stack)
		free(img);
	if (!fits) /* more corners than a polygon holds: no sure part */
		return false;
	lx_poly_inset(&hull, inset, &in);
	/* inside the rays the map serves, by the same margin */
	lx_poly_clip_halfplane(&in, 1, 0, -(map->bounds[0] * sx + inset), &in);
	lx_poly_clip_halfplane(&in, 0, 1, -(map->bounds[1] * sy + inset), &in);
	lx_poly_clip_halfplane(&in, -1, 0, map->bounds[2] * sx - inset, &in);
	lx_poly_clip_halfplane(&in, 0, -1, map->bounds[3] * sy - inset, &in);
	if (in.n < 3)
		return false;
	/* each corner on the plane, in front of the light and of the eye; where one is not,
	 * the polygon cut to where they are (a shadow running past the eye) and tried again */
	vec2 pix[LX_POLY_MAX];
	int got = window_corners(&k, &in, &far, pix);
	if (got < 0 && cut_to_front(&k, &in) && in.n >= 3)
		got = window_corners(&k, &in, &far, pix);
	if (got <= 0)
		return false;
	lx_poly_hull(pix, in.n, win); /* convex, counter-clockwise whichever way the image turned */
	return win->n >= 3;
}
