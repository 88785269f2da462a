#include "linalg.h"
#include <math.h>
#include <string.h>

bool v3_finite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

mat4 m4_identity(void)
{
	mat4 r = {{0}};
	r.m[0] = r.m[5] = r.m[10] = r.m[15] = 1.0;
	return r;
}

/* r = a b for column-major n x n matrices (r apart from a and b). */
static void square_mul(int n, const double *a, const double *b, double *r)
{
	for (int c = 0; c < n; c++)
		for (int row = 0; row < n; row++) {
			double s = 0;
			for (int k = 0; k < n; k++)
				s += a[k * n + row] * b[c * n + k];
			r[c * n + row] = s;
		}
}

mat4 m4_mul(const mat4 *a, const mat4 *b)
{
	mat4 r;
	square_mul(4, a->m, b->m, r.m);
	return r;
}

/* a x = b for the m columns of b (n x m, row-major) at once: each column goes through
 * the operations lx_solve would give it alone, so the results are the same to the bit. */
static bool solve_columns(int n, double *a, double *b, int m, double eps)
{
	double big = 0;
	for (int i = 0; i < n * n; i++)
		big = lx_fmax(big, fabs(a[i]));
	if (!(big > 0) || !isfinite(big))
		return false;
	for (int c = 0; c < n; c++) {
		int p = c;
		for (int r = c + 1; r < n; r++)
			if (fabs(a[r * n + c]) > fabs(a[p * n + c]))
				p = r;
		if (!(fabs(a[p * n + c]) > eps * big))
			return false;
		if (p != c) {
			for (int k = 0; k < n; k++) {
				double t = a[c * n + k];
				a[c * n + k] = a[p * n + k];
				a[p * n + k] = t;
			}
			for (int j = 0; j < m; j++) {
				double t = b[c * m + j];
				b[c * m + j] = b[p * m + j];
				b[p * m + j] = t;
			}
		}
		for (int r = c + 1; r < n; r++) {
			double f = a[r * n + c] / a[c * n + c]; /* pivot checked above */
			if (f == 0)
				continue;
			for (int k = c; k < n; k++)
				a[r * n + k] -= f * a[c * n + k];
			for (int j = 0; j < m; j++)
				b[r * m + j] -= f * b[c * m + j];
		}
	}
	for (int j = 0; j < m; j++)
		for (int r = n - 1; r >= 0; r--) {
			double s = b[r * m + j];
			for (int k = r + 1; k < n; k++)
				s -= a[r * n + k] * b[k * m + j];
			b[r * m + j] = s / a[r * n + r];
		}
	return true;
}

bool lx_solve(int n, double *a, double *b, double eps) { return solve_columns(n, a, b, 1, eps); }

/* r = a^-1 for a column-major n x n matrix (n <= 4): the identity's columns solved for
 * together (one elimination; pivots below eps fail). */
static bool square_invert(int n, const double *a, double *r, double eps)
{
	double A[16], B[16];
	for (int row = 0; row < n; row++)
		for (int k = 0; k < n; k++)
			A[row * n + k] = a[k * n + row], B[row * n + k] = row == k;
	if (!solve_columns(n, A, B, n, eps))
		return false;
	for (int c = 0; c < n; c++)
		for (int row = 0; row < n; row++)
			r[c * n + row] = B[row * n + c];
	return true;
}

bool m4_invert(const mat4 *a, mat4 *out)
{
	mat4 r;
	if (!square_invert(4, a->m, r.m, 1e-300) || !m4_finite(&r))
		return false;
	*out = r;
	return true;
}

bool m4_finite(const mat4 *a)
{
	for (int i = 0; i < 16; i++)
		if (!isfinite(a->m[i]))
			return false;
	return true;
}

mat4 m4_translate(vec3 t)
{
	mat4 r = m4_identity();
	r.m[12] = t.x;
	r.m[13] = t.y;
	r.m[14] = t.z;
	return r;
}

bool m4_look_at(vec3 eye, vec3 at, vec3 up, mat4 *out)
{
	vec3 f, s, u;
	if (!v3_normalize(v3_sub(at, eye), &f) || !v3_normalize(v3_cross(f, up), &s))
		return false;
	u = v3_cross(s, f);
	mat4 r = m4_identity();
	r.m[0] = s.x, r.m[4] = s.y, r.m[8] = s.z;
	r.m[1] = u.x, r.m[5] = u.y, r.m[9] = u.z;
	r.m[2] = -f.x, r.m[6] = -f.y, r.m[10] = -f.z;
	r.m[12] = -v3_dot(s, eye);
	r.m[13] = -v3_dot(u, eye);
	r.m[14] = v3_dot(f, eye);
	*out = r;
	return true;
}

bool m4_perspective(double fovy, double aspect, double n, double f, mat4 *out)
{
	if (!(fovy > 0 && fovy < M_PI && aspect > 0 && n > 0 && f > n) || !isfinite(f))
		return false;
	double t = 1.0 / tan(fovy / 2); /* fovy < pi so tan is finite and > 0 */
	mat4 r = {{0}};
	r.m[0] = t / aspect;
	r.m[5] = t;
	r.m[10] = (f + n) / (n - f);
	r.m[11] = -1.0;
	r.m[14] = 2.0 * f * n / (n - f);
	*out = r;
	return true;
}

bool m4_ortho(double l, double r_, double b, double t, double n, double f, mat4 *out)
{
	if (!(r_ > l && t > b && f > n))
		return false;
	mat4 r = m4_identity();
	r.m[0] = 2.0 / (r_ - l);
	r.m[5] = 2.0 / (t - b);
	r.m[10] = -2.0 / (f - n);
	r.m[12] = -(r_ + l) / (r_ - l);
	r.m[13] = -(t + b) / (t - b);
	r.m[14] = -(f + n) / (f - n);
	*out = r;
	return true;
}

bool m4_frustum(double l, double r_, double b, double t, double n, double f, mat4 *out)
{
	if (!(r_ > l && t > b && n > 0 && f > n) || !isfinite(f))
		return false;
	mat4 r = {{0}};
	r.m[0] = 2 * n / (r_ - l);
	r.m[5] = 2 * n / (t - b);
	r.m[8] = (r_ + l) / (r_ - l);
	r.m[9] = (t + b) / (t - b);
	r.m[10] = -(f + n) / (f - n);
	r.m[11] = -1.0;
	r.m[14] = -2 * f * n / (f - n);
	*out = r;
	return true;
}

mat4 m4_crop(double x0, double x1, double y0, double y1, double z0, double z1)
{
	mat4 c = m4_identity();
	c.m[0] = 2 / (x1 - x0), c.m[12] = -(x1 + x0) / (x1 - x0);
	c.m[5] = 2 / (y1 - y0), c.m[13] = -(y1 + y0) / (y1 - y0);
	c.m[10] = 2 / (z1 - z0), c.m[14] = -(z1 + z0) / (z1 - z0);
	return c;
}

mat3 m3_mul(const mat3 *a, const mat3 *b)
{
	mat3 r;
	square_mul(3, a->m, b->m, r.m);
	return r;
}

bool m3_invert(const mat3 *a, mat3 *out)
{
	mat3 r;
	if (!square_invert(3, a->m, r.m, 1e-14))
		return false;
	*out = r;
	return true;
}

double v4_len(vec4 a) { return sqrt(v4_dot(a, a)); /* a sum of squares: >= 0 */ }

/* 3x3 determinant of the rows (a, b, q) taken at columns i, j, k; inlined, so that the
 * constant columns fold (the shadow pass's convexity tests call v4_cross3 thousands of
 * times a frame) */
static inline __attribute__((always_inline)) double minor3(const double *a, const double *b, const double *q, int i,
								int j, int k)
{
	return a[i] * (b[j] * q[k] - b[k] * q[j]) - a[j] * (b[i] * q[k] - b[k] * q[i]) + a[k] * (b[i] * q[j] - b[j] * q[i]);
}

vec4 v4_cross3(vec4 a, vec4 b, vec4 q)
{
	/* the cofactors of the last row of [a; b; q; v]: (-1)^(3 + j) times the minor without column j */
	const double pa[4] = {a.x, a.y, a.z, a.w}, pb[4] = {b.x, b.y, b.z, b.w}, pq[4] = {q.x, q.y, q.z, q.w};
	return (vec4){-minor3(pa, pb, pq, 1, 2, 3), minor3(pa, pb, pq, 0, 2, 3), -minor3(pa, pb, pq, 0, 1, 3),
		      minor3(pa, pb, pq, 0, 1, 2)};
}
