#include "light_image.h"
#include "light_space.h"
#include "metrics.h"
#include "reference.h"
#include "soft_reference.h"
#include "test_util.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A 10 m floor seen by camera (a "camera ..." line), one box (a "box ..." line) and the
 * given light. */
static void floor_scene(struct lx_scene *s, const char *camera, const char *box, struct lx_light light)
{
	char err[256], text[512];
	snprintf(text, sizeof text, "light point 0 5 0\n%s\nplane floor corner -5 0 5 edge1 10 0 0 edge2 0 0 -10\n%s\n",
		 camera, box);
	if (!lx_scene_parse(text, "test.scene", s, err, sizeof err))
		fail_msg("%s", err);
	s->light = light;
}

/* One box, 1 m wide with its bottom at 1 m, centred at the origin. */
static void box_scene(struct lx_scene *s, struct lx_light light)
{
	floor_scene(s, "camera eye 0 6 0.001 at 0 0 0 fov 60", "box size 1 1 1 at 0 0 bounce 1 1", light);
}

static void shadows_fall_where_geometry_says(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f;
	char err[256];
	/* light straight above at 5 m: the box (y from 1 to 2, x, z in [-0.5, 0.5]) casts a
	 * square of half-width 0.5 * 5 / (5 - 2) = 0.8333 on the floor */
	box_scene(&s, (struct lx_light){.position = {0, 5, 0}});
	assert_true(lx_meshes_build(&s, &m));
	assert_true(lx_frame_setup(&f, &s, &m, 0, 64, 64, err, sizeof err));
	struct lx_raycaster *rc = lx_raycaster_create(&f);
	assert_non_null(rc);
	double t;
	int tri = lx_raycast_first(rc, v3(0.8, 3, 0), v3(0, -1, 0), 0, 10, &t);
	assert_true(tri >= 0);
	assert_int_equal(lx_raycaster_object(rc, tri), 0); /* the floor */
	assert_near(t, 3, 1e-12);
	assert_true(lx_reference_shadowed(rc, &s.light, v3(0.80, 0, 0.0), tri));
	assert_true(lx_reference_shadowed(rc, &s.light, v3(0.83, 0, 0.83), tri));
	assert_false(lx_reference_shadowed(rc, &s.light, v3(0.84, 0, 0.0), tri));
	assert_false(lx_reference_shadowed(rc, &s.light, v3(3, 0, -3), tri));
	/* the top of the box is lit, its bottom faces away from the light */
	tri = lx_raycast_first(rc, v3(0.1, 4, 0.1), v3(0, -1, 0), 0, 10, &t);
	assert_int_equal(lx_raycaster_object(rc, tri), 1);
	assert_near(t, 2, 1e-12);
	assert_false(lx_reference_shadowed(rc, &s.light, v3(0.1, 2, 0.1), tri));
	tri = lx_raycast_first(rc, v3(0.1, -1, 0.1), v3(0, 1, 0), 0, 10, &t);
	assert_int_equal(lx_raycaster_object(rc, tri), 0); /* the floor is hit first from below */
	/* a point light below the floor: the floor's top faces away and is shadowed */
	struct lx_light under = {.position = {0, -1, 0}};
	tri = lx_raycast_first(rc, v3(3, 3, 3), v3(0, -1, 0), 0, 10, &t);
	assert_true(lx_reference_shadowed(rc, &under, v3(3, 0, 3), tri));
	/* a directional light at 45 degrees moves the shadow by the height */
	struct lx_light dir = {.directional = true};
	v3_normalize(v3(1, -1, 0), &dir.direction);
	tri = lx_raycast_first(rc, v3(1.5, 3, 0), v3(0, -1, 0), 0, 10, &t);
	assert_true(lx_reference_shadowed(rc, &dir, v3(1.5, 0, 0), tri)); /* x in [0.5, 2.5] is shadowed */
	assert_false(lx_reference_shadowed(rc, &dir, v3(0.45, 0, 0), tri));
	assert_false(lx_reference_shadowed(rc, &dir, v3(2.6, 0, 0), tri));
	lx_raycaster_destroy(rc);
	lx_meshes_free(&m);
}

/* Boxes and spheres at x = 1, 16, 16^2, ... 16^31, each a third of its distance wide (so
 * float vertices keep their shape): the BVH's splits over 16 bins peel one caster per
 * level, past LX_BVH_MAX_DEPTH; below the cap the leaves take the rest, and every caster
 * is still found by a ray (the traversal once dropped nodes silently when its stack
 * overflowed). */
static void bvh_depth_cap_loses_nothing(void **state)
{
	(void)state;
	struct lx_scene s = {0};
	s.light = (struct lx_light){.position = {0, 1e10, 0}};
	s.camera = (struct lx_camera){.eye = v3(0, 1e10, 1e9), .at = v3(0, 0, 0), .up = v3(0, 1, 0), .fovy_deg = 60};
	for (int k = 0; k < LX_MAX_CASTERS; k++) {
		double x = ldexp(1, 4 * k);
		s.casters[s.caster_count++] = (struct lx_caster){.shape = k % 2 ? LX_SPHERE : LX_BOX,
								 .size = v3(0.3 * x, 0.3 * x, 0.3 * x), .x = x, .period = 1,
								 .color = v3(1, 1, 1)};
	}
	struct lx_scene_meshes m;
	struct lx_frame f;
	char err[256];
	assert_true(lx_meshes_build(&s, &m));
	assert_true(lx_frame_setup(&f, &s, &m, 0, 16, 16, err, sizeof err));
	struct lx_raycaster *rc = lx_raycaster_create(&f);
	assert_non_null(rc);
	assert_int_equal(lx_raycaster_depth(rc), LX_BVH_MAX_DEPTH); /* the cap was reached */
	for (int k = 0; k < LX_MAX_CASTERS; k++) {
		double t;
		double x = ldexp(1, 4 * k);
		vec3 top = v3(x, 10 * x, 0);
		int tri = lx_raycast_first(rc, top, v3(0, -1, 0), 0, 100 * x, &t);
		assert_true(tri >= 0);
		assert_int_equal(lx_raycaster_object(rc, tri), k);
		assert_true(lx_raycast_any(rc, top, v3(0, -1, 0), 0, 100 * x, -1));
	}
	lx_raycaster_destroy(rc);
	lx_meshes_free(&m);
}

/* The default scene's frame at time 0, w x h. */
/* A built-in scene's meshes and its frame at time 0 (free with lx_meshes_free). */
static void scene_frame(void (*scene)(struct lx_scene *), struct lx_scene *s, struct lx_scene_meshes *m,
			struct lx_frame *f, int w, int h)
{
	char err[256];
	scene(s);
	assert_true(lx_meshes_build(s, m));
	assert_true(lx_frame_setup(f, s, m, 0, w, h, err, sizeof err));
}

/* Pixels the reference shadows for frame f (w x h) among those whose four neighbours see
 * the same object: off the objects' outlines, where a pixel's ray can graze an edge and
 * the ray caster decides by rounding (the table top flush with its slab, seen from
 * below: a ray past the slab's edge onto the top, and the shadow ray back along it). */
static long reference_shadowed(const struct lx_frame *f, int w, int h)
{
	long n = (long)w * h, shadowed = 0;
	int16_t *obj = malloc((size_t)n * sizeof(int16_t));
	uint8_t *sh = malloc((size_t)n);
	assert_true(obj && sh && lx_reference_image(f, obj, sh, 2));
	for (int y = 1; y < h - 1; y++)
		for (int x = 1; x < w - 1; x++) {
			long i = (long)y * w + x;
			shadowed += obj[i] != LX_NO_OBJECT && sh[i] == 1 && obj[i - 1] == obj[i] && obj[i + 1] == obj[i] &&
				    obj[i - w] == obj[i] && obj[i + w] == obj[i];
		}
	free(obj), free(sh);
	return shadowed;
}

/* The rule that lets every method draw no map (lx_shadows_hidden): with the point light
 * at the eye, over random views of both built-in scenes, the exact reference shadows no
 * pixel it sees; 20 cm above the eye the rule no longer holds, and shadows come into view.
 * A light a nanometre off the eye still counts as at it; a caster reaching between the
 * eye's plane and the near plane (the eye on the box's top, looking along it) turns the
 * rule off. */
static void hidden_shadows_are_hidden(void **state)
{
	(void)state;
	enum { W = 160, H = 120 };
	uint64_t seed = 77;
	int hidden = 0, seen_off = 0;
	char err[256];
	for (int k = 0; k < 24; k++) {
		struct lx_scene s;
		struct lx_scene_meshes m;
		struct lx_frame f;
		k % 2 ? lx_scene_table(&s) : lx_scene_default(&s);
		s.camera.eye = v3(test_rand(&seed) * 8 - 4, 0.3 + test_rand(&seed) * 4, test_rand(&seed) * 8 - 3);
		s.camera.at = v3(test_rand(&seed) * 4 - 2, test_rand(&seed) * 1.5, test_rand(&seed) * 4 - 4);
		s.light = lx_light_white(v3_add(s.camera.eye, v3(0, 1e-9, 0)));
		assert_true(lx_meshes_build(&s, &m));
		assert_true(lx_frame_setup(&f, &s, &m, 0.7 * k, W, H, err, sizeof err));
		if (lx_shadows_hidden(&f)) {
			hidden++;
			long n = reference_shadowed(&f, W, H);
			if (n != 0)
				fail_msg("view %d: the light at the eye, yet the reference shadows %ld pixels in sight", k, n);
		}
		s.light = lx_light_white(v3_add(s.camera.eye, v3(0, 0.2, 0)));
		assert_true(lx_frame_setup(&f, &s, &m, 0.7 * k, W, H, err, sizeof err));
		assert_false(lx_shadows_hidden(&f));
		seen_off += reference_shadowed(&f, W, H) > 0;
		lx_meshes_free(&m);
	}
	print_message("%d of 24 views hidden with the light at the eye; 20 cm above it, %d show a shadow\n", hidden,
		      seen_off);
	assert_true(hidden >= 20 && seen_off >= 12);
	/* the eye 0.1 mm above the default box's top, looking along it */
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f;
	lx_scene_default(&s);
	assert_true(lx_meshes_build(&s, &m));
	assert_true(lx_frame_setup(&f, &s, &m, 0, W, H, err, sizeof err));
	int box = s.plane_count + 1;
	vec3 top = v3(0.5 * (f.bmin[box].x + f.bmax[box].x), f.bmax[box].y + 1e-4, 0.5 * (f.bmin[box].z + f.bmax[box].z));
	s.camera.eye = top, s.camera.at = v3_add(top, v3(-1, 0, 0)), s.light = lx_light_white(top);
	assert_true(lx_frame_setup(&f, &s, &m, 0, W, H, err, sizeof err));
	assert_false(lx_shadows_hidden(&f));
	lx_meshes_free(&m);
}

static void reference_image_is_deterministic_across_threads(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f;
	scene_frame(lx_scene_default, &s, &m, &f, 96, 72);
	long n = 96 * 72;
	int16_t *o1 = malloc(n * sizeof(int16_t)), *o2 = malloc(n * sizeof(int16_t));
	uint8_t *s1 = malloc(n), *s2 = malloc(n);
	assert_true(lx_reference_image(&f, o1, s1, 1));
	assert_true(lx_reference_image(&f, o2, s2, 3));
	assert_memory_equal(o1, o2, n * sizeof(int16_t));
	assert_memory_equal(s1, s2, n);
	long floor = 0, shadowed = 0;
	for (long i = 0; i < n; i++)
		floor += o1[i] == 0, shadowed += s1[i];
	assert_true(floor > n / 4);    /* the floor fills much of the default view */
	assert_true(shadowed > n / 50); /* and shadows fall on it */
	free(o1), free(o2), free(s1), free(s2);
	lx_meshes_free(&m);
}

/* The table scene's top rests 1 mm above its slab, flush with the slab's edges. At
 * 1920x1080 one row of pixels along the table's front edge looks through that gap onto
 * the slab's top, which the table top hides from the light: the reference shadows it
 * (any triangle blocks), while in lixel a plane whose lit side faces the light casts
 * nothing, so every method lights it (results.md, the table at 1920x1080). This pins
 * the reference's side of that: the row is there, on the slab's top, and shadowed. */
/* Whether triangle tri (-1: none) is on the slab's top face. */
static bool on_slab_top(const struct lx_raycaster *rc, int tri, int slab)
{
	return tri >= 0 && lx_raycaster_object(rc, tri) == slab && lx_raycaster_normal(rc, tri).y > 0.99;
}

static void table_top_shades_the_slab_seen_through_the_gap(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f;
	scene_frame(lx_scene_table, &s, &m, &f, 1920, 1080);
	struct lx_raycaster *rc = lx_raycaster_create(&f);
	assert_non_null(rc);
	int slab = s.plane_count; /* the first caster */
	int rows = 0, row = -1;
	for (int y = 0; y < f.view.height; y++) { /* the middle column, through the table's front */
		vec3 p;
		int tri = lx_reference_pixel(&f, rc, f.view.width / 2, y, &p);
		if (on_slab_top(rc, tri, slab))
			rows++, row = y;
	}
	assert_int_equal(rows, 1);
	int seen = 0, shadowed = 0;
	for (int x = 0; x < f.view.width; x++) {
		vec3 p;
		int tri = lx_reference_pixel(&f, rc, x, row, &p);
		if (!on_slab_top(rc, tri, slab))
			continue;
		seen++;
		assert_true(p.y < 0.75 && p.y > 0.748); /* the slab's top, under the table top */
		shadowed += lx_reference_shadowed(rc, &f.light, p, tri);
	}
	print_message("the slab's top in view through the gap: %d pixels of row %d, %d shadowed\n", seen, row, shadowed);
	assert_true(seen > 500);
	assert_int_equal(shadowed, seen);
	lx_raycaster_destroy(rc);
	lx_meshes_free(&m);
}

/* lx_raycast_blocked_hint answers as lx_raycast_blocked whatever its hint (none, the one
 * carried from ray to ray as the soft reference does, a triangle that has nothing to do
 * with the ray, one out of range), and leaves a triangle of another object as the hint
 * when it answers "blocked": rays from points of the default view towards spots around
 * the light, blocked and not. */
static void hinted_rays_answer_as_plain_ones(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f;
	scene_frame(lx_scene_default, &s, &m, &f, 64, 48);
	struct lx_raycaster *rc = lx_raycaster_create(&f);
	assert_non_null(rc);
	long blocked = 0, open = 0, kept = 0;
	for (int y = 0; y < 48; y++)
		for (int x = 0; x < 64; x++) {
			vec3 p;
			int tri = lx_reference_pixel(&f, rc, x, y, &p), carried = -1;
			if (tri < 0)
				continue;
			int object = lx_raycaster_object(rc, tri);
			for (int k = 0; k < 25; k++) {
				vec3 spot = v3_add(s.light.position, v3(0.15 * (k % 5 - 2), 0, 0.15 * (k / 5 - 2)));
				vec3 d = v3_sub(spot, p);
				bool want = lx_raycast_blocked(rc, p, d, 1e-9, 1 - 1e-9, object);
				int hints[4] = {-1, carried, (x * 31 + y * 17 + k) % 200, 1 << 30};
				for (int h = 0; h < 4; h++) {
					int hint = hints[h], before = hint;
					bool got = lx_raycast_blocked_hint(rc, p, d, 1e-9, 1 - 1e-9, object, &hint);
					if (got != want)
						fail_msg("pixel (%d, %d) ray %d hint %d: blocked %d, the plain query says %d", x, y, k,
							 before, got, want);
					if (got) {
						assert_true(hint >= 0);
						assert_int_not_equal(lx_raycaster_object(rc, hint), object);
					} else {
						assert_int_equal(hint, before); /* kept when nothing blocks */
					}
					if (h == 1)
						kept += got && hint == before, carried = hint;
				}
				blocked += want, open += !want;
			}
		}
	print_message("%ld rays blocked, %ld not; %ld blocked by the carried hint\n", blocked, open, kept);
	assert_true(blocked > 1000 && open > 1000 && kept > blocked / 4);
	lx_raycaster_destroy(rc);
	lx_meshes_free(&m);
}

static void mismatch_counts_each_kind(void **state)
{
	(void)state;
	const int16_t ref_o[8] = {-1, 0, 0, 0, 0, 1, 1, -1};
	const uint8_t ref_s[8] = {0, 1, 0, 1, 0, 0, 1, 0};
	const int16_t o[8] = {-1, 0, 0, 0, 0, 1, 0, 2};
	const uint8_t s[8] = {0, 1, 1, 0, 0, 0, 1, 0};
	struct lx_mismatch mm;
	lx_mismatch_compare(ref_o, ref_s, o, s, 8, &mm);
	assert_int_equal(mm.compared, 5);
	assert_int_equal(mm.silhouette, 2);
	assert_int_equal(mm.false_shadow, 1);
	assert_int_equal(mm.missing_shadow, 1);
	assert_near(mm.mismatch_pct, 40, 1e-12);
	assert_near(mm.false_shadow_pct, 20, 1e-12);
}

static void jacobian_of_known_homographies(void **state)
{
	(void)state;
	double smax, smin;
	/* a similarity: rotation by 30 degrees and scale 2 */
	double c = 2 * cos(M_PI / 6), s = 2 * sin(M_PI / 6);
	mat3 h = {{c, s, 0, -s, c, 0, 5, 7, 1}};
	assert_true(lx_homography_jacobian(&h, 10, 20, &smax, &smin));
	assert_near(smax, 2, 1e-12);
	assert_near(smin, 2, 1e-12);
	/* anisotropic scale */
	mat3 a = {{3, 0, 0, 0, 0.5, 0, 0, 0, 1}};
	assert_true(lx_homography_jacobian(&a, 1, 1, &smax, &smin));
	assert_near(smax, 3, 1e-12);
	assert_near(smin, 0.5, 1e-12);
	/* a projective map u = x / (x + 1): du/dx = 1 / (x + 1)^2, v = y / (x + 1) */
	mat3 p = {{1, 0, 1, 0, 1, 0, 0, 0, 1}};
	assert_true(lx_homography_jacobian(&p, 1, 0, &smax, &smin));
	assert_near(smax, 0.5, 1e-12);
	assert_near(smin, 0.25, 1e-12);
	/* w' = 0: refused, not divided by */
	mat3 z = {{1, 0, 1, 0, 1, 0, 0, 0, 0}};
	assert_false(lx_homography_jacobian(&z, 0, 0, &smax, &smin));
}

/* The homography from the matrices agrees with projecting points by hand. */
static void plane_homography_matches_projection(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f;
	char err[256];
	scene_frame(lx_scene_default, &s, &m, &f, 200, 150);
	struct lx_region_request req[] = {{"m", 300, 200, 0, false, 0}};
	struct lx_atlas atlas;
	assert_true(lx_atlas_layout(&atlas, req, 1, 1, 2048, err, sizeof err));
	struct lx_shadow_map map = {.region = 0, .rendered = true};
	mat4 v, p;
	assert_true(m4_look_at(v3(1, 8, 2), v3(0, 0, 0), v3(0, 1, 0), &v));
	assert_true(m4_perspective(1.2, 1.5, 1, 20, &p));
	map.light_clip = m4_mul(&p, &v);
	mat3 h;
	assert_true(lx_plane_homography(&f, &atlas, &map, 0, &h));
	vec3 pts[] = {{0, 0, 0}, {1.5, 0, -2}, {-2, 0, 1}};
	for (int i = 0; i < 3; i++) {
		vec4 c = m4_mul_point(&f.view.view_proj, pts[i]), l = m4_mul_point(&map.light_clip, pts[i]);
		double x = (c.x / c.w + 1) * 100, y = (c.y / c.w + 1) * 75;
		double u = (l.x / l.w + 1) * 150, w = (l.y / l.w + 1) * 100;
		double hw = h.m[2] * x + h.m[5] * y + h.m[8];
		assert_near((h.m[0] * x + h.m[3] * y + h.m[6]) / hw, u, 1e-8);
		assert_near((h.m[1] * x + h.m[4] * y + h.m[7]) / hw, w, 1e-8);
	}
	lx_meshes_free(&m);
}

static int cmp_sorted(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* lx_median selects rather than sorts; it must give what a sort gives, for every length
 * (odd, even, one) and for arrays full of ties, sorted, reversed or random. */
static void median_equals_sorted_middle(void **state)
{
	(void)state;
	uint64_t seed = 7;
	double v[257], s[257];
	for (int n = 1; n <= 257; n++) {
		for (int kind = 0; kind < 4; kind++) {
			for (int i = 0; i < n; i++)
				v[i] = kind == 0 ? floor(test_rand(&seed) * 4) /* ties */
				       : kind == 1 ? i : kind == 2 ? n - i : test_rand(&seed) * 1e3 - 500;
			memcpy(s, v, (size_t)n * sizeof *v);
			qsort(s, (size_t)n, sizeof *s, cmp_sorted);
			double want = n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
			assert_true(lx_median(v, n) == want);
		}
	}
	assert_true(isnan(lx_median(v, 0)));
}

/* Paired ratios: per view, so a method faster on every view but one is seen as such,
 * whatever a pooled median says; views without two times are left out. */
static void paired_ratios_view_by_view(void **state)
{
	(void)state;
	struct lx_paired_ratios p;
	const double a[] = {3.3, 4.19, 4.0, NAN, 2.0, 5.0}, b[] = {3.5, 4.05, 4.0, 3.0, 0.0, 5.5};
	lx_paired_ratios(a, b, 6, &p);
	assert_int_equal(p.count, 4); /* the NaN and the zero time left out */
	assert_int_equal(p.most_at, 1);
	assert_true(fabs(p.most - 4.19 / 4.05) < 1e-15 && fabs(p.least - 5.0 / 5.5) < 1e-15);
	assert_int_equal(p.at_most_one, 3); /* 4.0 / 4.0 = 1 counts */
	assert_true(fabs(p.median - 0.5 * (3.3 / 3.5 + 1.0)) < 1e-15);
	lx_paired_ratios(a + 3, b + 3, 2, &p);
	assert_int_equal(p.count, 0);
	assert_int_equal(p.most_at, -1);
	assert_true(isnan(p.median) && isnan(p.most) && isnan(p.least));
	lx_paired_ratios(a, b, 0, &p);
	assert_int_equal(p.count, 0);
}

/* A view's difference resolved by its rounds: slower (or faster) in every round, not in
 * most of them; a tie, a missing time or a single round resolves nothing. */
static void rounds_sign_every_round(void **state)
{
	(void)state;
	const double a[] = {4.2, 4.4, 4.1, 4.3, 4.25}, b[] = {4.0, 4.3, 4.0, 4.2, 4.2};
	assert_int_equal(lx_rounds_sign(a, b, 5), 1);
	assert_int_equal(lx_rounds_sign(b, a, 5), -1);
	const double c[] = {4.2, 4.4, 3.9, 4.3, 4.25}; /* faster in one round of five */
	assert_int_equal(lx_rounds_sign(c, b, 5), 0);
	const double d[] = {4.2, 4.3, 4.1, 4.3, 4.25}; /* the same in one round */
	assert_int_equal(lx_rounds_sign(d, b, 5), 0);
	const double e[] = {4.2, 4.4, NAN, 4.3, 4.25}, z[] = {4.0, 4.3, 4.0, 0.0, 4.2};
	assert_int_equal(lx_rounds_sign(e, b, 5), 0);
	assert_int_equal(lx_rounds_sign(a, z, 5), 0);
	assert_int_equal(lx_rounds_sign(a, b, 1), 0);
	assert_int_equal(lx_rounds_sign(a, b, 0), 0);
	assert_int_equal(lx_rounds_sign(a, b, 2), 1);
}

/* A thin sheet 1 m above the floor covering x < 0: its edge along z at x = 0 casts a
 * straight penumbra. */
static void edge_scene(struct lx_scene *s, struct lx_light light, struct lx_scene_meshes *m, struct lx_frame *f)
{
	char err[256];
	floor_scene(s, "camera eye 0.5 3 3 at 0 0 0 fov 60", "box size 8 0.001 8 at -4 0 bounce 1 1", light);
	assert_true(lx_meshes_build(s, m));
	assert_true(lx_frame_setup(f, s, m, 0, 64, 64, err, sizeof err));
}

/* The share of a unit disc on the side u > t of a chord: its segment's area over pi. */
static double disc_beyond(double t)
{
	t = fmax(-1, fmin(1, t));
	return (acos(t) - t * sqrt(1 - t * t)) / M_PI;
}

/* The soft reference across a straight edge against the exact share of the light's disc
 * the edge leaves uncovered (a chord's segment): a directional light straight down of
 * 2 degrees (the disc of directions, radius h tan 1 degree on the floor), and a point
 * light 5 m up whose sphere subtends 2 degrees from the camera's target (the disc's
 * shadow through the edge: radius r h / (5 - h) on the floor, r the sphere's radius).
 * Each point within 0.05 (12 x 12 strata; an edge crosses about 17 of them), on average
 * within 0.012; a point light of size 0 is the hard reference. */
static void soft_reference_matches_a_penumbra(void **state)
{
	(void)state;
	for (int directional = 0; directional < 2; directional++) {
		struct lx_scene s;
		struct lx_scene_meshes m;
		struct lx_frame f;
		struct lx_light light = {.directional = directional, .position = {0, 5, 0}, .direction = {0, -1, 0}};
		edge_scene(&s, light, &m, &f);
		struct lx_raycaster *rc = lx_raycaster_create(&f);
		struct lx_area_light area, point;
		lx_area_light_make(&f, rc, 2.0, &area);
		lx_area_light_make(&f, rc, 0.0, &point);
		double half = directional ? tan(M_PI / 180) : area.radius * 1.0 / (5 - 1.0), worst = 0, sum = 0;
		int n = 0;
		for (double x = -1.5; x <= 1.5; x += 0.05, n++) {
			vec3 p = v3(x * half, 0, 0.3), o = v3(p.x, 0.5, p.z); /* below the sheet */
			double t;
			int tri = lx_raycast_first(rc, o, v3(0, -1, 0), 0, 10, &t);
			assert_int_equal(lx_raycaster_object(rc, tri), 0);
			/* uncovered where a sample's ray passes x > 0 at the edge's height: the disc
			 * beyond the chord at -x / half */
			double want = disc_beyond(-x), got = lx_soft_visibility(rc, &area, p, tri, (unsigned long long)n);
			worst = fmax(worst, fabs(got - want)), sum += fabs(got - want);
			double hard = lx_soft_visibility(rc, &point, p, tri, 0);
			assert_true(hard == (lx_reference_shadowed(rc, &s.light, p, tri) ? 0.0 : 1.0));
		}
		print_message("%s light: penumbra half-width %.4f m, worst error %.4f, mean %.4f over %d points\n",
			      directional ? "directional" : "point", half, worst, sum / n, n);
		assert_true(worst < 0.05);
		assert_true(sum / n < 0.012);
		lx_raycaster_destroy(rc);
		lx_meshes_free(&m);
	}
}

/* The soft image: the same with 1 and 3 threads, 1 on the background, 0 on faces turned
 * away from the light, and in [0, 1], with some pixels in between on the default view. */
static void soft_image_is_deterministic_and_bounded(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f;
	scene_frame(lx_scene_default, &s, &m, &f, 96, 72);
	long n = 96 * 72, between = 0;
	float *a = malloc(n * sizeof(float)), *b = malloc(n * sizeof(float));
	int16_t *o = malloc(n * sizeof(int16_t));
	uint8_t *sh = malloc(n);
	assert_true(lx_soft_reference_image(&f, 3.0, a, 1));
	assert_true(lx_soft_reference_image(&f, 3.0, b, 3));
	assert_memory_equal(a, b, n * sizeof(float));
	assert_true(lx_reference_image(&f, o, sh, 2));
	for (long i = 0; i < n; i++) {
		assert_true(a[i] >= 0 && a[i] <= 1);
		if (o[i] < 0)
			assert_true(a[i] == 1);
		between += a[i] > 0 && a[i] < 1;
	}
	print_message("%ld of %ld pixels in a penumbra of a 3-degree light\n", between, n);
	assert_true(between > 20);
	free(a), free(b), free(o), free(sh);
	lx_meshes_free(&m);
}

/* soft_error_pct over the compared pixels only, in percent. */
static void soft_error_counts_compared_pixels(void **state)
{
	(void)state;
	const int16_t ref_o[5] = {-1, 0, 0, 1, 1};
	const uint8_t ref_s[5] = {0, 0, 0, LX_REF_EDGE_ON, 0};
	const float ref_v[5] = {1, 0.5f, 1, 0, 0.25f};
	const int16_t o[5] = {-1, 0, 0, 1, 2};
	const uint8_t v[5] = {0, 255, 0, 255, 0};
	/* compared: pixels 1 and 2 (0 is background, 3 grazed, 4 a silhouette) */
	assert_near(lx_soft_error(ref_o, ref_s, ref_v, o, v, 5), 100 * (0.5 + 1.0) / 2, 1e-6);
	assert_near(lx_soft_error(ref_o, ref_s, ref_v, o, v, 1), 0, 0);
}

/* The shaded reference of a spotlight needs the light's image; with it the same decisions
 * come out as without colours. */
static void shaded_reference_needs_the_light_image(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m = {0};
	struct lx_frame f;
	char err[256];
	assert_true(lx_scene_builtin("spotlight", &s));
	assert_true(lx_meshes_build(&s, &m));
	assert_true(lx_frame_setup(&f, &s, &m, 0.4, 32, 24, err, sizeof err));
	int16_t o1[32 * 24], o2[32 * 24];
	uint8_t s1[32 * 24], s2[32 * 24], rgba[32 * 24 * 4];
	assert_false(lx_reference_image_shaded(&f, NULL, o1, s1, rgba, 2));
	struct lx_image beam;
	assert_true(lx_light_image_load(&s.light, &beam, err, sizeof err));
	assert_true(lx_reference_image_shaded(&f, &beam, o1, s1, rgba, 2));
	assert_true(lx_reference_image(&f, o2, s2, 1));
	assert_memory_equal(o1, o2, sizeof o1);
	assert_memory_equal(s1, s2, sizeof s1);
	lx_image_free(&beam);
	lx_meshes_free(&m);
}

/* The multi-light reference's tests: 120 x 90 views of the default scene at t = 0.3. */
#define LW 120
#define LH 90
#define LN (LW * LH)

struct shaded {
	int16_t object[LN];
	uint8_t shadowed[LN], rgba[LN * 4];
};

static void lights_frame(const char *scene, struct lx_scene *s, struct lx_scene_meshes *m, struct lx_frame *f)
{
	char err[256];
	assert_true(lx_scene_builtin(scene, s));
	assert_true(lx_meshes_build(s, m));
	assert_true(lx_frame_setup(f, s, m, 0.3, LW, LH, err, sizeof err));
}

/* The shaded reference of frame f's light alone (im: a projective light's image). */
static struct shaded *alone(const struct lx_frame *f, const struct lx_image *im)
{
	struct shaded *r = malloc(sizeof *r);
	assert_non_null(r);
	assert_true(lx_reference_image_shaded(f, im, r->object, r->shadowed, r->rgba, 3));
	return r;
}

/* Frames a's and b's lights together: a's decisions in r->shadowed, b's in sh_b. */
static struct shaded *together(const struct lx_frame *a, const struct lx_frame *b, uint8_t *sh_b)
{
	struct shaded *r = malloc(sizeof *r);
	assert_non_null(r);
	const struct lx_frame *frames[2] = {a, b};
	uint8_t *sh[2] = {r->shadowed, sh_b};
	assert_true(lx_reference_lights(frames, NULL, 2, r->object, sh, r->rgba, 3));
	return r;
}

/* One light through lx_reference_lights is lx_reference_image_shaded, byte for byte, for
 * a point light, a spotlight and a projector; n out of range and a projective light's
 * missing image are refused. */
static void one_light_is_the_single_reference(void **state)
{
	(void)state;
	static const char *const scenes[] = {"default", "spotlight", "projector"};
	struct shaded *b = malloc(sizeof *b);
	assert_non_null(b);
	for (int k = 0; k < 3; k++) {
		struct lx_scene s;
		struct lx_scene_meshes m;
		struct lx_frame f;
		struct lx_image im;
		char err[256];
		lights_frame(scenes[k], &s, &m, &f);
		assert_true(lx_light_image_load(&s.light, &im, err, sizeof err));
		const struct lx_image *ims[1] = {k ? &im : NULL}; /* a plain light needs no image */
		struct shaded *a = alone(&f, ims[0]);
		const struct lx_frame *frames[LX_MAX_LIGHTS + 1] = {&f, &f, &f, &f, &f};
		uint8_t *sh[LX_MAX_LIGHTS + 1] = {b->shadowed, b->shadowed, b->shadowed, b->shadowed, b->shadowed};
		memset(b, 0xa5, sizeof *b);
		assert_true(lx_reference_lights(frames, ims, 1, b->object, sh, b->rgba, 2));
		assert_memory_equal(a->object, b->object, sizeof a->object);
		assert_memory_equal(a->shadowed, b->shadowed, sizeof a->shadowed);
		assert_memory_equal(a->rgba, b->rgba, sizeof a->rgba);
		assert_false(lx_reference_lights(frames, ims, 0, b->object, sh, b->rgba, 2));
		assert_false(lx_reference_lights(frames, NULL, LX_MAX_LIGHTS + 1, b->object, sh, NULL, 2));
		/* without colours no image is needed; with them a projective light's is */
		assert_true(lx_reference_lights(frames, NULL, 1, b->object, sh, NULL, 2));
		assert_memory_equal(a->shadowed, b->shadowed, sizeof a->shadowed);
		assert_true(lx_reference_lights(frames, NULL, 1, b->object, sh, b->rgba, 2) == (k == 0));
		free(a);
		lx_image_free(&im);
		lx_meshes_free(&m);
	}
	free(b);
}

/* Two point lights. Each light's decisions are its own reference's. The colours add as
 * the passes do: with light 1 black (the ambient term alone, A) the image is A + D2, D2
 * light 2's pass, within one level of light 2's own image (a sum of two roundings against
 * one); with light 1 white it is min(255, S1 + D2), S1 light 1's own image, exactly, and
 * S1 itself where light 2 sends nothing. */
static void two_lights_add_as_the_passes_do(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f1, f2, fk;
	lights_frame("default", &s, &m, &f1);
	f2 = f1, fk = f1;
	f2.light.position = v3(-3, 4, 2.5);
	fk.light.color = v3(0, 0, 0);
	struct shaded *s1 = alone(&f1, NULL), *s2 = alone(&f2, NULL), *a = alone(&fk, NULL);
	uint8_t *sh2 = malloc(LN), *shk = malloc(LN);
	struct shaded *both = together(&f1, &f2, sh2), *k2 = together(&fk, &f2, shk);
	assert_memory_equal(both->object, s1->object, sizeof s1->object);
	assert_memory_equal(both->shadowed, s1->shadowed, LN);
	assert_memory_equal(sh2, s2->shadowed, LN);
	assert_memory_equal(shk, s2->shadowed, LN);
	long added = 0, clamped = 0, dark = 0;
	for (long i = 0; i < LN; i++)
		for (int ch = 0; ch < 3; ch++) {
			long j = i * 4 + ch, d2 = k2->rgba[j] - a->rgba[j], sum = s1->rgba[j] + d2;
			assert_true(d2 >= 0 && abs(k2->rgba[j] - s2->rgba[j]) <= 1);
			if (both->rgba[j] != (sum < 255 ? sum : 255))
				fail_msg("pixel %ld channel %d: %d, expected min(255, %d + %ld)", i, ch, both->rgba[j],
					 s1->rgba[j], d2);
			if (s1->object[i] < 0 || s2->shadowed[i] == 1) {
				assert_int_equal(both->rgba[j], s1->rgba[j]);
				dark++;
			}
			added += d2 > 0, clamped += sum > 255;
		}
	print_message("two lights: %ld channels added to, %ld clamped, %ld unchanged (background, light 2 shadowed)\n",
		      added, clamped, dark);
	assert_true(added > LN); /* light 2 lights much of the view */
	assert_true(clamped > 0 && dark > 0); /* and the clamp and its shadows are exercised */
	free(s1), free(s2), free(a), free(both), free(k2), free(sh2), free(shk);
	lx_meshes_free(&m);
}

/* Every light is multiplied by its colour, a point or a directional light too: a red
 * light's red is a white light's, its green and blue the ambient term's alone; added to a
 * white light, it changes no green or blue, and where only it lights (the white light's
 * shadow) green and blue stay at the ambient level. */
static void a_coloured_light_tints_its_own_channel(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame white, red, black, red2;
	lights_frame("default", &s, &m, &white);
	for (int directional = 0; directional < 2; directional++) {
		if (directional) {
			white.light.directional = true;
			assert_true(v3_normalize(v3(-0.4, -1, -0.3), &white.light.direction));
		}
		red = white, black = white, red2 = white;
		red.light.color = red2.light.color = v3(1, 0, 0), black.light.color = v3(0, 0, 0);
		red2.light.position = v3(-3, 4, 2.5); /* elsewhere: by position or by direction */
		assert_true(v3_normalize(v3(0.5, -1, -0.2), &red2.light.direction));
		struct shaded *w = alone(&white, NULL), *r = alone(&red, NULL), *a = alone(&black, NULL);
		uint8_t *sh2 = malloc(LN);
		struct shaded *both = together(&white, &red2, sh2);
		long greener = 0, only_red = 0;
		for (long i = 0; i < LN; i++) {
			const uint8_t *pw = w->rgba + i * 4, *pr = r->rgba + i * 4, *pa = a->rgba + i * 4;
			const uint8_t *pb = both->rgba + i * 4;
			assert_true(pr[0] == pw[0] && pr[1] == pa[1] && pr[2] == pa[2]);
			greener += pw[1] > pa[1];
			assert_true(pb[1] == pw[1] && pb[2] == pw[2] && pb[0] >= pw[0]);
			if (w->object[i] >= 0 && w->shadowed[i] == 1 && sh2[i] == 0) {
				assert_true(pb[1] == pa[1] && pb[2] == pa[2]);
				only_red += pb[0] > pa[0];
			}
		}
		print_message("%s: %ld pixels greener under white than under red, %ld lit red only\n",
			      directional ? "directional" : "point", greener, only_red);
		assert_true(greener > LN / 4); /* a white light does light green: the equality above means something */
		assert_true(only_red > 20);
		free(w), free(r), free(a), free(both), free(sh2);
	}
	lx_meshes_free(&m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(shadows_fall_where_geometry_says),
		cmocka_unit_test(bvh_depth_cap_loses_nothing),
		cmocka_unit_test(reference_image_is_deterministic_across_threads),
		cmocka_unit_test(hidden_shadows_are_hidden),
		cmocka_unit_test(hinted_rays_answer_as_plain_ones),
		cmocka_unit_test(table_top_shades_the_slab_seen_through_the_gap),
		cmocka_unit_test(mismatch_counts_each_kind),
		cmocka_unit_test(soft_reference_matches_a_penumbra),
		cmocka_unit_test(soft_image_is_deterministic_and_bounded),
		cmocka_unit_test(soft_error_counts_compared_pixels),
		cmocka_unit_test(median_equals_sorted_middle),
		cmocka_unit_test(paired_ratios_view_by_view),
		cmocka_unit_test(rounds_sign_every_round),
		cmocka_unit_test(shaded_reference_needs_the_light_image),
		cmocka_unit_test(one_light_is_the_single_reference),
		cmocka_unit_test(two_lights_add_as_the_passes_do),
		cmocka_unit_test(a_coloured_light_tints_its_own_channel),
		cmocka_unit_test(jacobian_of_known_homographies),
		cmocka_unit_test(plane_homography_matches_projection),
	};
	return cmocka_run_group_tests_name("reference", tests, NULL, NULL);
}
