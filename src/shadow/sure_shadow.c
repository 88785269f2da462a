#include "sure_shadow.h"
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

bool lx_sure_shadow_window(const struct lx_frame *f, const struct lx_shadow_map *map, int w, int h, int id,
			   const float *pts, const unsigned short *index, int n, int plane, double inset, double depth_gap, struct lx_poly *win)
{
	win->n = 0;
	if (n < 3 || w < 1 || h < 1 || plane < 0 || plane >= f->scene->plane_count || id < f->scene->plane_count ||
	    id >= f->object_count || (!pts && n != 8))
		return false;
	const mat4 *m = &map->light_clip;
	double far = farthest_depth(m, f->bmin[id], f->bmax[id], map->plane < 0);
	if (isnan(far))
		return false;
	/* the caster's image in lixels about the map's centre (every corner in front of the
	 * light: its box is) */
	double sx = 0.5 * w, sy = 0.5 * h;
	enum { ON_STACK = 128 }; /* a fan's corners, a box's 8; a whole mesh (the tests') on the heap */
	vec2 stack[ON_STACK], *img = n <= ON_STACK ? stack : malloc((size_t)n * sizeof(vec2));
	if (!img)
		return false; /* out of memory: no sure part */
	vec3 o = f->offset[id], lo = f->bmin[id], hi = f->bmax[id];
	for (int k = 0; k < n; k++) {
		const float *q = pts ? pts + 3 * (index ? index[k] : k) : NULL;
		vec3 x = q ? v3(q[0] + o.x, q[1] + o.y, q[2] + o.z) : v3_box_corner(lo, hi, k);
		vec4 c = m4_mul_point(m, x);
		img[k] = (vec2){c.x / c.w * sx, c.y / c.w * sy}; /* c.w > 0 inside the box */
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
	/* each corner on the plane, in front of the light and of the eye, its depth beyond
	 * the caster's; the plane's depth there is linear-fractional too, least at a corner */
	const struct lx_plane *P = &f->scene->planes[plane];
	vec3 nrm = lx_plane_normal(P), at = v3_add(P->corner, f->offset[plane]);
	vec2 pix[LX_POLY_MAX];
	for (int k = 0; k < in.n; k++) {
		vec3 x;
		if (!on_plane(m, in.v[k].x / sx, in.v[k].y / sy, at, nrm, &x))
			return false;
		vec4 c = m4_mul_point(m, x), e = m4_mul_point(&f->view.view_proj, x);
		/* beyond the far plane a receiver's depth is clamped to it */
		if (!(lx_fmin(c.z / c.w, 1.0) - far >= depth_gap) || !(e.w > 0))
			return false;
		pix[k] = lx_view_window_point(&f->view, e);
	}
	lx_poly_hull(pix, in.n, win); /* convex, counter-clockwise whichever way the image turned */
	return win->n >= 3;
}
