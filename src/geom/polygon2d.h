/* Convex polygons in 2D, GL-free: hulls, intersections and the hull of a difference,
 * for the sets of wanted light rays drawn on a plane ([Chong-Gortler], section 3).
 * Polygons are counter-clockwise vertex lists. */
#ifndef LX_POLYGON2D_H
#define LX_POLYGON2D_H
#include <stdbool.h>

#define LX_POLY_MAX 64

typedef struct { double x, y; } vec2;

struct lx_poly {
	int n;
	vec2 v[LX_POLY_MAX];
};

/* Convex hull of n points (Andrew's monotone chain); collinear points dropped, and
 * points the same but for rounding (within a trillionth of their size), so that no edge
 * has a length of about 0. A hull
 * of more than LX_POLY_MAX vertices becomes a 32-sided polygon around it (a superset):
 * false then. Clipping (below) does the same where a cut would add the 65th vertex. */
bool lx_poly_hull(const vec2 *pts, int n, struct lx_poly *out);
/* Intersection of two convex polygons (clipping a by each edge of b); out may be a. */
void lx_poly_intersect(const struct lx_poly *a, const struct lx_poly *b, struct lx_poly *out);
/* Keeps the part of a on the side a.x * x + a.y * y + c >= 0 of a line. */
void lx_poly_clip_halfplane(const struct lx_poly *a, double nx, double ny, double c, struct lx_poly *out);
/* HULL(a - b - c) for convex a, b, c (b or c may be empty): the hull of every point of
 * a outside the interiors of b and c. Empty when that set has no area. */
void lx_poly_hull_of_difference(const struct lx_poly *a, const struct lx_poly *b, const struct lx_poly *c,
				struct lx_poly *out);
double lx_poly_area(const struct lx_poly *p);
/* The parts of a's edges inside convex b (either winding): the sums of their extents
 * along x (*dx) and along y (*dy). An edge's length times its normal's x component is
 * its extent along y: these weigh how much of a's outline runs along each axis. */
void lx_poly_edges_inside(const struct lx_poly *a, const struct lx_poly *b, double *dx, double *dy);
/* The bounds, along axes ex and ey, of the part of convex a outside the interior of
 * convex b (either winding): (lowest along ex, along ey, highest along ex, along ey),
 * those of HULL(a - b) but for rounding. That part's extremes lie at a's vertices outside b
 * or where a's edges leave b; false when none of a lies outside b. */
bool lx_poly_bounds_outside(const struct lx_poly *a, const struct lx_poly *b, vec2 ex, vec2 ey, double out[4]);
/* Strictly inside by more than eps (distance to every edge). */
bool lx_poly_contains(const struct lx_poly *p, vec2 q, double eps);
/* The pixels [*x0, *x1) whose centres, in every row of [y0, y1), lie inside p by more
 * than inset along the row (pixel (x, y) has its centre at x + 0.5, y + 0.5); false when
 * none. A convex polygon holds the segment between two of its points, so the first and
 * the last row decide. */
bool lx_poly_rows_inside(const struct lx_poly *p, int y0, int y1, double inset, int *x0, int *x1);
void lx_poly_bounds(const struct lx_poly *p, double *x0, double *y0, double *x1, double *y1);
/* Convex p scaled down about its vertices' mean so that every edge moves in by d or
 * more (within lx_poly_inset's result, for a few operations a vertex instead of a clip
 * an edge): empty (n = 0) when the mean lies within d of an edge. out may not be p. */
void lx_poly_shrink(const struct lx_poly *p, double d, struct lx_poly *out);
/* Convex counter-clockwise p moved in by d (every edge by d along its inner normal) into
 * out (may be p): empty (n = 0) when nothing is left. */
void lx_poly_inset(const struct lx_poly *p, double d, struct lx_poly *out);

#endif
