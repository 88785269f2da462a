#include "polygon2d.h"
#include "linalg.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double cross(vec2 o, vec2 a, vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

/* Points that need more than LX_POLY_MAX vertices: a polygon of LX_POLY_DOP sides, each a
 * supporting line of the points at an evenly spaced angle, which holds them all (a
 * superset, never a subset: dropping vertices would cut the wanted region). */
#define LX_POLY_DOP 32
static void dop(const vec2 *pts, int n, struct lx_poly *out)
{
	double d[LX_POLY_DOP], c[LX_POLY_DOP], s[LX_POLY_DOP];
	for (int i = 0; i < LX_POLY_DOP; i++) {
		c[i] = cos(2 * M_PI * i / LX_POLY_DOP), s[i] = sin(2 * M_PI * i / LX_POLY_DOP), d[i] = -INFINITY;
		for (int k = 0; k < n; k++)
			if (isfinite(pts[k].x) && isfinite(pts[k].y))
				d[i] = lx_fmax(d[i], c[i] * pts[k].x + s[i] * pts[k].y);
	}
	out->n = 0;
	if (!isfinite(d[0]))
		return; /* no finite point */
	out->n = LX_POLY_DOP;
	for (int i = 0; i < LX_POLY_DOP; i++) { /* lines i and i + 1 meet: their angles differ by 2 pi / 32 */
		int j = (i + 1) % LX_POLY_DOP;
		double det = c[i] * s[j] - s[i] * c[j]; /* sin(2 pi / 32) */
		out->v[i] = (vec2){(d[i] * s[j] - s[i] * d[j]) / det, (c[i] * d[j] - d[i] * c[j]) / det};
	}
}

static void fit(const vec2 *pts, int n, struct lx_poly *out)
{
	if (n > LX_POLY_MAX) {
		dop(pts, n, out);
		return;
	}
	out->n = n;
	memcpy(out->v, pts, (size_t)n * sizeof(vec2));
}

/* Whether a and b are the same point but for rounding: within a trillionth of their size,
 * or within tol. */
static bool same_point(vec2 a, vec2 b, double tol)
{
	double d = fabs(a.x - b.x) + fabs(a.y - b.y);
	return d <= 1e-12 * (fabs(a.x) + fabs(a.y) + fabs(b.x) + fabs(b.y)) || d <= tol;
}

/* Whether a comes after b in x, then y (the monotone chain's order). */
static bool after(vec2 a, vec2 b) { return a.x > b.x || (a.x == b.x && a.y > b.y); }

/* Sorts p by x, then y. Shell sort (Ciura's gaps): the few hundred points a call gets
 * sort in place without qsort's call per comparison; this runs several times a frame,
 * most often on a box's 8 corners, which the last gap (insertion) sorts alone. */
static void sort_points(vec2 *p, int m)
{
	static const int gaps[] = {701, 301, 132, 57, 23, 10, 4, 1};
	for (size_t g = 0; g < sizeof gaps / sizeof gaps[0]; g++) {
		int gap = gaps[g];
		for (int i = gap; i < m; i++) {
			vec2 t = p[i];
			int j = i;
			for (; j >= gap && after(p[j - gap], t); j -= gap)
				p[j] = p[j - gap];
			p[j] = t;
		}
	}
}

bool lx_poly_hull(const vec2 *pts, int n, struct lx_poly *out)
{
	out->n = 0;
	if (n <= 0)
		return true;
	/* the usual few hundred points on the stack: this runs every frame */
	enum { ON_STACK = 512 }; /* what callers pass but for scenes of many round casters (16 points each) */
	vec2 stack[3 * ON_STACK];
	vec2 *p = n <= ON_STACK ? stack : malloc((size_t)n * 3 * sizeof(vec2)), *h = p + n;
	if (!p) { /* out of memory: the 32-sided polygon around the points, no hull */
		dop(pts, n, out);
		return false;
	}
	/* the finite points, and their extent in y */
	int m = 0;
	double ylo = INFINITY, yhi = -INFINITY;
	for (int i = 0; i < n; i++)
		if (isfinite(pts[i].x) && isfinite(pts[i].y)) {
			p[m++] = pts[i];
			ylo = pts[i].y < ylo ? pts[i].y : ylo, yhi = pts[i].y > yhi ? pts[i].y : yhi;
		}
	if (m == 0) {
		if (p != stack)
			free(p);
		return true;
	}
	sort_points(p, m);
	/* Points the same but for rounding (a flat box's corners come in pairs; a sphere's
	 * outline sends two points down each ray) turn any way, and kept, they let a vertex
	 * that is no corner stay and leave an edge of length about 0, which points anywhere:
	 * a polygon clipped by it loses nearly everything. So a point within a trillionth of
	 * its own size (and a thousand-trillionth of the points' extent, for those near 0) of
	 * the last one kept is skipped. A tolerance on the turns instead, scaled by the
	 * extent squared, cut real corners when a point lay near the light's plane, far out. */
	double floor_tol = 1e-15 * lx_fmax(p[m - 1].x - p[0].x, yhi - ylo);
	int k = 0;
	for (int i = 0; i < m; i++) { /* lower hull */
		if (k > 0 && same_point(h[k - 1], p[i], floor_tol))
			continue;
		while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0)
			k--;
		h[k++] = p[i];
	}
	for (int i = m - 2, t = k + 1; i >= 0; i--) { /* upper hull */
		if (same_point(h[k - 1], p[i], floor_tol))
			continue;
		while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0)
			k--;
		h[k++] = p[i];
	}
	k = k > 1 ? k - 1 : k; /* the last point repeats the first */
	fit(h, k, out);
	if (p != stack)
		free(p);
	return k <= LX_POLY_MAX;
}

/* The part of polygon v (n <= LX_POLY_MAX vertices) on the side nx x + ny y + c >= 0,
 * into r (room for n + 1); returns its count. Each vertex's side is worked out once. */
static int clip_points(const vec2 *v, int n, double nx, double ny, double c, vec2 *r)
{
	double d[LX_POLY_MAX];
	int inside = 0;
	for (int i = 0; i < n; i++) {
		d[i] = nx * v[i].x + ny * v[i].y + c;
		inside += d[i] >= 0;
	}
	if (inside == 0)
		return 0;
	int rn = 0;
	if (inside == n) { /* most cuts take nothing: v as it is */
		memcpy(r, v, (size_t)n * sizeof(vec2));
		rn = n;
	} else
		for (int i = 0; i < n; i++) {
			int j = lx_loop_next(i, n);
			vec2 p = v[i], q = v[j];
			double dp = d[i], dq = d[j];
			if (dp >= 0)
				r[rn++] = p;
			if ((dp >= 0) != (dq >= 0)) {
				double t = dp / (dp - dq); /* signs differ: dp - dq != 0 */
				vec2 x = {p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t};
				if (!(rn && r[rn - 1].x == x.x && r[rn - 1].y == x.y))
					r[rn++] = x;
			}
		}
	/* no repeated vertices: they make zero-length edges */
	while (rn > 1 && r[rn - 1].x == r[0].x && r[rn - 1].y == r[0].y)
		rn--;
	return rn;
}

void lx_poly_clip_halfplane(const struct lx_poly *a, double nx, double ny, double c, struct lx_poly *out)
{
	vec2 r[LX_POLY_MAX + 1]; /* a convex n-gon cut by a line has at most n + 1 vertices */
	fit(r, clip_points(a->v, a->n, nx, ny, c, r), out);
}

/* Clipped in two buffers in turn, each cut fitted as lx_poly_clip_halfplane fits it,
 * copying only the vertices held (a polygon is a kilobyte, its few vertices far less). */
void lx_poly_intersect(const struct lx_poly *a, const struct lx_poly *b, struct lx_poly *out)
{
	vec2 buf[2][LX_POLY_MAX + 1];
	int n = b->n < 3 ? 0 : a->n, cur = 0;
	memcpy(buf[0], a->v, (size_t)n * sizeof(vec2));
	for (int i = 0; i < b->n && n > 0; i++) {
		vec2 p = b->v[i], q = b->v[lx_loop_next(i, b->n)];
		/* inside of a counter-clockwise edge p->q: cross(p, q, x) >= 0 */
		double nx = -(q.y - p.y), ny = q.x - p.x;
		n = clip_points(buf[cur], n, nx, ny, -(nx * p.x + ny * p.y), buf[1 - cur]);
		cur = 1 - cur;
		if (n > LX_POLY_MAX) { /* the 32-sided polygon around it, as fit gives */
			struct lx_poly t;
			fit(buf[cur], n, &t);
			n = t.n;
			memcpy(buf[cur], t.v, (size_t)n * sizeof(vec2));
		}
	}
	out->n = n;
	memcpy(out->v, buf[cur], (size_t)n * sizeof(vec2));
}

double lx_poly_area(const struct lx_poly *p)
{
	double s = 0;
	for (int i = 0; i < p->n; i++) {
		vec2 a = p->v[i], b = p->v[lx_loop_next(i, p->n)];
		s += a.x * b.y - a.y * b.x;
	}
	return 0.5 * s;
}

/* The part [*t0, *t1] of segment p + t (q - p), t in [0, 1], inside convex b, whose
 * winding is given: side 1 counter-clockwise, -1 clockwise; false when none of it is. */
static bool segment_in(const struct lx_poly *b, double side, vec2 p, vec2 q, double *t0, double *t1)
{
	*t0 = 0, *t1 = 1;
	for (int k = 0; k < b->n && *t0 < *t1; k++) {
		vec2 u = b->v[k], w = b->v[lx_loop_next(k, b->n)];
		double ex = w.x - u.x, ey = w.y - u.y;
		double f0 = side * (ex * (p.y - u.y) - ey * (p.x - u.x)), f1 = side * (ex * (q.y - u.y) - ey * (q.x - u.x));
		if (f0 < 0 && f1 < 0)
			*t1 = -1;
		else if (f0 < 0) /* f1 >= 0 > f0: f0 - f1 < 0 */
			*t0 = lx_fmax(*t0, f0 / (f0 - f1));
		else if (f1 < 0) /* f0 >= 0 > f1: f0 - f1 > 0 */
			*t1 = lx_fmin(*t1, f0 / (f0 - f1));
	}
	return *t1 > *t0;
}

void lx_poly_edges_inside(const struct lx_poly *a, const struct lx_poly *b, double *dx, double *dy)
{
	*dx = *dy = 0;
	if (b->n < 3)
		return;
	double side = lx_poly_area(b) < 0 ? -1 : 1;
	for (int i = 0; i < a->n; i++) {
		vec2 p = a->v[i], q = a->v[lx_loop_next(i, a->n)];
		double t0, t1;
		if (segment_in(b, side, p, q, &t0, &t1)) {
			*dx += (t1 - t0) * fabs(q.x - p.x);
			*dy += (t1 - t0) * fabs(q.y - p.y);
		}
	}
}

bool lx_poly_bounds_outside(const struct lx_poly *a, const struct lx_poly *b, vec2 ex, vec2 ey, double out[4])
{
	out[0] = out[1] = INFINITY, out[2] = out[3] = -INFINITY;
	double side = lx_poly_area(b) < 0 ? -1 : 1;
	for (int i = 0; i < a->n; i++) {
		vec2 p = a->v[i], q = a->v[lx_loop_next(i, a->n)], x[3];
		double t0 = 0, t1 = 1;
		int n = 0;
		/* the ends of the edge's parts outside b (its own end is the next edge's start) */
		if (b->n < 3 || !segment_in(b, side, p, q, &t0, &t1))
			x[n++] = p;
		else {
			if (t0 > 0)
				x[n++] = p, x[n++] = (vec2){p.x + (q.x - p.x) * t0, p.y + (q.y - p.y) * t0};
			if (t1 < 1)
				x[n++] = (vec2){p.x + (q.x - p.x) * t1, p.y + (q.y - p.y) * t1};
		}
		for (int k = 0; k < n; k++) { /* finite: ternaries, not fmin's library calls */
			double u = ex.x * x[k].x + ex.y * x[k].y, v = ey.x * x[k].x + ey.y * x[k].y;
			out[0] = u < out[0] ? u : out[0], out[1] = v < out[1] ? v : out[1];
			out[2] = u > out[2] ? u : out[2], out[3] = v > out[3] ? v : out[3];
		}
	}
	return out[0] <= out[2];
}

bool lx_poly_contains(const struct lx_poly *p, vec2 q, double eps)
{
	if (p->n < 3)
		return false;
	for (int i = 0; i < p->n; i++) {
		vec2 a = p->v[i], b = p->v[lx_loop_next(i, p->n)];
		double len = hypot(b.x - a.x, b.y - a.y);
		if (!(len > 0))
			continue; /* a repeated vertex bounds nothing */
		if (cross(a, b, q) / len <= eps)
			return false;
	}
	return true;
}

void lx_poly_bounds(const struct lx_poly *p, double *x0, double *y0, double *x1, double *y1)
{
	*x0 = *y0 = INFINITY;
	*x1 = *y1 = -INFINITY;
	for (int i = 0; i < p->n; i++) {
		*x0 = lx_fmin(*x0, p->v[i].x), *x1 = lx_fmax(*x1, p->v[i].x);
		*y0 = lx_fmin(*y0, p->v[i].y), *y1 = lx_fmax(*y1, p->v[i].y);
	}
}

/* The vertices of pieces, gathered for their hull in a fixed buffer: when it fills up it
 * is replaced by the hull of what it holds, which has the same hull as all of it. */
struct gather {
	vec2 pts[4 * LX_POLY_MAX];
	int n;
};

static void gather_piece(struct gather *g, const struct lx_poly *piece)
{
	if (g->n + piece->n > 4 * LX_POLY_MAX) {
		struct lx_poly h;
		lx_poly_hull(g->pts, g->n, &h);
		memcpy(g->pts, h.v, (size_t)h.n * sizeof(vec2));
		g->n = h.n;
	}
	memcpy(g->pts + g->n, piece->v, (size_t)piece->n * sizeof(vec2));
	g->n += piece->n;
}

/* a - interior(b) as convex pieces: for b's edges in turn, the part of what remains
 * outside that edge is a piece, the part inside goes on. Pieces without area (a boundary
 * shared with b) are dropped. Each piece goes to c's subtraction when c is given, else
 * to the gathering. */
static void subtract(const struct lx_poly *a, const struct lx_poly *b, const struct lx_poly *c, double min_area,
		     struct gather *g)
{
	if (b->n < 3) {
		if (c)
			subtract(a, c, NULL, min_area, g);
		else
			gather_piece(g, a);
		return;
	}
	struct lx_poly rest = *a, piece;
	for (int i = 0; i < b->n && rest.n >= 3; i++) {
		vec2 p = b->v[i], q = b->v[lx_loop_next(i, b->n)];
		double nx = -(q.y - p.y), ny = q.x - p.x, k = -(nx * p.x + ny * p.y); /* inside: >= 0 */
		if (nx == 0 && ny == 0)
			continue;
		lx_poly_clip_halfplane(&rest, -nx, -ny, -k, &piece);
		if (piece.n >= 3 && fabs(lx_poly_area(&piece)) > min_area) {
			if (c)
				subtract(&piece, c, NULL, min_area, g);
			else
				gather_piece(g, &piece);
		}
		lx_poly_clip_halfplane(&rest, nx, ny, k, &rest);
	}
}

void lx_poly_hull_of_difference(const struct lx_poly *a, const struct lx_poly *b, const struct lx_poly *c,
				struct lx_poly *out)
{
	out->n = 0;
	if (a->n < 3)
		return;
	struct gather g = {.n = 0};
	subtract(a, b, c, 1e-12 * fabs(lx_poly_area(a)), &g);
	lx_poly_hull(g.pts, g.n, out);
	if (out->n < 3)
		out->n = 0;
}

/* The polygon's extent along the line at height y: false when the line misses it. */
static bool cross_section(const struct lx_poly *p, double y, double *lo, double *hi)
{
	*lo = INFINITY, *hi = -INFINITY;
	for (int i = 0; i < p->n; i++) {
		vec2 a = p->v[i], b = p->v[lx_loop_next(i, p->n)];
		if ((a.y <= y) != (b.y <= y)) { /* a.y != b.y: the edge crosses the line */
			double x = a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y);
			*lo = lx_fmin(*lo, x), *hi = lx_fmax(*hi, x);
		}
	}
	return *lo <= *hi;
}

bool lx_poly_rows_inside(const struct lx_poly *p, int y0, int y1, double inset, int *x0, int *x1)
{
	double la, ha, lb, hb;
	if (y1 <= y0 || !cross_section(p, y0 + 0.5, &la, &ha) || !cross_section(p, y1 - 0.5, &lb, &hb))
		return false;
	double lo = lx_fmax(la, lb) + inset, hi = lx_fmin(ha, hb) - inset;
	if (!(lo <= hi) || !(lo > -1e9 && hi < 1e9)) /* (the callers' windows are far smaller) */
		return false;
	*x0 = (int)ceil(lo - 0.5), *x1 = (int)floor(hi - 0.5) + 1; /* centres x + 0.5 in [lo, hi] */
	return *x1 > *x0;
}

void lx_poly_shrink(const struct lx_poly *p, double d, struct lx_poly *out)
{
	out->n = 0;
	if (p->n < 3)
		return;
	vec2 c = {0, 0};
	for (int k = 0; k < p->n; k++)
		c.x += p->v[k].x / p->n, c.y += p->v[k].y / p->n;
	double least = INFINITY; /* the squared distance from c to the nearest edge's line */
	for (int k = 0; k < p->n; k++) {
		vec2 s = p->v[k], t = p->v[lx_loop_next(k, p->n)];
		double ex = t.x - s.x, ey = t.y - s.y, len2 = ex * ex + ey * ey, x = ex * (c.y - s.y) - ey * (c.x - s.x);
		if (len2 > 0) /* a hull leaves no edge of length 0; a guard all the same */
			least = lx_fmin(least, x * x / len2);
	}
	double rho = sqrt(least); /* least >= 0 */
	if (!(rho > d))
		return; /* the mean within d of an edge: thinner than 2 d, or rounding */
	double k = 1 - d / rho; /* an edge h >= rho from c moves in by h d / rho >= d */
	out->n = p->n;
	for (int i = 0; i < p->n; i++)
		out->v[i] = (vec2){c.x + (p->v[i].x - c.x) * k, c.y + (p->v[i].y - c.y) * k};
}

void lx_poly_inset(const struct lx_poly *p, double d, struct lx_poly *out)
{
	struct lx_poly a = *p; /* the edges are p's, whatever out is */
	*out = a;
	for (int k = 0; k < a.n && out->n >= 3; k++) { /* counter-clockwise: inside on the left */
		vec2 s = a.v[k], t = a.v[lx_loop_next(k, a.n)];
		double nx = -(t.y - s.y), ny = t.x - s.x, len = sqrt(nx * nx + ny * ny);
		if (len > 0) /* a hull leaves no edge of length 0; a guard all the same */
			lx_poly_clip_halfplane(out, nx, ny, -(nx * s.x + ny * s.y) - d * len, out);
	}
	if (out->n < 3)
		out->n = 0;
}
