/* Vectors and 4x4 matrices in double precision.
 * Matrices are column-major (m[col*4 + row]) like GL, so they upload without a
 * transpose; every constructor states when it can fail instead of dividing by 0. */
#ifndef LX_LINALG_H
#define LX_LINALG_H
#include <math.h>
#include <stdbool.h>

typedef struct { double x, y, z; } vec3;
typedef struct { double x, y, z, w; } vec4;
typedef struct { double m[16]; } mat4;
typedef struct { double m[9]; } mat3; /* column-major too */

static inline vec3 v3(double x, double y, double z) { return (vec3){x, y, z}; }
/* The index after i in a closed loop of n (a polygon's next vertex): a compare where a
 * modulo would divide, in loops that run many times a frame. */
static inline int lx_loop_next(int i, int n) { return i + 1 < n ? i + 1 : 0; }
static inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 v3_scale(vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline double v3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/* fmin and fmax (a NaN loses), inline: x86-64's libm makes each a call, and a frame's
 * set-up makes thousands (inline, 5% fewer of its instructions, the same results bit
 * for bit). */
static inline double lx_fmin(double a, double b) { return a < b || isnan(b) ? a : b; }
static inline double lx_fmax(double a, double b) { return a > b || isnan(b) ? a : b; }
/* Per component: the corners of boxes grown to hold a point (a NaN loses). */
static inline vec3 v3_min(vec3 a, vec3 b) { return v3(lx_fmin(a.x, b.x), lx_fmin(a.y, b.y), lx_fmin(a.z, b.z)); }
static inline vec3 v3_max(vec3 a, vec3 b) { return v3(lx_fmax(a.x, b.x), lx_fmax(a.y, b.y), lx_fmax(a.z, b.z)); }
/* Corner k (0..7) of the box [lo, hi]: bit 0 picks x, bit 1 y, bit 2 z from hi. */
static inline vec3 v3_box_corner(vec3 lo, vec3 hi, int k)
{
	return (vec3){k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
}
static inline vec3 v3_cross(vec3 a, vec3 b)
{
	return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* The small helpers below are inline: the reference, the metrics and the per-pixel tests
 * call them millions of times a frame (out of line they were a tenth of test_extremes). */
static inline double v3_len(vec3 a) { return sqrt(v3_dot(a, a)); /* a sum of squares: >= 0 */ }
/* Unit vector; false (and *out untouched) when |a| is too small to normalise. */
static inline bool v3_normalize(vec3 a, vec3 *out)
{
	double l = v3_len(a);
	if (!(l > 1e-300) || !isfinite(l))
		return false;
	*out = v3_scale(a, 1.0 / l);
	return true;
}
bool v3_finite(vec3 a);

mat4 m4_identity(void);
mat4 m4_mul(const mat4 *a, const mat4 *b);
static inline vec4 m4_mul_v4(const mat4 *a, vec4 v)
{
	const double *m = a->m;
	return (vec4){m[0] * v.x + m[4] * v.y + m[8] * v.z + m[12] * v.w, m[1] * v.x + m[5] * v.y + m[9] * v.z + m[13] * v.w,
		      m[2] * v.x + m[6] * v.y + m[10] * v.z + m[14] * v.w, m[3] * v.x + m[7] * v.y + m[11] * v.z + m[15] * v.w};
}
static inline vec4 m4_mul_point(const mat4 *a, vec3 p) { return m4_mul_v4(a, (vec4){p.x, p.y, p.z, 1.0}); } /* w = 1 */
/* Row r of a matrix: as a plane, r . (x, y, z, 1) >= 0 on world points. */
static inline vec4 m4_row(const mat4 *m, int r) { return (vec4){m->m[r], m->m[4 + r], m->m[8 + r], m->m[12 + r]}; }
/* a p + b q */
static inline vec4 v4_lin(double a, vec4 p, double b, vec4 q)
{
	return (vec4){a * p.x + b * q.x, a * p.y + b * q.y, a * p.z + b * q.z, a * p.w + b * q.w};
}
static inline double v4_dot(vec4 a, vec4 b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }
/* a . (p, 1): the plane a at point p */
static inline double v4_dot_point(vec4 a, vec3 p) { return a.x * p.x + a.y * p.y + a.z * p.z + a.w; }
double v4_len(vec4 a);
/* The vector c with det[a; b; q; v] = c . v for every v (rows): orthogonal to a, b and q.
 * Of three points (p, 1), the plane through them; of a matrix's x, y and w rows, its
 * centre of projection, and then det[M p0 | M p1 | M p2] over those rows is
 * v4_cross3(rows) . v4_cross3(points): the sign of the triangle's projected area. */
vec4 v4_cross3(vec4 a, vec4 b, vec4 q);
/* Inverse by Gaussian elimination with partial pivoting; false when singular
 * (pivot below 1e-300 relative to the matrix's largest element). */
bool m4_invert(const mat4 *a, mat4 *out);
bool m4_finite(const mat4 *a);
mat4 m4_translate(vec3 t);
/* View matrix looking from eye to at; false if eye == at or up is parallel to the view. */
bool m4_look_at(vec3 eye, vec3 at, vec3 up, mat4 *out);
/* GL perspective (fovy in radians); false unless 0 < fovy < pi, aspect > 0, 0 < n < f. */
bool m4_perspective(double fovy, double aspect, double n, double f, mat4 *out);
/* GL orthographic; false when any extent is empty. */
bool m4_ortho(double l, double r, double b, double t, double n, double f, mat4 *out);

/* GL off-centre perspective (glFrustum); false unless l < r, b < t, 0 < n < f. */
bool m4_frustum(double l, double r, double b, double t, double n, double f, mat4 *out);

/* The affine map taking the box [x0, x1] x [y0, y1] x [z0, z1] onto [-1, 1]^3 (x0 -> -1,
 * z0 -> -1): the unit cube clipping step. z0 > z1 flips depth. Extents must not be empty. */
mat4 m4_crop(double x0, double x1, double y0, double y1, double z0, double z1);

mat3 m3_mul(const mat3 *a, const mat3 *b);
bool m3_invert(const mat3 *a, mat3 *out);

/* Solve A x = b (n x n, row-major A, n <= 16) with partial pivoting.
 * Returns false when a pivot falls below eps times the largest |A_ij|. */
bool lx_solve(int n, double *a, double *b, double eps);

#endif
