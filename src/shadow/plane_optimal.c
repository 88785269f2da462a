#include "plane_optimal.h"
#include <math.h>
#include <string.h>

vec4 lx_light_point(const struct lx_light *l)
{
	if (l->directional)
		return (vec4){-l->direction.x, -l->direction.y, -l->direction.z, 0};
	return (vec4){l->position.x, l->position.y, l->position.z, 1};
}

vec4 lx_plane_equation(const struct lx_plane *p)
{
	vec3 n = lx_plane_normal(p);
	return (vec4){n.x, n.y, n.z, -v3_dot(n, p->corner)};
}

struct lx_window_row lx_window_row(const struct lx_view *v, double wy)
{
	const double *m = v->inv_view_proj.m;
	double ny = 2 * wy / v->height - 1;
	vec4 c1 = {m[4], m[5], m[6], m[7]}, c2 = {m[8], m[9], m[10], m[11]}, c3 = {m[12], m[13], m[14], m[15]};
	vec4 mid = v4_lin(ny, c1, 1, c3);
	return (struct lx_window_row){v4_lin(1, mid, -1, c2), v4_lin(1, mid, 1, c2), {m[0], m[1], m[2], m[3]},
				      2.0 / v->width};
}

bool lx_window_on_plane(const struct lx_view *v, vec4 plane, double wx, double wy, vec3 *q, double *t)
{
	struct lx_window_row r = lx_window_row(v, wy);
	return lx_window_row_on_plane(&r, plane, wx, q, t);
}

double lx_plane_near_limit(const struct lx_plane *p) { return 1e-3 * (v3_len(p->edge1) + v3_len(p->edge2)); }

/* parallelogram coordinates: solve q - corner = s e1 + u e2 in the plane (the edges are
 * not parallel: the scene parser checks it) */
struct lx_plane_gram lx_plane_gram(const struct lx_plane *p)
{
	double e11 = v3_dot(p->edge1, p->edge1), e12 = v3_dot(p->edge1, p->edge2), e22 = v3_dot(p->edge2, p->edge2);
	return (struct lx_plane_gram){p->corner, p->edge1, p->edge2, e11, e12, e22, e11 * e22 - e12 * e12};
}

bool lx_plane_contains(const struct lx_plane *p, vec3 q)
{
	struct lx_plane_gram g = lx_plane_gram(p);
	return lx_plane_gram_contains(&g, q);
}

static vec4 scale4(vec4 a, double s) { return (vec4){a.x * s, a.y * s, a.z * s, a.w * s}; }
static vec4 add4(vec4 a, vec4 b) { return (vec4){a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
static vec4 unit4(vec4 a)
{
	double l = v4_len(a);
	return l > 0 ? scale4(a, 1 / l) : a;
}

/* T with columns lambda_i * X_i such that sum lambda_i X_i = X_4 (the projective basis
 * that maps e_i -> X_i and (1, 1, 1, 1) -> X_4). False when the points are not in
 * general position. */
static bool basis(const vec4 x[5], mat4 *t)
{
	double a[16], b[4] = {x[4].x, x[4].y, x[4].z, x[4].w};
	for (int c = 0; c < 4; c++) {
		a[0 * 4 + c] = x[c].x;
		a[1 * 4 + c] = x[c].y;
		a[2 * 4 + c] = x[c].z;
		a[3 * 4 + c] = x[c].w;
	}
	if (!lx_solve(4, a, b, 1e-12))
		return false;
	double big = lx_fmax(lx_fmax(fabs(b[0]), fabs(b[1])), lx_fmax(fabs(b[2]), fabs(b[3])));
	for (int c = 0; c < 4; c++) {
		if (!(fabs(b[c]) > 1e-9 * big)) /* X_4 lies in the span of three of the others */
			return false;
		t->m[c * 4 + 0] = b[c] * x[c].x;
		t->m[c * 4 + 1] = b[c] * x[c].y;
		t->m[c * 4 + 2] = b[c] * x[c].z;
		t->m[c * 4 + 3] = b[c] * x[c].w;
	}
	return true;
}

/* Angle between M x and the target y, as homogeneous points (either sign). */
static double residual(const mat4 *m, vec4 x, vec4 y)
{
	vec4 v = unit4(m4_mul_v4(m, x)), u = unit4(y);
	double d = fabs(v4_dot(v, u));
	return acos(lx_fmin(1.0, d));
}

enum lx_plane_camera_status lx_plane_camera_solve(const struct lx_view *v, vec4 light, vec4 plane, vec4 inside,
						   struct lx_plane_camera *out)
{
	light = unit4(light);
	/* |pi . L| is the light's distance to P (point light, unit normal); relative to the
	 * view's extent a tiny value makes the construction singular. */
	if (fabs(v4_dot(plane, light)) < 1e-9)
		return LX_PLANE_CAMERA_LIGHT_ON_PLANE;
	const double W = v->width, H = v->height;
	const double cx[4] = {0, 0, W, W}, cy[4] = {0, H, H, 0};
	vec4 p[4];
	for (int i = 0; i < 4; i++) {
		double nx = cx[i] / W * 2 - 1, ny = cy[i] / H * 2 - 1;
		vec4 n = m4_mul_v4(&v->inv_view_proj, (vec4){nx, ny, -1, 1});
		vec4 f = m4_mul_v4(&v->inv_view_proj, (vec4){nx, ny, 1, 1});
		/* the ray's point on P, homogeneous: at infinity or behind the eye is fine */
		p[i] = add4(scale4(n, v4_dot(plane, f)), scale4(f, -v4_dot(plane, n)));
		if (!(v4_len(p[i]) > 1e-12 * v4_len(n) * v4_len(f)))
			return LX_PLANE_CAMERA_EDGE_ON;
		p[i] = unit4(p[i]);
		if (p[i].w < 0)
			p[i] = scale4(p[i], -1);
	}
	/* p4 lifted towards the light: on the line L p4, between them when both are finite. */
	vec4 l = light.w < 0 ? scale4(light, -1) : light;
	vec4 lifted = unit4(add4(p[3], l));
	vec4 X[5] = {light, p[0], p[1], p[2], lifted};
	vec4 Y[5] = {{0, 0, 1, 0}, {cx[0], cy[0], 1, 1}, {cx[1], cy[1], 1, 1}, {cx[2], cy[2], 1, 1}, {cx[3], cy[3], -1, 1}};
	mat4 tx, ty, txi;
	if (!basis(X, &tx) || !basis(Y, &ty) || !m4_invert(&tx, &txi))
		return LX_PLANE_CAMERA_SINGULAR;
	mat4 m = m4_mul(&ty, &txi);
	/* fix the scale by the largest element, never by one entry that may be 0 */
	double big = 0;
	for (int i = 0; i < 16; i++)
		big = lx_fmax(big, fabs(m.m[i]));
	if (!(big > 0) || !m4_finite(&m))
		return LX_PLANE_CAMERA_SINGULAR;
	for (int i = 0; i < 16; i++)
		m.m[i] /= big;
	double r = 0;
	for (int i = 0; i < 5; i++)
		r = lx_fmax(r, residual(&m, X[i], Y[i]));
	/* the fourth corner itself must keep its window x, y too (equation 6) */
	vec4 q4 = m4_mul_v4(&m, p[3]);
	if (fabs(q4.w) > 1e-12 * v4_len(q4))
		r = lx_fmax(r, hypot(q4.x / q4.w - cx[3], q4.y / q4.w - cy[3]) / (W + H));
	if (!(r < 1e-7))
		return LX_PLANE_CAMERA_SINGULAR;
	/* q > 0 where the map must see */
	vec4 qi = m4_mul_v4(&m, inside);
	if (qi.w * (inside.w < 0 ? -1 : 1) < 0)
		for (int i = 0; i < 16; i++)
			m.m[i] = -m.m[i];
	/* depth increasing away from the light: compare the inside point with a point
	 * between it and the light */
	vec4 in = inside.w < 0 ? scale4(inside, -1) : inside;
	vec4 nearer = add4(unit4(in), scale4(l, 0.5));
	vec4 a = m4_mul_v4(&m, nearer), b = m4_mul_v4(&m, in);
	if (fabs(a.w) > 0 && fabs(b.w) > 0 && a.z / a.w > b.z / b.w)
		for (int c = 0; c < 4; c++)
			m.m[c * 4 + 2] = -m.m[c * 4 + 2];
	out->m = m;
	out->residual = r;
	return LX_PLANE_CAMERA_OK;
}

/* Clips a homogeneous polygon against -w <= x, y, z <= w (GL's clip volume). */
static int clip_homogeneous(vec4 *poly, int n, vec4 *tmp)
{
	for (int k = 0; k < 6; k++) {
		int m = 0;
		for (int i = 0; i < n; i++) {
			vec4 a = poly[i], b = poly[lx_loop_next(i, n)];
			double ca[3] = {a.x, a.y, a.z}, cb[3] = {b.x, b.y, b.z};
			double s = k & 1 ? -1 : 1;
			double da = a.w + s * ca[k / 2], db = b.w + s * cb[k / 2];
			if (da >= 0 && m < 32)
				tmp[m++] = a;
			if ((da >= 0) != (db >= 0) && m < 32)
				tmp[m++] = add4(a, scale4(add4(b, scale4(a, -1)), da / (da - db)));
		}
		memcpy(poly, tmp, (size_t)m * sizeof(vec4));
		n = m;
	}
	return n;
}

bool lx_plane_visible(const struct lx_view *v, const struct lx_plane *p, struct lx_poly *window, vec3 *world,
		      int *world_count)
{
	vec3 c[4] = {p->corner, v3_add(p->corner, p->edge1), v3_add(v3_add(p->corner, p->edge1), p->edge2),
		     v3_add(p->corner, p->edge2)};
	vec4 poly[32], tmp[32];
	for (int i = 0; i < 4; i++)
		poly[i] = m4_mul_point(&v->view_proj, c[i]);
	int n = clip_homogeneous(poly, 4, tmp);
	window->n = 0;
	*world_count = 0;
	vec2 pts[32];
	for (int i = 0; i < n; i++) {
		if (!(poly[i].w > 0))
			continue; /* inside the clip volume w >= |z| > 0 except at degenerate corners */
		pts[i] = (vec2){(poly[i].x / poly[i].w + 1) * 0.5 * v->width, (poly[i].y / poly[i].w + 1) * 0.5 * v->height};
		vec4 wp = m4_mul_v4(&v->inv_view_proj, (vec4){poly[i].x / poly[i].w, poly[i].y / poly[i].w, poly[i].z / poly[i].w, 1});
		world[(*world_count)++] = v3(wp.x / wp.w, wp.y / wp.w, wp.z / wp.w);
	}
	lx_poly_hull(pts, *world_count, window);
	/* an edge-on plane covers no area on screen */
	return window->n >= 3 && fabs(lx_poly_area(window)) > 1e-6;
}

int lx_halfspace_vertices(const vec4 *planes, int n, const vec3 *box, double tol, vec3 *out, int max_out)
{
	/* Each triple of planes meets in p = -(d1 (n2 x n3) + d2 (n3 x n1) + d3 (n1 x n2)) / det,
	 * det = n1 . (n2 x n3) (Cramer's rule; this runs every frame, so no general solver).
	 * A triple whose det is tiny against its normals is parallel or nearly so: skipped. */
	enum { MAX_PLANES = 32 };
	if (n > MAX_PLANES)
		n = MAX_PLANES;
	vec3 nn[MAX_PLANES];
	double scale[MAX_PLANES];
	for (int i = 0; i < n; i++) {
		nn[i] = v3(planes[i].x, planes[i].y, planes[i].z);
		scale[i] = fabs(nn[i].x) + fabs(nn[i].y) + fabs(nn[i].z);
	}
	int count = 0;
	for (int i = 0; i < n; i++)
		for (int j = i + 1; j < n; j++) {
			vec3 cij = v3_cross(nn[i], nn[j]);
			for (int k = j + 1; k < n; k++) {
				double det = v3_dot(nn[k], cij);
				if (!(fabs(det) > 1e-12 * scale[i] * scale[j] * scale[k]))
					continue;
				vec3 cjk = v3_cross(nn[j], nn[k]), cki = v3_cross(nn[k], nn[i]);
				vec3 p = v3_scale(v3_add(v3_add(v3_scale(cjk, planes[i].w), v3_scale(cki, planes[j].w)),
							 v3_scale(cij, planes[k].w)),
						  -1 / det);
				double pscale = fabs(p.x) + fabs(p.y) + fabs(p.z);
				bool inside = isfinite(pscale) &&
					      (!box || (p.x >= box[0].x - tol && p.y >= box[0].y - tol && p.z >= box[0].z - tol &&
							p.x <= box[1].x + tol && p.y <= box[1].y + tol && p.z <= box[1].z + tol));
				for (int q = 0; q < n && inside; q++)
					inside = v3_dot(nn[q], p) + planes[q].w >= -1e-9 * (scale[q] * pscale + fabs(planes[q].w));
				if (inside && count < max_out)
					out[count++] = p;
			}
		}
	return count;
}
