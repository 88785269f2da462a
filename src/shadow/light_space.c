#include "light_space.h"
#include "convex.h"
#include <math.h>
#include <string.h>

/* A point light's frustum is kept within this half-angle; a wider cone would spend the
 * map on grazing directions (or need several maps), so what lies outside is left
 * unshadowed with a warning. */
#define MAX_HALF_ANGLE_DEG 75.0

int lx_light_space_receivers(const struct lx_frame *f, vec3 *pts)
{
	vec3 fc[8];
	if (!(f->lit_min.x <= f->lit_max.x && f->lit_min.y <= f->lit_max.y && f->lit_min.z <= f->lit_max.z))
		return 0; /* a projective light that reaches nothing in view */
	lx_view_frustum_corners(&f->view, fc);
	return lx_frustum_box_points(fc, f->lit_min, f->lit_max, pts, LX_CONVEX_MAX_POINTS);
}

/* Which objects can cast: casters always; planes only when their back face is lit. */
bool lx_object_can_cast(const struct lx_frame *f, int id)
{
	const struct lx_scene *s = f->scene;
	if (id >= s->plane_count)
		return true;
	const struct lx_plane *p = &s->planes[id];
	vec3 n = lx_plane_normal(p);
	if (f->light.directional)
		return v3_dot(n, f->light.direction) > 0;
	return v3_dot(n, v3_sub(f->light.position, p->corner)) <= 1e-12 * (1 + v3_len(p->edge1) + v3_len(p->edge2));
}

/* G coordinates and depth of a world point; false at or behind a point light. */
static bool project_view(const struct lx_light_space *ls, vec4 q, vec2 *g, double *depth)
{
	*depth = -q.z;
	if (ls->directional) {
		*g = (vec2){q.x, q.y};
		return true;
	}
	if (!(*depth > ls->tiny))
		return false;
	*g = (vec2){q.x / *depth, q.y / *depth};
	return true;
}

/* Room for every point the light space projects: the receiver volume's vertices, or
 * every object's outline (lx_frame_object_outline). */
#define LIGHT_SPACE_POINTS                                                                           \
	(LX_CONVEX_MAX_POINTS > LX_OUTLINE_POINTS * (LX_MAX_PLANES + LX_MAX_CASTERS) ? LX_CONVEX_MAX_POINTS \
										      : LX_OUTLINE_POINTS * (LX_MAX_PLANES + LX_MAX_CASTERS))

/* The images of view-space points q[0, n) that project (packed into g) and the depth
 * range [*dlo, *dhi] they span (empty: +inf, -inf); returns how many project (the rest
 * lie behind a point light). */
static int project_points(const struct lx_light_space *ls, const vec4 *q, int n, vec2 *g, double *dlo, double *dhi)
{
	int m = 0;
	*dlo = INFINITY, *dhi = -INFINITY;
	for (int i = 0; i < n; i++) {
		double depth;
		if (project_view(ls, q[i], &g[m], &depth)) {
			m++;
			*dlo = lx_fmin(*dlo, depth), *dhi = lx_fmax(*dhi, depth);
		}
	}
	return m;
}

/* Whether an object in the box [lo, hi] may lie between the light and a receiver: its
 * bounding sphere reaches the receivers' cone (point light) or their bounds across the
 * beam (directional), short of the farthest receiver. Conservative: one caster far from
 * the rest, off to the side or behind the light, must not widen the map. */
static bool reaches_receivers(const struct lx_light_space *ls, vec3 lo, vec3 hi, double cone, const double rb[4])
{
	vec4 q = m4_mul_point(&ls->view, v3_scale(v3_add(lo, hi), 0.5));
	double r = 0.5 * v3_len(v3_sub(hi, lo)), depth = -q.z;
	if (depth - r > ls->zfar)
		return false; /* beyond every receiver */
	if (ls->directional)
		return q.x + r >= rb[0] && q.y + r >= rb[1] && q.x - r <= rb[2] && q.y - r <= rb[3];
	double dist = sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
	if (!(dist > r))
		return true; /* the sphere holds the light */
	return atan2(sqrt(q.x * q.x + q.y * q.y), depth) - asin(r / dist) <= cone; /* r / dist < 1 */
}

bool lx_shadows_hidden(const struct lx_frame *f)
{
	const struct lx_view *v = &f->view;
	if (f->light.directional)
		return false;
	/* A light d from the eye moves a shadow's edge off its caster's outline by at most
	 * d / near radians (the caster lies beyond the near plane), and a radian spans at most
	 * f (1 + t^2 (1 + a^2)) pixels, at the image's corners (f: the focal length in pixels,
	 * t = tan(fovy / 2), a the aspect). fovy < pi and height >= 1: t and f are finite. */
	double t = tan(0.5 * v->fovy), a = (double)v->width / v->height, corner2 = 1 + t * t * (1 + a * a);
	double px_per_rad = 0.5 * v->height / t * corner2; /* corner2: 1 / cos^2 at the image's corners */
	if (!(v3_len(v3_sub(f->light.position, v->eye)) * px_per_rad <= LX_HIDDEN_SHADOW_PX * v->near))
		return false;
	/* The segment from a point in sight to the eye runs, in front of the near plane, inside
	 * the pyramid from the eye to the near plane's window: no caster's box may meet it. A
	 * box misses it when it lies farther from the eye than the window's corners, or all its
	 * corners lie outside one of the pyramid's six planes (the four sides pass through the
	 * eye, so they hold behind it too). */
	double reach = v->near * sqrt(corner2); /* the eye to a corner of the window */
	for (int id = 0; id < f->object_count; id++) {
		if (!lx_object_can_cast(f, id))
			continue;
		vec3 lo = f->bmin[id], hi = f->bmax[id], e = v->eye;
		vec3 gap = v3(lx_fmax(lx_fmax(lo.x - e.x, e.x - hi.x), 0), lx_fmax(lx_fmax(lo.y - e.y, e.y - hi.y), 0),
			      lx_fmax(lx_fmax(lo.z - e.z, e.z - hi.z), 0));
		if (v3_len(gap) > reach)
			continue;
		int out[6] = {0};
		for (int k = 0; k < 8; k++) {
			vec3 x = v3_box_corner(f->bmin[id], f->bmax[id], k);
			vec4 c = m4_mul_point(&v->view_proj, x);
			double along = v3_dot(v3_sub(x, v->eye), v->dir);
			out[0] += c.x > c.w, out[1] += -c.x > c.w, out[2] += c.y > c.w, out[3] += -c.y > c.w;
			out[4] += along >= v->near, out[5] += along <= 0;
		}
		if (out[0] < 8 && out[1] < 8 && out[2] < 8 && out[3] < 8 && out[4] < 8 && out[5] < 8)
			return false;
	}
	return true;
}

void lx_light_space_build(const struct lx_frame *f, struct lx_light_space *ls)
{
	*ls = (struct lx_light_space){.directional = f->light.directional, .empty = true};
	ls->size = v3_len(v3_sub(f->scene_max, f->scene_min));
	ls->tiny = 1e-9 * (ls->size + 1e-300);
	if (lx_shadows_hidden(f))
		return; /* every shadow behind its caster: nothing to draw */
	vec3 *rec = ls->receiver_pts;
	int nrec = ls->receiver_count = lx_light_space_receivers(f, rec);
	if (nrec == 0)
		return; /* the view holds nothing of the scene */
	vec3 centroid = v3(0, 0, 0);
	for (int i = 0; i < nrec; i++)
		centroid = v3_add(centroid, v3_scale(rec[i], 1.0 / nrec));
	vec3 eye, dir;
	if (ls->directional) {
		dir = f->light.direction;
		eye = v3_sub(centroid, v3_scale(dir, ls->size + 1));
	} else {
		eye = f->light.position;
		if (!v3_normalize(v3_sub(centroid, eye), &dir))
			dir = v3(0, -1, 0); /* light at the centroid: any axis, the cone is clamped later */
	}
	vec3 up = fabs(dir.y) < 0.9 ? v3(0, 1, 0) : v3(1, 0, 0);
	m4_look_at(eye, v3_add(eye, dir), up, &ls->view); /* unit dir, up not parallel: cannot fail */

	/* the receivers' image and depth; and their cone from a point light (the widest angle
	 * off the axis), or their bounds across a directional light's beam: what a caster
	 * must reach to matter */
	vec4 q[LIGHT_SPACE_POINTS];
	vec2 pts[LIGHT_SPACE_POINTS];
	double cone = 0, rx0 = INFINITY, ry0 = INFINITY, rx1 = -INFINITY, ry1 = -INFINITY, dlo, dhi;
	for (int i = 0; i < nrec; i++) {
		q[i] = m4_mul_point(&ls->view, rec[i]);
		cone = lx_fmax(cone, atan2(sqrt(q[i].x * q[i].x + q[i].y * q[i].y), -q[i].z));
		rx0 = lx_fmin(rx0, q[i].x), rx1 = lx_fmax(rx1, q[i].x), ry0 = lx_fmin(ry0, q[i].y), ry1 = lx_fmax(ry1, q[i].y);
	}
	int n = project_points(ls, q, nrec, pts, &dlo, &dhi);
	ls->receivers_behind = n < nrec;
	ls->zfar = dhi;
	lx_poly_hull(pts, n, &ls->receivers);
	/* the casters that reach them: their outlines (lx_frame_object_outline: a box's
	 * corners, tighter for round casters) */
	int ncasters = 0, npoints = 0;
	for (int id = 0; id < f->object_count; id++) {
		if (!lx_object_can_cast(f, id) ||
		    !reaches_receivers(ls, f->bmin[id], f->bmax[id], cone, (double[4]){rx0, ry0, rx1, ry1}))
			continue;
		ls->casting |= 1ull << id; /* ids < LX_MAX_PLANES + LX_MAX_CASTERS = 40 */
		ncasters++;
		vec3 x[LX_OUTLINE_POINTS];
		int k = lx_frame_object_outline(f, id, false, x);
		double *b = ls->caster_g[id];
		b[0] = b[1] = INFINITY, b[2] = b[3] = -INFINITY;
		for (int j = 0; j < k; j++) {
			vec2 g;
			double depth;
			q[npoints] = m4_mul_point(&ls->view, x[j]);
			if (!project_view(ls, q[npoints++], &g, &depth)) { /* behind the light: anywhere */
				b[0] = b[1] = -INFINITY, b[2] = b[3] = INFINITY;
				continue;
			}
			b[0] = lx_fmin(b[0], g.x), b[1] = lx_fmin(b[1], g.y), b[2] = lx_fmax(b[2], g.x), b[3] = lx_fmax(b[3], g.y);
		}
	}
	n = project_points(ls, q, npoints, pts, &dlo, &dhi);
	ls->casters_unbounded = n < npoints; /* a caster reaching behind the light projects everywhere */
	ls->znear = ls->casters_unbounded ? -INFINITY : dlo;
	lx_poly_hull(pts, n, &ls->casters);
	/* Nothing casts, no receiver is in front of the light, or every caster lies beyond
	 * every receiver: no shadow can fall in the view. */
	ls->empty = ncasters == 0 || !(ls->zfar > -INFINITY) || ls->znear > ls->zfar;
}

/* Whether box [lo, hi] stays clear of every ray from the light to a point of the box
 * [rlo, rhi], along one of the world axes: the rays' points (the receiver's box and the
 * light, or its box swept towards a directional light) have an extent on that axis
 * that the caster's box does not meet. A sufficient test, cheap enough for every pair:
 * two objects side by side across the light's rays are told apart, which the bounds on
 * G alone do not (the nearer one's image covers the farther one's). */
static bool box_clear_of_rays(const struct lx_light *light, vec3 lo, vec3 hi, vec3 rlo, vec3 rhi)
{
	const double c_lo[3] = {lo.x, lo.y, lo.z}, c_hi[3] = {hi.x, hi.y, hi.z};
	double r_lo[3] = {rlo.x, rlo.y, rlo.z}, r_hi[3] = {rhi.x, rhi.y, rhi.z};
	const double l[3] = {light->position.x, light->position.y, light->position.z};
	const double d[3] = {light->direction.x, light->direction.y, light->direction.z};
	for (int k = 0; k < 3; k++) {
		if (light->directional) { /* towards the light: against its direction, without end */
			r_lo[k] = d[k] > 0 ? -INFINITY : r_lo[k];
			r_hi[k] = d[k] < 0 ? INFINITY : r_hi[k];
		} else
			r_lo[k] = lx_fmin(r_lo[k], l[k]), r_hi[k] = lx_fmax(r_hi[k], l[k]);
		if (c_hi[k] < r_lo[k] || c_lo[k] > r_hi[k])
			return true;
	}
	return false;
}

bool lx_light_space_shadowed_by_other(const struct lx_light_space *ls, const struct lx_frame *f, int id,
				      const double own[4])
{
	for (int c = 0; c < f->object_count; c++) {
		const double *b = ls->caster_g[c];
		if (c != id && (ls->casting >> c & 1) && b[0] <= own[2] && own[0] <= b[2] && b[1] <= own[3] &&
		    own[1] <= b[3] && !box_clear_of_rays(&f->light, f->bmin[c], f->bmax[c], f->bmin[id], f->bmax[id]))
			return true;
	}
	return false;
}

double lx_light_space_front(const struct lx_light_space *ls, const struct lx_frame *f, vec4 X)
{
	if (ls->directional)
		return X.w;
	vec3 L = f->light.position;
	vec4 d = {X.x - L.x * X.w, X.y - L.y * X.w, X.z - L.z * X.w, 0};
	return -m4_mul_v4(&ls->view, d).z; /* the depth of the direction along the light's axis */
}

bool lx_light_space_chart(const struct lx_light_space *ls, const struct lx_frame *f, vec4 X, vec2 *g)
{
	double front = lx_light_space_front(ls, f, X);
	if (ls->directional) {
		if (!(front > 0))
			return false;
		vec4 q = m4_mul_v4(&ls->view, X);
		*g = (vec2){q.x / q.w, q.y / q.w}; /* view is affine: q.w = X.w > 0 */
		return true;
	}
	vec3 L = f->light.position;
	vec4 q = m4_mul_v4(&ls->view, (vec4){X.x - L.x * X.w, X.y - L.y * X.w, X.z - L.z * X.w, 0});
	double len = sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
	if (!(front > 1e-12 * len))
		return false;
	*g = (vec2){q.x / front, q.y / front};
	return true;
}

/* A hull of fewer than three points (everything seen edge-on) becomes its padded
 * bounding box, so a flat but real set of rays is not lost. */
static struct lx_poly solid(const struct lx_poly *p, double pad)
{
	if (p->n >= 3 || p->n == 0)
		return *p;
	double x0, y0, x1, y1;
	lx_poly_bounds(p, &x0, &y0, &x1, &y1);
	x0 -= pad, y0 -= pad, x1 += pad, y1 += pad;
	return (struct lx_poly){4, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
}

bool lx_light_space_wanted(const struct lx_light_space *ls, struct lx_poly *out)
{
	double pad = ls->directional ? 1e-6 * (ls->size + 1e-300) : 1e-9;
	struct lx_poly rec = solid(&ls->receivers, pad), cas = solid(&ls->casters, pad);
	out->n = 0;
	if (ls->empty)
		return true;
	if (ls->receivers_behind && ls->casters_unbounded)
		return false;
	/* Receivers behind the light can only be shadowed by casters behind it too (the
	 * segment from the light never enters the front half-space), so with the light
	 * inside the receiver volume the casters alone bound the rays. */
	if (ls->receivers_behind)
		*out = cas;
	else if (ls->casters_unbounded)
		*out = rec;
	else
		lx_poly_intersect(&rec, &cas, out);
	return true;
}

bool lx_light_space_clamp(const struct lx_light_space *ls, double r[4])
{
	const double tmax = tan(MAX_HALF_ANGLE_DEG * M_PI / 180);
	if (ls->directional || !(r[0] < -tmax || r[2] > tmax || r[1] < -tmax || r[3] > tmax))
		return false;
	r[0] = lx_fmax(r[0], -tmax), r[1] = lx_fmax(r[1], -tmax), r[2] = lx_fmin(r[2], tmax), r[3] = lx_fmin(r[3], tmax);
	return true;
}

bool lx_light_space_map(const struct lx_light_space *ls, double x0, double x1, double y0, double y1, mat4 *clip,
			struct lx_shadow_result *warn, const char *prefix)
{
	double znear = ls->znear, zfar = ls->zfar;
	if (!ls->directional) {
		double r[4] = {x0, y0, x1, y1};
		if (lx_light_space_clamp(ls, r)) {
			x0 = r[0], y0 = r[1], x1 = r[2], y1 = r[3];
			lx_shadow_warn(warn, "%s: receivers span more than %.0f degrees around the point light; those outside the map are unshadowed",
				       prefix, 2 * MAX_HALF_ANGLE_DEG);
		}
		double min_near = zfar * 1e-4;
		if (znear < min_near) {
			if (!ls->casters_unbounded)
				lx_shadow_warn(warn, "%s: a caster within %.3g m of the point light is clipped by the near plane",
					       prefix, min_near);
			znear = min_near;
		}
	}
	/* Keep the frustum non-empty for flat configurations (a single plane edge-on). */
	double pad = ls->directional ? 1e-6 * (ls->size + 1e-300) : 1e-9;
	if (!(x1 - x0 >= pad))
		x0 -= pad, x1 += pad;
	if (!(y1 - y0 >= pad))
		y0 -= pad, y1 += pad;
	/* a sliver of depth margin so the extreme points do not fall on the clip planes */
	double zpad = lx_fmax((zfar - znear) * 1e-4, ls->directional ? 1e-6 * (ls->size + 1e-300) : znear * 1e-4);
	mat4 proj;
	bool ok;
	if (ls->directional)
		ok = m4_ortho(x0, x1, y0, y1, znear - zpad, zfar + zpad, &proj);
	else {
		double n = lx_fmax(znear - zpad, znear * 0.5);
		ok = m4_frustum(x0 * n, x1 * n, y0 * n, y1 * n, n, zfar + zpad, &proj);
	}
	if (ok) {
		*clip = m4_mul(&proj, &ls->view);
		ok = m4_finite(clip);
	}
	if (!ok)
		lx_shadow_warn(warn, "%s: degenerate light frustum; the map is skipped this frame", prefix);
	return ok;
}

bool lx_uniform_map(const struct lx_frame *f, struct lx_light_space *ls, struct lx_shadow_result *out,
		    const char *prefix, struct lx_uniform_fit *fit)
{
	struct lx_shadow_map *map = &out->maps[0]; /* the rest of out cleared by lx_shadow_method_frame */
	out->map_count = 1;
	*map = (struct lx_shadow_map){.region = 0, .rendered = false, .light_clip = m4_identity()};
	lx_shadow_map_full(map);
	lx_light_space_build(f, ls);
	struct lx_uniform_fit local, *u = fit ? fit : &local;
	u->wanted.n = 0;
	u->x0 = u->y0 = -INFINITY;
	u->x1 = u->y1 = INFINITY;
	if (lx_light_space_wanted(ls, &u->wanted)) {
		if (u->wanted.n < 3)
			return false; /* nothing to shadow, or casters and receivers do not overlap */
		lx_poly_bounds(&u->wanted, &u->x0, &u->y0, &u->x1, &u->y1);
	}
	map->rendered = lx_light_space_map(ls, u->x0, u->x1, u->y0, u->y1, &map->light_clip, out, prefix);
	return map->rendered;
}
