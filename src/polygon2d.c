#include "polygon2d.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double cross(vec2 o, vec2 a, vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

static int cmp_vec2(const void *pa, const void *pb)
{
	const vec2 *a = pa, *b = pb;
	if (a->x != b->x)
		return a->x < b->x ? -1 : 1;
	return (a->y > b->y) - (a->y < b->y);
}

void lx_poly_hull(const vec2 *pts, int n, struct lx_poly *out)
{
	vec2 p[4 * LX_POLY_MAX], h[8 * LX_POLY_MAX];
	int m = 0;
	for (int i = 0; i < n && m < 4 * LX_POLY_MAX; i++)
		if (isfinite(pts[i].x) && isfinite(pts[i].y))
			p[m++] = pts[i];
	out->n = 0;
	if (m == 0)
		return;
	qsort(p, (size_t)m, sizeof(vec2), cmp_vec2);
	int k = 0;
	for (int i = 0; i < m; i++) { /* lower hull */
		while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0)
			k--;
		h[k++] = p[i];
	}
	for (int i = m - 2, t = k + 1; i >= 0; i--) { /* upper hull */
		while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0)
			k--;
		h[k++] = p[i];
	}
	k = k > 1 ? k - 1 : k; /* the last point repeats the first */
	if (k > LX_POLY_MAX)
		k = LX_POLY_MAX;
	out->n = k;
	memcpy(out->v, h, (size_t)k * sizeof(vec2));
}

void lx_poly_clip_halfplane(const struct lx_poly *a, double nx, double ny, double c, struct lx_poly *out)
{
	struct lx_poly r = {0};
	for (int i = 0; i < a->n; i++) {
		vec2 p = a->v[i], q = a->v[(i + 1) % a->n];
		double dp = nx * p.x + ny * p.y + c, dq = nx * q.x + ny * q.y + c;
		if (dp >= 0 && r.n < LX_POLY_MAX)
			r.v[r.n++] = p;
		if ((dp >= 0) != (dq >= 0) && r.n < LX_POLY_MAX) {
			double t = dp / (dp - dq); /* signs differ: dp - dq != 0 */
			r.v[r.n++] = (vec2){p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t};
		}
	}
	*out = r;
}

void lx_poly_intersect(const struct lx_poly *a, const struct lx_poly *b, struct lx_poly *out)
{
	struct lx_poly r = *a;
	for (int i = 0; i < b->n && r.n > 0; i++) {
		vec2 p = b->v[i], q = b->v[(i + 1) % b->n];
		/* inside of a counter-clockwise edge p->q: cross(p, q, x) >= 0 */
		double nx = -(q.y - p.y), ny = q.x - p.x;
		lx_poly_clip_halfplane(&r, nx, ny, -(nx * p.x + ny * p.y), &r);
	}
	if (b->n < 3)
		r.n = 0;
	*out = r;
}

double lx_poly_area(const struct lx_poly *p)
{
	double s = 0;
	for (int i = 0; i < p->n; i++) {
		vec2 a = p->v[i], b = p->v[(i + 1) % p->n];
		s += a.x * b.y - a.y * b.x;
	}
	return 0.5 * s;
}

bool lx_poly_contains(const struct lx_poly *p, vec2 q, double eps)
{
	if (p->n < 3)
		return false;
	for (int i = 0; i < p->n; i++) {
		vec2 a = p->v[i], b = p->v[(i + 1) % p->n];
		double len = hypot(b.x - a.x, b.y - a.y);
		if (!(len > 0) || cross(a, b, q) / len <= eps)
			return false;
	}
	return true;
}

void lx_poly_bounds(const struct lx_poly *p, double *x0, double *y0, double *x1, double *y1)
{
	*x0 = *y0 = INFINITY;
	*x1 = *y1 = -INFINITY;
	for (int i = 0; i < p->n; i++) {
		*x0 = fmin(*x0, p->v[i].x), *x1 = fmax(*x1, p->v[i].x);
		*y0 = fmin(*y0, p->v[i].y), *y1 = fmax(*y1, p->v[i].y);
	}
}

/* Intersection points of the edges of two polygons. */
static int edge_crossings(const struct lx_poly *a, const struct lx_poly *b, vec2 *out, int max_out)
{
	int n = 0;
	for (int i = 0; i < a->n; i++)
		for (int j = 0; j < b->n; j++) {
			vec2 p = a->v[i], p2 = a->v[(i + 1) % a->n], q = b->v[j], q2 = b->v[(j + 1) % b->n];
			double rx = p2.x - p.x, ry = p2.y - p.y, sx = q2.x - q.x, sy = q2.y - q.y;
			double den = rx * sy - ry * sx;
			if (fabs(den) < 1e-300) /* parallel edges: their end points are candidates already */
				continue;
			double t = ((q.x - p.x) * sy - (q.y - p.y) * sx) / den;
			double u = ((q.x - p.x) * ry - (q.y - p.y) * rx) / den;
			if (t >= 0 && t <= 1 && u >= 0 && u <= 1 && n < max_out)
				out[n++] = (vec2){p.x + rx * t, p.y + ry * t};
		}
	return n;
}

static bool inside_or_on(const struct lx_poly *p, vec2 q, double eps)
{
	if (p->n < 3)
		return false;
	for (int e = 0; e < p->n; e++) {
		vec2 a = p->v[e], b = p->v[(e + 1) % p->n];
		double len = hypot(b.x - a.x, b.y - a.y);
		if (len > 0 && cross(a, b, q) / len < -eps)
			return false;
	}
	return true;
}

void lx_poly_hull_of_difference(const struct lx_poly *a, const struct lx_poly *b, const struct lx_poly *c,
				struct lx_poly *out)
{
	/* Every vertex of closure(a - b - c) is a vertex of one of the three polygons or a
	 * crossing of two of their edges. A candidate is such a vertex when points of
	 * a - b - c lie right next to it: probe a tiny circle around it. The hull of the
	 * vertices is the hull of the difference; boundaries shared by b and c leave none. */
	out->n = 0;
	if (a->n < 3)
		return;
	vec2 cand[4 * LX_POLY_MAX];
	int n = 0;
	const struct lx_poly *polys[3] = {a, b, c};
	double x0, y0, x1, y1;
	lx_poly_bounds(a, &x0, &y0, &x1, &y1);
	double r = 1e-7 * (fabs(x1 - x0) + fabs(y1 - y0)), eps = r * 1e-3;
	if (!(r > 0))
		return;
	for (int k = 0; k < 3; k++)
		for (int i = 0; i < polys[k]->n && n < 4 * LX_POLY_MAX; i++)
			cand[n++] = polys[k]->v[i];
	for (int k = 0; k < 3; k++)
		for (int l = k + 1; l < 3; l++)
			n += edge_crossings(polys[k], polys[l], cand + n, 4 * LX_POLY_MAX - n);
	vec2 keep[4 * LX_POLY_MAX];
	int m = 0;
	for (int i = 0; i < n; i++)
		for (int d = 0; d < 24; d++) {
			double ang = 2 * M_PI * (d + 0.37) / 24;
			vec2 q = {cand[i].x + r * cos(ang), cand[i].y + r * sin(ang)};
			if (lx_poly_contains(a, q, eps) && !inside_or_on(b, q, eps) && !inside_or_on(c, q, eps)) {
				keep[m++] = cand[i];
				break;
			}
		}
	lx_poly_hull(keep, m, out);
	if (out->n < 3)
		out->n = 0;
}
