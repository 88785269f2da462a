#include "linalg.h"
#include "convex.h"
#include "test_util.h"

static mat4 random_matrix(uint64_t *s)
{
	mat4 m;
	for (int i = 0; i < 16; i++)
		m.m[i] = test_rand(s) * 2 - 1;
	return m;
}

static void inverse_times_matrix_is_identity(void **state)
{
	(void)state;
	uint64_t s = 42;
	for (int k = 0; k < 200; k++) {
		mat4 a = random_matrix(&s), inv;
		assert_true(m4_invert(&a, &inv));
		mat4 p = m4_mul(&a, &inv);
		for (int i = 0; i < 16; i++)
			assert_near(p.m[i], (i % 5 == 0) ? 1.0 : 0.0, 1e-8);
	}
}

static void singular_matrices_are_refused(void **state)
{
	(void)state;
	mat4 a = m4_identity(), inv;
	a.m[10] = 0; /* a zero row and column */
	assert_false(m4_invert(&a, &inv));
	mat4 z = {{0}};
	assert_false(m4_invert(&z, &inv));
	double A[4] = {1, 2, 2, 4}, b[2] = {1, 1};
	assert_false(lx_solve(2, A, b, 1e-12));
}

static void solver_pivots(void **state)
{
	(void)state;
	/* a zero in the first pivot position needs a row swap */
	double A[9] = {0, 1, 1, 1, 0, 1, 1, 1, 0}, b[3] = {2, 2, 2};
	assert_true(lx_solve(3, A, b, 1e-12));
	for (int i = 0; i < 3; i++)
		assert_near(b[i], 1.0, 1e-12);
}

/* m4_invert eliminates once for the four columns: each must come out as lx_solve gives
 * it alone, to the bit (the maps' matrices, and so the golden images, rest on it). */
static void inverse_columns_are_the_solver_s(void **state)
{
	(void)state;
	unsigned long long x = 12345;
	for (int trial = 0; trial < 500; trial++) {
		mat4 a, inv;
		for (int i = 0; i < 16; i++) {
			x = x * 6364136223846793005ull + 1442695040888963407ull;
			a.m[i] = (double)(x >> 11) / 9007199254740992.0 * 2 - 1;
		}
		if (trial % 5 == 0)
			a.m[0] = 0; /* a swap at the first pivot */
		if (!m4_invert(&a, &inv))
			continue;
		for (int c = 0; c < 4; c++) {
			double A[16], b[4] = {0, 0, 0, 0};
			for (int row = 0; row < 4; row++)
				for (int k = 0; k < 4; k++)
					A[row * 4 + k] = a.m[k * 4 + row];
			b[c] = 1;
			assert_true(lx_solve(4, A, b, 1e-300));
			for (int row = 0; row < 4; row++)
				assert_memory_equal(&b[row], &inv.m[c * 4 + row], sizeof(double));
		}
	}
}

static void look_at_maps_eye_to_origin_and_view_to_minus_z(void **state)
{
	(void)state;
	mat4 v;
	assert_true(m4_look_at(v3(1, 2, 3), v3(1, 2, -7), v3(0, 1, 0), &v));
	vec4 e = m4_mul_point(&v, v3(1, 2, 3)), a = m4_mul_point(&v, v3(1, 2, -7));
	assert_near(e.x, 0, 1e-12); assert_near(e.y, 0, 1e-12); assert_near(e.z, 0, 1e-12);
	assert_near(a.x, 0, 1e-12); assert_near(a.y, 0, 1e-12); assert_near(a.z, -10, 1e-12);
	assert_false(m4_look_at(v3(0, 0, 0), v3(0, 0, 0), v3(0, 1, 0), &v));
	assert_false(m4_look_at(v3(0, 0, 0), v3(0, 5, 0), v3(0, 1, 0), &v)); /* looking along up */
}

static void projections_map_near_and_far_to_unit_cube(void **state)
{
	(void)state;
	mat4 p;
	assert_true(m4_perspective(1.0, 1.5, 0.5, 40, &p));
	vec4 n = m4_mul_point(&p, v3(0, 0, -0.5)), f = m4_mul_point(&p, v3(0, 0, -40));
	assert_near(n.z / n.w, -1, 1e-12);
	assert_near(f.z / f.w, 1, 1e-12);
	assert_true(m4_frustum(-1, 3, -2, 1, 0.5, 10, &p));
	vec4 c = m4_mul_point(&p, v3(3, 1, -0.5)); /* the near plane's top right corner */
	assert_near(c.x / c.w, 1, 1e-12); assert_near(c.y / c.w, 1, 1e-12); assert_near(c.z / c.w, -1, 1e-12);
	assert_true(m4_ortho(-1, 3, -2, 1, -4, 10, &p));
	c = m4_mul_point(&p, v3(-1, -2, 4));
	assert_near(c.x, -1, 1e-12); assert_near(c.y, -1, 1e-12); assert_near(c.z, -1, 1e-12);
	/* degenerate parameters are refused, not divided by */
	assert_false(m4_perspective(0, 1, 0.1, 10, &p));
	assert_false(m4_perspective(1, 1, 0, 10, &p));
	assert_false(m4_perspective(1, 1, 1, 1, &p));
	assert_false(m4_frustum(1, 1, -1, 1, 0.1, 10, &p));
	assert_false(m4_ortho(0, 1, 0, 1, 2, 2, &p));
}

static void normalize_guards_zero(void **state)
{
	(void)state;
	vec3 o = v3(7, 7, 7);
	assert_false(v3_normalize(v3(0, 0, 0), &o));
	assert_near(o.x, 7, 0);
	assert_true(v3_normalize(v3(3, 0, 4), &o));
	assert_near(o.x, 0.6, 1e-15);
}

static double det4_rows(vec4 r[4])
{
	/* by elimination with partial pivoting, each swap turning the sign */
	double a[4][4], d = 1;
	for (int i = 0; i < 4; i++)
		a[i][0] = r[i].x, a[i][1] = r[i].y, a[i][2] = r[i].z, a[i][3] = r[i].w;
	for (int c = 0; c < 4; c++) {
		int p = c;
		for (int i = c + 1; i < 4; i++)
			if (fabs(a[i][c]) > fabs(a[p][c]))
				p = i;
		if (p != c)
			for (int j = 0; j < 4; j++) {
				double t = a[c][j];
				a[c][j] = a[p][j], a[p][j] = t;
			}
		d *= p != c ? -a[c][c] : a[c][c];
		if (a[c][c] == 0)
			return 0;
		for (int i = c + 1; i < 4; i++)
			for (int j = c + 1; j < 4; j++)
				a[i][j] -= a[i][c] / a[c][c] * a[c][j];
	}
	return d;
}

/* lx_fmin and lx_fmax, which stand in for fmin and fmax in the set-up: the smaller and
 * the larger, either way round, and a NaN loses to a number (bounds start at a NaN-free
 * infinity and must stay finite past a corner that is not). */
static void min_and_max_let_a_nan_lose(void **state)
{
	(void)state;
	assert_true(lx_fmin(-1, 2) == -1 && lx_fmin(2, -1) == -1 && lx_fmax(-1, 2) == 2 && lx_fmax(2, -1) == 2);
	assert_true(lx_fmin(NAN, 3) == 3 && lx_fmin(3, NAN) == 3 && lx_fmax(NAN, 3) == 3 && lx_fmax(3, NAN) == 3);
	assert_true(lx_fmin(INFINITY, 5) == 5 && lx_fmax(-INFINITY, 5) == 5);
	assert_true(isnan(lx_fmin(NAN, NAN)) && isnan(lx_fmax(NAN, NAN)));
	vec3 lo = v3_min(v3(1, NAN, -2), v3(0, 4, -3));
	assert_true(lo.x == 0 && lo.y == 4 && lo.z == -3);
}

/* v4_cross3: det[a; b; q; v] = c . v for random rows and v, c orthogonal to a, b, q; and
 * the projected triangle's orientation it gives: a triangle's clip-space x, y, w
 * determinant equals c(rows) . c(points), so the sign says which way it turns on the screen. */
static void cross3_is_the_cofactor_vector(void **state)
{
	(void)state;
	uint64_t s = 7;
	for (int k = 0; k < 200; k++) {
		vec4 r[4];
		for (int i = 0; i < 4; i++)
			r[i] = (vec4){test_rand(&s) * 2 - 1, test_rand(&s) * 2 - 1, test_rand(&s) * 2 - 1, test_rand(&s) * 2 - 1};
		vec4 c = v4_cross3(r[0], r[1], r[2]);
		assert_near(v4_dot(c, r[3]), det4_rows(r), 1e-12);
		for (int i = 0; i < 3; i++)
			assert_near(v4_dot(c, r[i]), 0, 1e-12);
		mat4 m = random_matrix(&s);
		vec4 p[3], q[3];
		for (int i = 0; i < 3; i++) {
			p[i] = (vec4){test_rand(&s), test_rand(&s), test_rand(&s), 1};
			vec4 t = m4_mul_v4(&m, p[i]);
			q[i] = (vec4){t.x, t.y, t.w, 0}; /* the x, y, w the rasterizer divides */
		}
		double area3 = q[0].x * (q[1].y * q[2].z - q[1].z * q[2].y) - q[0].y * (q[1].x * q[2].z - q[1].z * q[2].x) +
			       q[0].z * (q[1].x * q[2].y - q[1].y * q[2].x);
		vec4 center = v4_cross3(m4_row(&m, 0), m4_row(&m, 1), m4_row(&m, 3));
		assert_near(v4_dot(center, v4_cross3(p[0], p[1], p[2])), area3, 1e-12);
	}
}

/* Whether p lies in the truncated pyramid below (near z = -1, far z = -10, sides through
 * the origin at 45 degrees) and in box lo..hi, both by tol. */
static bool in_both(vec3 p, vec3 lo, vec3 hi, double tol)
{
	double d = -p.z;
	return d >= 1 - tol && d <= 10 + tol && fabs(p.x) <= d + tol && fabs(p.y) <= d + tol && p.x >= lo.x - tol &&
	       p.y >= lo.y - tol && p.z >= lo.z - tol && p.x <= hi.x + tol && p.y <= hi.y + tol && p.z <= hi.z + tol;
}

/* lx_frustum_box_points: a box well inside the frustum comes back as its corners (the
 * short way, taken for the casters in view every frame), one the far plane or a side cuts
 * as points inside both, some on the cut. */
static void frustum_box_points_cut_a_box_or_keep_it(void **state)
{
	(void)state;
	vec3 fc[8] = {v3(-1, -1, -1),	v3(1, -1, -1),	v3(1, 1, -1),	v3(-1, 1, -1),
		      v3(-10, -10, -10), v3(10, -10, -10), v3(10, 10, -10), v3(-10, 10, -10)};
	vec3 pts[LX_CONVEX_MAX_POINTS];
	vec3 lo = v3(-0.5, -0.25, -5), hi = v3(0.5, 0.75, -2);
	int n = lx_frustum_box_points(fc, lo, hi, pts, LX_CONVEX_MAX_POINTS);
	assert_int_equal(n, 24); /* each face's four corners */
	for (int k = 0; k < 8; k++) {
		bool found = false;
		for (int i = 0; i < n; i++)
			found |= v3_len(v3_sub(pts[i], v3_box_corner(lo, hi, k))) == 0;
		assert_true(found);
	}
	for (int i = 0; i < n; i++)
		assert_true(in_both(pts[i], lo, hi, 0));
	/* across the far plane, and across a side (x = -z) */
	vec3 cut[2][2] = {{v3(-0.5, -0.5, -12), v3(0.5, 0.5, -5)}, {v3(1.5, -0.5, -3), v3(4, 0.5, -2)}};
	for (int c = 0; c < 2; c++) {
		n = lx_frustum_box_points(fc, cut[c][0], cut[c][1], pts, LX_CONVEX_MAX_POINTS);
		assert_true(n > 0);
		bool on_cut = false;
		for (int i = 0; i < n; i++) {
			assert_true(in_both(pts[i], cut[c][0], cut[c][1], 1e-9));
			on_cut |= c == 0 ? fabs(pts[i].z + 10) < 1e-9 : fabs(pts[i].x + pts[i].z) < 1e-9;
		}
		assert_true(on_cut);
	}
	/* a box wholly outside: nothing */
	assert_int_equal(lx_frustum_box_points(fc, v3(20, 20, -5), v3(21, 21, -4), pts, LX_CONVEX_MAX_POINTS), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(inverse_times_matrix_is_identity),
		cmocka_unit_test(singular_matrices_are_refused),
		cmocka_unit_test(solver_pivots),
		cmocka_unit_test(inverse_columns_are_the_solver_s),
		cmocka_unit_test(look_at_maps_eye_to_origin_and_view_to_minus_z),
		cmocka_unit_test(projections_map_near_and_far_to_unit_cube),
		cmocka_unit_test(normalize_guards_zero),
		cmocka_unit_test(min_and_max_let_a_nan_lose),
		cmocka_unit_test(cross3_is_the_cofactor_vector),
		cmocka_unit_test(frustum_box_points_cut_a_box_or_keep_it),
	};
	return cmocka_run_group_tests_name("linalg", tests, NULL, NULL);
}
