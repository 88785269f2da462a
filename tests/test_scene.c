#include "configs.h"
#include "frame.h"
#include "light_image.h"
#include "mesh.h"
#include "scene.h"
#include "silhouette.h"
#include "test_util.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef LX_TEST_DATA
#define LX_TEST_DATA "tests/data"
#endif

static void default_scene_is_the_specified_one(void **state)
{
	(void)state;
	struct lx_scene s;
	lx_scene_default(&s);
	assert_int_equal(s.plane_count, 2);
	assert_string_equal(s.planes[0].name, "floor");
	assert_string_equal(s.planes[1].name, "wall");
	vec3 nf = lx_plane_normal(&s.planes[0]), nw = lx_plane_normal(&s.planes[1]);
	assert_near(nf.y, 1, 1e-12);
	assert_near(nw.z, 1, 1e-12);
	assert_near(s.planes[1].corner.z, -5, 0);
	assert_false(s.light.directional);
	assert_near(s.light.position.x, 2.5, 0); assert_near(s.light.position.y, 6, 0); assert_near(s.light.position.z, 3, 0);
	assert_near(s.camera.eye.y, 2, 0); assert_near(s.camera.eye.z, 6, 0); assert_near(s.camera.at.y, 0.8, 0);
	assert_near(s.camera.fovy_deg, 60, 0);
	/* a sphere of radius 0.6 and at least three other shapes */
	assert_true(s.caster_count >= 4);
	assert_int_equal(s.casters[0].shape, LX_SPHERE);
	assert_near(s.casters[0].size.x, 0.6, 0);
	bool shapes[LX_SHAPE_COUNT] = {false};
	for (int i = 0; i < s.caster_count; i++)
		shapes[s.casters[i].shape] = true;
	for (int k = 0; k < LX_SHAPE_COUNT; k++)
		assert_true(shapes[k]);
	/* they bounce between 0.3 and 2 inside x, z in [-3, 3], reaching both ends */
	for (int i = 0; i < s.caster_count; i++) {
		const struct lx_caster *c = &s.casters[i];
		double lo = 1e9, hi = -1e9;
		for (double t = 0; t < 60; t += 0.001) {
			double b = lx_caster_bottom(c, t);
			lo = fmin(lo, b), hi = fmax(hi, b);
		}
		assert_true(lo >= 0.3 - 1e-12 && lo < 0.31);
		assert_true(hi <= 2.0 + 1e-12 && hi > 1.99);
		assert_true(c->x - c->size.x >= -3 && c->x + c->size.x <= 3);
		assert_true(c->z - c->size.z >= -3 && c->z + c->size.z <= 3);
	}
}

static void same_scene(const struct lx_scene *a, const struct lx_scene *b)
{
	assert_int_equal(a->plane_count, b->plane_count);
	assert_int_equal(a->caster_count, b->caster_count);
	assert_memory_equal(a->planes, b->planes, sizeof a->planes);
	for (int i = 0; i < a->caster_count; i++) {
		assert_int_equal(a->casters[i].shape, b->casters[i].shape);
		assert_memory_equal(&a->casters[i].size, &b->casters[i].size, sizeof(vec3));
		assert_near(a->casters[i].x, b->casters[i].x, 0);
		assert_near(a->casters[i].z, b->casters[i].z, 0);
		assert_near(a->casters[i].low, b->casters[i].low, 0);
		assert_near(a->casters[i].high, b->casters[i].high, 0);
		assert_near(a->casters[i].period, b->casters[i].period, 0);
		assert_near(a->casters[i].phase, b->casters[i].phase, 0);
	}
	assert_int_equal(lx_scene_light_count(a), lx_scene_light_count(b));
	for (int i = 0; i < lx_scene_light_count(a); i++)
		assert_memory_equal(&a->lights[i], &b->lights[i], sizeof a->lights[i]);
	assert_memory_equal(&a->camera, &b->camera, sizeof a->camera);
}

static void scene_files_match_the_built_in_scenes(void **state)
{
	(void)state;
	static const char *const names[] = {"default", "table", "spotlight", "projector", "twolights"};
	for (int k = 0; k < 5; k++) {
		struct lx_scene a, b;
		char err[256], path[256];
		assert_true(lx_scene_builtin(names[k], &a));
		snprintf(path, sizeof path, "%s/%s.scene", LX_TEST_DATA, names[k]);
		if (!lx_scene_load(path, &b, err, sizeof err))
			fail_msg("%s", err);
		if (a.light.image == LX_IMAGE_BUILTIN_SLIDE) {
			/* the file names the slide the binary holds: the same pixels */
			struct lx_image ia, ib;
			assert_true(lx_light_image_load(&a.light, &ia, err, sizeof err));
			if (!lx_light_image_load(&b.light, &ib, err, sizeof err))
				fail_msg("%s", err);
			assert_int_equal(ia.width, ib.width);
			assert_int_equal(ia.height, ib.height);
			assert_memory_equal(ia.rgba, ib.rgba, (size_t)ia.width * ia.height * 4);
			lx_image_free(&ia);
			lx_image_free(&ib);
			b.light.image = a.light.image;
			memset(b.light.image_path, 0, sizeof b.light.image_path);
		}
		same_scene(&a, &b);
	}
	struct lx_scene c;
	assert_false(lx_scene_builtin("kitchen", &c));
}

struct bad_case {
	const char *text;
	int line;
	const char *expect; /* a fragment of the message */
};

static void malformed_files_name_the_line_and_what_was_expected(void **state)
{
	(void)state;
	static const struct bad_case cases[] = {
		{"light point 1 2\n", 1, "expected a number for light position"},
		{"light point 1 2 three\n", 1, "got 'three'"},
		{"light lamp 1 2 3\n", 1, "expected 'point', 'directional', 'spot' or 'projector'"},
		{"light spot 1 2 3\n", 1, "expected 'light spot X Y Z at X Y Z fov DEG"},
		{"light directional 0 0 0\n", 1, "non-zero light direction"},
		{"light point 0 5 0\nplane floor corner 0 0 0 edge1 1 0 0 edge2 2 0 0\n", 2, "not parallel"},
		/* found by fuzz_scene: the cross product's squared length overflowed, the
		 * plane was taken and lx_plane_normal fell back to (0, 1, 0) */
		/* found by fuzz_scene before numbers were bounded: a cross product too long to normalise */
		{"light point 0 5 0\nplane floor corner -5 0 5 edge1 10 0 1e154 edge2 0 9 0.3\n", 2, "from -1e+15 to 1e+15, got '1e154'"},
		{"light point 0 5 0\nplane floor corner 0 0 0 edge1 1 0 0\n", 2, "expected 'plane NAME"},
		{"light point 0 5 0\nplane floor corner 0 0 0 edge1 1 0 0 edge2 0 0 1\nplane floor corner 0 0 0 edge1 1 0 0 edge2 0 0 1\n",
		 3, "already defined"},
		{"light point 0 5 0\n\n# comment\nsphere radius -1 at 0 0\n", 4, "radius > 0"},
		{"light point 0 5 0\nsphere radius 1\n", 2, "'sphere radius R at X Z'"},
		{"light point 0 5 0\nbox size 1 1 1 at 0 0 bounce 2 1\n", 2, "LOW <= HIGH"},
		/* HIGH - LOW overflowed: the caster's height at time 0 was inf * 0 = NaN */
		/* HIGH - LOW overflowing to infinity gave NaN casters */
		{"light point 0 5 0\nbox size 1 1 1 at 0 0 bounce -1e308 1e308\n", 2, "from -1e+15 to 1e+15, got '-1e308'"},
		{"light point 0 5 0\ncone radius 1 height 1 at 0 0 wobble 3\n", 2, "unexpected 'wobble'"},
		{"light point 0 5 0\nteapot at 0 0\n", 2, "got 'teapot'"},
		{"light point 0 5 0\ncamera eye 0 0 0 at 0 0 0\n", 2, "eye differs from at"},
		{"light point 0 5 0\ncamera eye 0 1 5 at 0 0 0 fov 180\n", 2, "fov in (0, 180)"},
		{"light point 0 5 0\nlight point 1 5 0\nlight directional 0 -1 0\nlight point 2 5 0\nlight point 3 5 0\n", 5,
		 "expected at most 4 light lines, found one more"},
		{"light point 0 5 0 color 1 0.5\n", 1, "expected a number"},
		{"light directional 0 -1 0 color 1 1 1.5\n", 1, "color components in [0, 1]"},
		{"plane floor corner 0 0 0 edge1 1 0 0 edge2 0 0 -1\n", 2, "expected a 'light point"},
		{"light point 0 5 0\n", 2, "at least one plane or caster"},
		{"light point 0 5 0\nsphere radius 1e999 at 0 0\n", 2, "got '1e999'"},
		{"light point 0 5 0\nsphere radius nan at 0 0\n", 2, "got 'nan'"},
		{"light point 0 5 0\nsphere radius 1 at 0 0 color 2 0 0\n", 2, "color components in [0, 1]"},
		{"light point 0 5 0 extra\n", 1, "expected 'color R G B' or the end of the light line, got 'extra'"},
		{"light point 0 5 0 color 1 1 1 extra\n", 1, "unexpected 'extra'"},
		{"light point 0 5 0\nsphere radius 1e999 at 0 0\n", 2, "too large to hold"},
		{"light point 0 5 0\nsphere radius 1e-320 at 0 0\n", 2, "too small to hold"},
		{"light point 0 5 0\nsphere radius 1e-300 at 0 0\n", 2, "radius of at least 1e-30"},
		{"light point 0 5 0\nbox size 1 1e-31 1 at 0 0\n", 2, "box size y of at least 1e-30"},
		{"light point 0 5 0\nsphere radius 0x1p0 at 0 0\n", 2, "not a decimal number"},
		{"light point 0 2e15 0\n", 1, "from -1e+15 to 1e+15"},
		{"light point 0 5 0\nplane fallback corner 0 0 0 edge1 1 0 0 edge2 0 0 -1\n", 2, "other than 'fallback'"},
		{"light point 0 5 0\nplane fl\xffr corner 0 0 0 edge1 1 0 0 edge2 0 0 -1\n", 2, "expected a plane name"},
		{"light point 0 5 0\nplane fl\"r corner 0 0 0 edge1 1 0 0 edge2 0 0 -1\n", 2, "expected a plane name"},
		/* projective lights */
		{"light spot 0 5 0 at 0 0 0 fov 0\n", 1, "light fov in (0, 150) degrees, got 0"},
		{"light spot 0 5 0 at 0 0 0 fov 150\n", 1, "light fov in (0, 150)"},
		{"light spot 0 5 0 fov 40\n", 1, "expected 'light spot X Y Z at X Y Z fov DEG"},
		{"light spot 0 5 0 at 0 5 0 fov 40\n", 1, "position differs from at"},
		{"light spot 0 5 0 at 0 0 0 fov 40 up 0 -1 0\n", 1, "up is not along its axis"},
		{"light spot 0 5 0 at 0 0 0 fov 40 range 3 2\n", 1, "0 <= NEAR < FAR, got 3 2"},
		{"light spot 0 5 0 at 0 0 0 fov 40 range -1 2\n", 1, "0 <= NEAR < FAR"},
		{"light spot 0 5 0 at 0 0 0 fov 40 color 1 2 1\n", 1, "color components in [0, 1]"},
		{"light spot 0 5 0 at 0 0 0 fov 40 slide x.png\n", 1, "expected at, fov, up, beam, color or range in a spot light, got 'slide'"},
		{"light projector 0 5 0 at 0 0 0 fov 40\n", 1, "expected 'slide FILE.png' in a projector light"},
		{"light projector 0 5 0 at 0 0 0 fov 40 slide\n", 1, "expected a PNG file after 'slide'"},
		{"light projector 0 5 0 at 0 0 0 fov 40 slide no-such.png\n", 1, "slide 'no-such.png': cannot read it"},
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct lx_scene s;
		char err[256], prefix[64];
		if (lx_scene_parse(cases[i].text, "bad.scene", &s, err, sizeof err))
			fail_msg("case %zu parsed but should not have: %s", i, cases[i].text);
		snprintf(prefix, sizeof prefix, "bad.scene:%d: ", cases[i].line);
		if (strncmp(err, prefix, strlen(prefix)) || !strstr(err, cases[i].expect))
			fail_msg("case %zu: got \"%s\", expected \"%s...%s\"", i, err, prefix, cases[i].expect);
		assert_null(strchr(err, '\n')); /* one line */
	}
}

static void missing_and_binary_files(void **state)
{
	(void)state;
	struct lx_scene s;
	char err[256];
	assert_false(lx_scene_load(LX_TEST_DATA "/no-such-file.scene", &s, err, sizeof err));
	assert_non_null(strstr(err, "no-such-file.scene: cannot open"));
	assert_false(lx_scene_load(LX_TEST_DATA, &s, err, sizeof err)); /* a directory */
	/* a slide that is not a PNG; one resolved against the scene file's folder */
	assert_false(lx_scene_parse("light projector 0 5 0 at 0 0 0 fov 40 slide default.scene\nsphere radius 1 at 0 0\n",
				    LX_TEST_DATA "/p.scene", &s, err, sizeof err));
	assert_non_null(strstr(err, "default.scene': expected a PNG file"));
	assert_true(lx_scene_parse("light projector 0 5 0 at 0 0 0 fov 40 slide slide.png\nsphere radius 1 at 0 0\n",
				   LX_TEST_DATA "/p.scene", &s, err, sizeof err));
	assert_int_equal(s.light.image, LX_IMAGE_FILE);
	assert_true(fabs(s.light.aspect - 256.0 / 192) < 1e-12); /* from the PNG's header */
}

/* Validation is relative to the scene's own size: the default scene in micrometres or
 * in thousands of kilometres is as valid as in metres (an absolute 1e-9 once refused
 * the first). */
static void any_scale_parses(void **state)
{
	(void)state;
	static const char *const texts[] = {
		"camera eye 0 2e-6 6e-6 at 0 8e-7 0\nlight point 2.5e-6 6e-6 3e-6\n"
		"plane floor corner -5e-6 0 5e-6 edge1 1e-5 0 0 edge2 0 0 -1e-5\nsphere radius 6e-7 at 0 0 bounce 3e-7 2e-6\n",
		"camera eye 0 2e9 6e9 at 0 8e8 0\nlight point 2.5e9 6e9 3e9\n"
		"plane floor corner -5e9 0 5e9 edge1 1e10 0 0 edge2 0 0 -1e10\nsphere radius 6e8 at 0 0 bounce 3e8 2e9\n"};
	for (int i = 0; i < 2; i++) {
		struct lx_scene s;
		char err[256];
		if (!lx_scene_parse(texts[i], "scaled.scene", &s, err, sizeof err))
			fail_msg("scale %d: %s", i, err);
		assert_int_equal(s.plane_count, 1);
	}
}

static void directional_light_and_defaults(void **state)
{
	(void)state;
	struct lx_scene s;
	char err[256];
	const char *text = "light directional 0 -2 0\nbox size 1 2 3 at 0.5 -0.5\n";
	if (!lx_scene_parse(text, "ok.scene", &s, err, sizeof err))
		fail_msg("%s", err);
	assert_true(s.light.directional);
	assert_near(s.light.direction.y, -1, 1e-15);
	assert_int_equal(s.caster_count, 1);
	assert_near(s.casters[0].size.z, 3, 0);
	assert_near(s.camera.fovy_deg, 60, 0);
}

static void assert_color(vec3 c, double r, double g, double b)
{
	if (!(c.x == r && c.y == g && c.z == b))
		fail_msg("light colour %g %g %g, expected %g %g %g", c.x, c.y, c.z, r, g, b);
}

/* Every light is multiplied by its colour, so a light nobody coloured must be white
 * whichever way it was made: parsed, built in, set by a configuration, or turned
 * directional by the frame for being far away (which keeps a colour it has). */
/* Up to four lights, in file order, each with its own kind and colour; scaling moves all. */
static void several_lights_keep_their_order_and_scale(void **state)
{
	(void)state;
	struct lx_scene s;
	char err[256];
	if (!lx_scene_parse("light point 1 5 0 color 0.5 0.4 0.3\nlight directional 0 -2 0\n"
			    "light spot -2 4 1 at 0 0 0 fov 50 color 0 0 1\nlight point 0 6 -1\nsphere radius 1 at 0 0\n",
			    "four.scene", &s, err, sizeof err))
		fail_msg("%s", err);
	assert_int_equal(lx_scene_light_count(&s), 4);
	assert_true(s.lights[0].position.x == 1 && s.lights[0].color.x == 0.5 && s.lights[0].color.z == 0.3);
	assert_true(s.lights[1].directional && s.lights[1].direction.y == -1);
	assert_true(s.lights[1].color.x == 1 && s.lights[1].color.y == 1 && s.lights[1].color.z == 1);
	assert_int_equal(s.lights[2].projective, LX_LIGHT_SPOT);
	assert_true(s.lights[2].color.x == 0 && s.lights[2].color.z == 1);
	assert_true(s.lights[3].position.y == 6 && !s.lights[3].directional);
	assert_true(&s.light == &s.lights[0]); /* the first light is the one the methods read */
	lx_scene_scale(&s, 2);
	assert_true(s.lights[0].position.x == 2 && s.lights[3].position.y == 12 && s.lights[2].at.x == 0);
	assert_true(s.lights[2].position.x == -4 && s.lights[1].direction.y == -1);
	/* the built-in two-light scene; a scene built by hand with its light only has one */
	assert_true(lx_scene_builtin("twolights", &s));
	assert_int_equal(lx_scene_light_count(&s), 2);
	assert_int_equal(s.lights[1].projective, LX_LIGHT_SPOT);
	struct lx_scene hand = {0};
	hand.light = lx_light_white(v3(0, 5, 0));
	assert_int_equal(lx_scene_light_count(&hand), 1);
}

static void lights_are_white_unless_coloured(void **state)
{
	(void)state;
	static const char *const texts[] = {"light point 0 5 0\n", "light directional 0 -2 0\n",
					    "light spot 0 5 0 at 0 0 0 fov 40\n"};
	struct lx_scene s;
	char err[256], text[256];
	for (int i = 0; i < 3; i++) {
		snprintf(text, sizeof text, "%sbox size 1 1 1 at 0 0\n", texts[i]);
		if (!lx_scene_parse(text, "white.scene", &s, err, sizeof err))
			fail_msg("%s", err);
		assert_color(s.light.color, 1, 1, 1);
	}
	if (!lx_scene_parse("light spot 0 5 0 at 0 0 0 fov 40 color 1 0.5 0\nbox size 1 1 1 at 0 0\n", "c.scene", &s,
			    err, sizeof err))
		fail_msg("%s", err);
	assert_color(s.light.color, 1, 0.5, 0);
	static const char *const builtins[] = {"default", "table", "projector"};
	for (int i = 0; i < 3; i++) {
		assert_true(lx_scene_builtin(builtins[i], &s));
		assert_color(s.light.color, 1, 1, 1);
	}
	for (int i = 0; i < lx_config_count; i++) {
		lx_scene_default(&s);
		lx_config_apply(&lx_configs[i], &s);
		assert_color(s.light.color, 1, 1, 1);
	}
	/* a point light 1e9 m away: the frame takes it as directional, in its own colour */
	lx_scene_default(&s);
	s.light.position = v3(0, 1e9, 0), s.light.color = v3(0.5, 0.25, 1);
	struct lx_scene_meshes m;
	struct lx_frame f;
	assert_true(lx_meshes_build(&s, &m));
	assert_true(lx_frame_setup(&f, &s, &m, 0, 32, 24, err, sizeof err));
	assert_true(f.light.directional);
	assert_color(f.light.color, 0.5, 0.25, 1);
	lx_meshes_free(&m);
}

/* The shadow rule (back faces are shadowed) needs closed, outward-facing meshes. */
static void caster_meshes_are_closed_and_outward(void **state)
{
	(void)state;
	struct lx_scene s;
	lx_scene_default(&s);
	struct lx_scene_meshes m;
	assert_true(lx_meshes_build(&s, &m));
	assert_int_equal(m.count, s.plane_count + s.caster_count);
	for (int id = s.plane_count; id < m.count; id++) {
		const struct lx_mesh *me = &m.mesh[id];
		vec3 c = v3_scale(v3_add(me->bmin, me->bmax), 0.5);
		double area_normal[3] = {0, 0, 0}; /* a closed surface's vector area is zero */
		for (int i = 0; i < me->vertex_count; i += 3) {
			const float *a = me->v + (size_t)i * LX_VERTEX_FLOATS, *b = a + LX_VERTEX_FLOATS, *d = b + LX_VERTEX_FLOATS;
			vec3 pa = v3(a[0], a[1], a[2]), pb = v3(b[0], b[1], b[2]), pd = v3(d[0], d[1], d[2]);
			vec3 n = v3_cross(v3_sub(pb, pa), v3_sub(pd, pa));
			vec3 centroid = v3_scale(v3_add(pa, v3_add(pb, pd)), 1.0 / 3);
			if (!(v3_dot(n, v3_sub(centroid, c)) > 0))
				fail_msg("object %d (%s): triangle %d faces inwards", id, lx_shape_name(s.casters[id - s.plane_count].shape), i / 3);
			/* the stored face normal agrees with the winding */
			assert_true(v3_dot(n, v3(a[6], a[7], a[8])) > 0);
			area_normal[0] += n.x, area_normal[1] += n.y, area_normal[2] += n.z;
		}
		for (int k = 0; k < 3; k++)
			assert_near(area_normal[k], 0, 1e-5);
	}
	lx_meshes_free(&m);
}

/* A mesh's positions each once (exact floats, as the renderer's shadow mesh), its
 * corners as indices into them; returns the count of positions. */
static int index_positions(const struct lx_mesh *me, float *pos, unsigned short *index)
{
	int np = 0;
	for (int i = 0; i < me->vertex_count; i++) {
		const float *q = me->v + (size_t)i * LX_VERTEX_FLOATS;
		int k = 0;
		while (k < np && memcmp(pos + 3 * k, q, 3 * sizeof(float)))
			k++;
		if (k == np)
			memcpy(pos + 3 * np++, q, 3 * sizeof(float));
		index[i] = (unsigned short)k;
	}
	return np;
}

/* Twice the signed area of a triangle's image seen from light L (a central projection
 * onto the plane across `axis` at unit distance). */
static double image_area2(vec3 L, vec3 axis, vec3 u, vec3 v, const float *a, const float *b, const float *c)
{
	const float *p[3] = {a, b, c};
	double x[3], y[3];
	for (int k = 0; k < 3; k++) {
		vec3 d = v3_sub(v3(p[k][0], p[k][1], p[k][2]), L);
		double z = v3_dot(d, axis); /* > 0: the light is outside the caster */
		x[k] = v3_dot(d, u) / z, y[k] = v3_dot(d, v) / z;
	}
	return (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
}

/* The band between the faces turned away (kept, their fan `outer` of `count` indices)
 * and those turned away by more than 30 degrees from edge-on (the renderer's
 * FAN_WELL_AWAY) as lx_fan_band_strip draws it, for the light at L looking along axis (u,
 * v across): its triangles' images wound as the faces', the mesh's own corners, covering
 * the band's faces' image. Returns 1 where a strip was made, 0 where the inner faces are
 * not one disk. */
static int check_band_strip(const float *pos, const unsigned short *welded, const int *adj, int t, int np,
			    const bool *kept, const unsigned short *outer, int count, vec3 L, vec3 axis, vec3 u, vec3 v,
			    double sign, int *next, int id, int trial)
{
	int n = 3 * t;
	bool *inner = malloc((size_t)t * sizeof *inner);
	unsigned short *fan = malloc((size_t)n * sizeof *fan), *strip = malloc((size_t)n * sizeof *strip);
	unsigned short *loop = malloc((size_t)n * sizeof *loop);
	double *work = malloc((size_t)2 * n * sizeof *work);
	assert_true(inner && fan && strip && loop && work);
	double band = 0;
	for (int k = 0; k < t; k++) {
		const float *a = pos + 3 * welded[3 * k], *b = pos + 3 * welded[3 * k + 1], *d = pos + 3 * welded[3 * k + 2];
		vec3 pa = v3(a[0], a[1], a[2]), pb = v3(b[0], b[1], b[2]), pd = v3(d[0], d[1], d[2]);
		vec3 nrm = v3_cross(v3_sub(pb, pa), v3_sub(pd, pa)), to = v3_sub(L, pa);
		inner[k] = kept[k] && -v3_dot(nrm, to) > 0.5 * v3_len(nrm) * v3_len(to);
		if (kept[k] && !inner[k] && adj[3 * k] >= 0)
			band += image_area2(L, axis, u, v, a, b, d);
	}
	int made = 0, ni = lx_silhouette_fan(welded, adj, t, inner, (unsigned short)np, next, fan, n);
	if (ni > 0) {
		mat4 lc = {{0}}; /* x, y and w: u, v and axis from L */
		vec3 row[3] = {u, v, axis};
		for (int r = 0; r < 3; r++) {
			int at = r == 2 ? 3 : r;
			lc.m[at] = row[r].x, lc.m[4 + at] = row[r].y, lc.m[8 + at] = row[r].z, lc.m[12 + at] = -v3_dot(row[r], L);
		}
		lc.m[2] = axis.x, lc.m[6] = axis.y, lc.m[10] = axis.z, lc.m[14] = -v3_dot(axis, L);
		int got = lx_fan_band_strip(outer, count, fan, ni, pos, &lc, next, loop, work, strip, n);
		for (int k = 0; k <= np; k++)
			assert_int_equal(next[k], -1);
		if (got < 0) /* at some corner neither triangle turns as the faces: the renderer keeps them */
			goto done;
		if (got != count + ni)
			fail_msg("object %d, light %d: a strip of %d indices across a band of %d and %d", id, trial, got, count, ni);
		double covered = 0, least = 0;
		for (int k = 0; k < got; k += 3) {
			assert_true(strip[k] != np && strip[k + 1] != np && strip[k + 2] != np);
			double a2 = image_area2(L, axis, u, v, pos + 3 * strip[k], pos + 3 * strip[k + 1], pos + 3 * strip[k + 2]);
			covered += a2, least = fmax(least, -sign * a2);
		}
		if (fabs(covered - band) > 1e-9 * fabs(band) + 1e-12 || least > 1e-12 * fabs(band))
			fail_msg("object %d, light %d: the strip covers %.12g of the band's %.12g (a triangle %.3g the other way)",
				 id, trial, covered, band, least);
		made = 1;
	}
done:
	free(inner), free(fan), free(strip), free(loop), free(work);
	return made;
}

/* The fans over one mesh's faces turned away from 200 lights round it (round: a sphere,
 * cylinder or cone; a box's mesh is only checked closed). Returns how many. */
static int check_fans(const struct lx_mesh *me, int id, bool round, uint64_t *seed, int *strips)
{
	int n = me->vertex_count, t = n / 3, fans = 0;
	float *pos = malloc((size_t)(n + 1) * 3 * sizeof(float));
	unsigned short *index = malloc((size_t)n * sizeof *index), *welded = malloc((size_t)n * sizeof *welded);
	unsigned short *fan = malloc((size_t)n * sizeof *fan), *loop = malloc((size_t)n * sizeof *loop);
	int *rep = malloc((size_t)n * sizeof *rep), *adj = malloc((size_t)n * sizeof *adj);
	int *next = malloc((size_t)(n + 1) * sizeof *next);
	bool *kept = malloc((size_t)t * sizeof *kept);
	assert_true(pos && index && welded && fan && loop && rep && adj && next && kept);
	int np = index_positions(me, pos, index);
	assert_true(lx_mesh_weld(pos, np, 1e-6, rep));
	for (int k = 0; k < n; k++)
		welded[k] = (unsigned short)rep[index[k]];
	assert_true(lx_mesh_adjacency(welded, t, adj)); /* every caster's, the box's too */
	vec3 c = v3_scale(v3_add(me->bmin, me->bmax), 0.5);
	for (int k = 0; k < 3; k++)
		pos[3 * np + k] = (float)((&c.x)[k]);
	for (int k = 0; k <= np; k++)
		next[k] = -1;
	for (int trial = 0; round && trial < 200; trial++) {
		vec3 dir = v3(0, 0, 1);
		assert_true(v3_normalize(v3(test_rand(seed) - 0.5, test_rand(seed) - 0.5, test_rand(seed) - 0.5), &dir));
		vec3 L = v3_add(c, v3_scale(dir, 0.8 + 5 * test_rand(seed))), axis = v3_scale(dir, -1), u, v;
		assert_true(v3_normalize(v3_cross(axis, fabs(axis.y) < 0.9 ? v3(0, 1, 0) : v3(1, 0, 0)), &u));
		v = v3_cross(axis, u);
		double faces = 0, covered = 0, least = 0;
		for (int k = 0; k < t; k++) {
			const float *a = pos + 3 * welded[3 * k], *b = pos + 3 * welded[3 * k + 1], *d = pos + 3 * welded[3 * k + 2];
			vec3 pa = v3(a[0], a[1], a[2]), pb = v3(b[0], b[1], b[2]), pd = v3(d[0], d[1], d[2]);
			vec3 nrm = v3_cross(v3_sub(pb, pa), v3_sub(pd, pa));
			kept[k] = v3_dot(nrm, v3_sub(L, pa)) < 0; /* turned away from the light */
			if (kept[k])
				faces += image_area2(L, axis, u, v, a, b, d);
		}
		double sign = faces < 0 ? -1 : 1; /* the faces turned away wind one way */
		int count = lx_silhouette_fan(welded, adj, t, kept, (unsigned short)np, next, fan, n);
		assert_true(count > 0 && count % 3 == 0 && count < 3 * t);
		for (int k = 0; k < count; k += 3) {
			double a2 = image_area2(L, axis, u, v, pos + 3 * fan[k], pos + 3 * fan[k + 1], pos + 3 * fan[k + 2]);
			covered += a2, least = fmax(least, -sign * a2); /* wound the other way: > 0 */
		}
		for (int k = 0; k <= np; k++)
			assert_int_equal(next[k], -1); /* left as it was */
		*strips += check_band_strip(pos, welded, adj, t, np, kept, fan, count, L, axis, u, v, sign, next, id, trial);
		if (fabs(covered - faces) > 1e-9 * fabs(faces) + 1e-12 || least > 1e-12 * fabs(faces))
			fail_msg("object %d, light %d: the fan covers %.12g of the faces' %.12g (a triangle %.3g the other way)",
				 id, trial, covered, faces, least);
		/* a convex caster's silhouette is convex: drawn as its polygon, the same image */
		int cut = lx_fan_as_polygon(fan, count, pos, (vec4){L.x, L.y, L.z, 1}, NULL, next, loop);
		assert_int_equal(cut, count - 6);
		covered = least = 0;
		for (int k = 0; k < cut; k += 3) {
			assert_true(fan[k] != np && fan[k + 1] != np && fan[k + 2] != np); /* the mesh's own corners */
			double a2 = image_area2(L, axis, u, v, pos + 3 * fan[k], pos + 3 * fan[k + 1], pos + 3 * fan[k + 2]);
			covered += a2, least = fmax(least, -sign * a2);
		}
		for (int k = 0; k <= np; k++)
			assert_int_equal(next[k], -1);
		if (fabs(covered - faces) > 1e-9 * fabs(faces) + 1e-12 || least > 1e-12 * fabs(faces))
			fail_msg("object %d, light %d: the polygon covers %.12g of the faces' %.12g (a triangle %.3g the other way)",
				 id, trial, covered, faces, least);
		fans++;
	}
	/* two kept triangles apart: two disks, no one loop */
	for (int k = 0; k < t; k++)
		kept[k] = false;
	kept[0] = true;
	for (int k = 1; k < t; k++) {
		bool touches = false;
		for (int e = 0; e < 3; e++)
			for (int j = 0; j < 3; j++)
				touches |= welded[3 * k + e] == welded[j];
		if (!touches && adj[3 * k] >= 0) {
			kept[k] = true;
			break;
		}
	}
	assert_int_equal(lx_silhouette_fan(welded, adj, t, kept, (unsigned short)np, next, fan, n), -1);
	assert_false(lx_mesh_adjacency(welded, t - 1, adj)); /* a hole: no closed mesh */
	free(pos), free(index), free(welded), free(fan), free(loop), free(rep), free(adj), free(next), free(kept);
	return fans;
}

/* The casters' shadow meshes, welded at their seams, are closed, and for lights all round
 * a round one the faces turned away from the light make one disk whose fan from the
 * caster's centre covers the same image, wound the same way, as does the fan's polygon
 * cut by diagonals, and the strip across the band between that disk's edge and the faces
 * turned well away covers the band's faces' image; a mesh with a hole and a kept set of
 * two disks are refused. */
static void silhouette_fans_cover_the_faces_turned_away(void **state)
{
	(void)state;
	struct lx_scene s;
	lx_scene_default(&s);
	struct lx_scene_meshes m;
	assert_true(lx_meshes_build(&s, &m));
	uint64_t seed = 7;
	int fans = 0, strips = 0;
	for (int id = s.plane_count; id < m.count; id++)
		fans += check_fans(&m.mesh[id], id, s.casters[id - s.plane_count].shape != LX_BOX, &seed, &strips);
	print_message("%d fans over the round casters' faces turned away from the light, each covering their image; "
		      "%d strips across the band nearer the edge-on, each covering its faces' image\n",
		      fans, strips);
	assert_int_equal(fans, 600);
	assert_true(strips >= 590); /* 597: three lights 4-6 m off meet a corner with neither */
	lx_meshes_free(&m);
}

/* A fan of 8 corners round (0, 0, 0) on the plane z = 0, seen from a light at (0, 0, 5),
 * with corner 2 pulled in to radius `r2` of the others' 1: its polygon for
 * lx_fan_as_polygon. */
static int octagon_fan(double r2, unsigned short *fan, float *pos, int *next, unsigned short *loop)
{
	for (int i = 0; i < 8; i++) {
		double a = -i * M_PI / 4, r = i == 2 ? r2 : 1; /* clockwise seen from the light: turned away */
		pos[3 * i] = (float)(r * cos(a)), pos[3 * i + 1] = (float)(r * sin(a)), pos[3 * i + 2] = 0;
		fan[3 * i] = 8, fan[3 * i + 1] = (unsigned short)i, fan[3 * i + 2] = (unsigned short)((i + 1) % 8);
	}
	pos[24] = pos[25] = pos[26] = 0; /* the apex */
	return lx_fan_as_polygon(fan, 24, pos, (vec4){0, 0, 5, 1}, NULL, next, loop);
}

/* A fan's polygon replaces it only where convex: a corner pulled in past its neighbours'
 * chord leaves the fan as it was; a corner on that chord (a straight angle) and one
 * outside it are cut into six triangles covering the octagon's area, none the other way. */
static void fan_polygons_only_where_convex(void **state)
{
	(void)state;
	unsigned short fan[24], loop[8];
	float pos[27];
	int next[9];
	for (int i = 0; i < 9; i++)
		next[i] = -1;
	double chord = cos(M_PI / 4); /* corner 2 on the line from corner 1 to corner 3 */
	const double radii[] = {0.5, chord, 1.0};
	for (int c = 0; c < 3; c++) {
		int n = octagon_fan(radii[c], fan, pos, next, loop);
		for (int i = 0; i < 9; i++)
			assert_int_equal(next[i], -1);
		if (c == 0) {
			assert_int_equal(n, 24); /* not convex: the fan unchanged */
			for (int i = 0; i < 8; i++)
				assert_true(fan[3 * i] == 8 && fan[3 * i + 1] == i && fan[3 * i + 2] == (i + 1) % 8);
			continue;
		}
		assert_int_equal(n, 18);
		double area = 0, fan_area = 0;
		for (int k = 0; k < n; k += 3) {
			const float *a = pos + 3 * fan[k], *b = pos + 3 * fan[k + 1], *d = pos + 3 * fan[k + 2];
			double a2 = (b[0] - a[0]) * (d[1] - a[1]) - (d[0] - a[0]) * (b[1] - a[1]);
			assert_true(fan[k] < 8 && a2 <= 1e-7); /* its own corners, clockwise like the fan */
			area += a2;
		}
		for (int i = 0; i < 8; i++) /* the octagon's, from the apex at 0 */
			fan_area += (double)pos[3 * ((i + 1) % 8)] * pos[3 * i + 1] - (double)pos[3 * i] * pos[3 * ((i + 1) % 8) + 1];
		assert_near(area, -fan_area, 1e-6);
	}
}

/* The length of the inner edges of a polygon's n corners (0 to n - 1 round it) cut into
 * triangles (k indices of tri; pos: x, y at z = 0), each inner edge counted once; the
 * triangles' summed area (twice, signed) in *area. */
static double inner_edges(const unsigned short *tri, int k, int n, const float *pos, double *area)
{
	double all = 0, outer = 0;
	*area = 0;
	for (int t = 0; t < k; t += 3)
		for (int e = 0; e < 3; e++) {
			const float *a = pos + 3 * tri[t + e], *b = pos + 3 * tri[t + (e + 1) % 3], *c = pos + 3 * tri[t + (e + 2) % 3];
			all += hypot(b[0] - a[0], b[1] - a[1]);
			int d = abs(tri[t + e] - tri[t + (e + 1) % 3]);
			if (d == 1 || d == n - 1) /* neighbours round the polygon: an outer edge, in one triangle */
				outer += hypot(b[0] - a[0], b[1] - a[1]);
			if (e == 0)
				*area += (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
		}
	return (all - outer) / 2;
}

/* Polygon pos[0, n) (n corners, then the apex) as its fan, cut by lx_fan_as_polygon with
 * `image` (NULL: the cheap way): each triangle of its corners and wound as the fan
 * (clockwise), n - 2 of them; returns their inner edges' length, their area in *area. */
static double cut_polygon(const float *pos, int n, const mat4 *image, double *area)
{
	unsigned short fan[24], loop[8];
	int next[9];
	for (int i = 0; i <= n; i++)
		next[i] = -1;
	for (int i = 0; i < n; i++)
		fan[3 * i] = (unsigned short)n, fan[3 * i + 1] = (unsigned short)i, fan[3 * i + 2] = (unsigned short)((i + 1) % n);
	int k = lx_fan_as_polygon(fan, 3 * n, pos, (vec4){0, 0, 5, 1}, image, next, loop);
	assert_int_equal(k, 3 * (n - 2));
	for (int i = 0; i < k; i++)
		assert_true(fan[i] < n);
	for (int i = 0; i < k; i += 3) {
		const float *a = pos + 3 * fan[i], *b = pos + 3 * fan[i + 1], *c = pos + 3 * fan[i + 2];
		assert_true((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]) < 0);
	}
	return inner_edges(fan, k, n, pos, area);
}

/* A box's silhouette as long as a table leg's shadow under a low light (a hexagon 10 m by
 * 10 cm) is cut at its shortest inner edges where the image is known: one along its
 * length and two across its ends, against two along it the cheap way; both cover the
 * hexagon once, wound as the fan. So too 300 random convex polygons of 4 to 8 corners
 * (on stretched ellipses): the same area, inner edges no longer than the cheap way's. */
static void short_polygons_cut_along_their_length_once(void **state)
{
	(void)state;
	/* clockwise seen from the light at (0, 0, 5), as a box's faces turned away are */
	const float corner[6][2] = {{0, 0.05f}, {10, 0.05f}, {10.05f, 0}, {10, -0.05f}, {0, -0.05f}, {-0.05f, 0}};
	float pos[27];
	for (int i = 0; i < 6; i++)
		pos[3 * i] = corner[i][0], pos[3 * i + 1] = corner[i][1], pos[3 * i + 2] = 0;
	pos[18] = 5, pos[19] = 0, pos[20] = 0; /* the apex */
	mat4 image = m4_identity(); /* x and y as they are, w = 1 */
	double area[2], cheap = cut_polygon(pos, 6, NULL, &area[0]), shortest = cut_polygon(pos, 6, &image, &area[1]);
	print_message("inner edges: %.3f m the cheap way, %.3f m the shortest\n", cheap, shortest);
	assert_near(area[0], area[1], 1e-6);
	assert_near(area[1], -2 * (10 * 0.1 + 0.05 * 0.1), 1e-5); /* twice the hexagon's, clockwise */
	assert_true(shortest < 10.3 && cheap > 20);
	uint64_t seed = 3;
	int shorter = 0;
	for (int trial = 0; trial < 300; trial++) {
		int n = 4 + trial % 5;
		double a = 0.2 + 5 * test_rand(&seed), b = 0.2 + 5 * test_rand(&seed), turn = 2 * M_PI * test_rand(&seed);
		double step[8], sum = 0;
		for (int i = 0; i < n; i++)
			sum += step[i] = 0.3 + test_rand(&seed);
		double t = 0;
		for (int i = 0; i < n; i++, t += step[i - 1] / sum) { /* clockwise round the ellipse */
			double x = a * cos(-2 * M_PI * t), y = b * sin(-2 * M_PI * t);
			pos[3 * i] = (float)(x * cos(turn) - y * sin(turn)), pos[3 * i + 1] = (float)(x * sin(turn) + y * cos(turn));
			pos[3 * i + 2] = 0;
		}
		pos[3 * n] = pos[3 * n + 1] = pos[3 * n + 2] = 0; /* the apex, inside */
		cheap = cut_polygon(pos, n, NULL, &area[0]), shortest = cut_polygon(pos, n, &image, &area[1]);
		assert_near(area[0], area[1], 1e-4 * fabs(area[0]));
		assert_true(shortest <= cheap * (1 + 1e-9));
		shorter += shortest < cheap * (1 - 1e-6);
	}
	print_message("300 random convex polygons: the shortest cut shorter than the cheap way in %d\n", shorter);
	assert_true(shorter > 50);
}

/* A flat-faced object (a plane, a box) carries each face's normal as its shading normal,
 * the very same floats (lx_mesh_is_flat): the renderer draws it as one draw, its faces
 * turned away from the light shaded by their Lambert term of 0. The boxes' and planes'
 * normals once came from two computations, a rounding apart, and so were drawn as round.
 * The round shapes' are smooth. */
static void flat_meshes_carry_their_face_normals(void **state)
{
	(void)state;
	struct lx_scene s;
	lx_scene_table(&s);
	struct lx_scene_meshes m;
	assert_true(lx_meshes_build(&s, &m));
	int boxes = 0;
	for (int id = 0; id < m.count; id++) {
		bool flat = lx_mesh_is_flat(&m.mesh[id]);
		bool box = id >= s.plane_count && s.casters[id - s.plane_count].shape == LX_BOX;
		boxes += box;
		if (flat != (id < s.plane_count || box))
			fail_msg("object %d: shading normals %s its face normals", id, flat ? "are" : "are not");
	}
	assert_int_equal(boxes, 5);
	lx_meshes_free(&m);
}

static int position_of(const int *order, int n, int id)
{
	for (int k = 0; k < n; k++)
		if (order[k] == id)
			return k;
	return -1;
}

/* The main pass's draw order: every object once; casters before the planes they stand
 * on; a table top before the slab and legs under it, which it hides from an eye above
 * it, and after them, with the casters above it, when the eye is below it. */
static void draw_order_draws_what_hides_first(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f;
	char err[256];
	int order[LX_MAX_PLANES + LX_MAX_CASTERS];
	lx_scene_default(&s);
	assert_true(lx_meshes_build(&s, &m));
	assert_true(lx_frame_setup(&f, &s, &m, 0, 256, 192, err, sizeof err));
	lx_frame_draw_order(&f, order);
	for (int k = 0; k < m.count; k++) /* the casters (2-5), then floor and wall */
		assert_int_equal(order[k], (k + s.plane_count) % m.count);
	lx_meshes_free(&m);

	lx_scene_table(&s); /* planes: 0 table top, 1 floor; casters: 2 slab, 3-6 legs, 7 sphere, 8 cone */
	assert_true(lx_meshes_build(&s, &m));
	assert_true(lx_frame_setup(&f, &s, &m, 0, 256, 192, err, sizeof err));
	lx_frame_draw_order(&f, order);
	bool seen[LX_MAX_PLANES + LX_MAX_CASTERS] = {0};
	for (int k = 0; k < m.count; k++) {
		assert_true(order[k] >= 0 && order[k] < m.count && !seen[order[k]]);
		seen[order[k]] = true;
	}
	int top = position_of(order, m.count, 0);
	for (int id = 2; id <= 6; id++)
		assert_true(position_of(order, m.count, id) > top);
	assert_true(position_of(order, m.count, 7) < top && position_of(order, m.count, 8) < top);
	assert_int_equal(order[m.count - 1], 1); /* the floor, under everything, last */

	s.camera.eye = v3(0, 0.4, 4.2); /* below the top: the casters above it are hidden now */
	assert_true(lx_frame_setup(&f, &s, &m, 0, 256, 192, err, sizeof err));
	lx_frame_draw_order(&f, order);
	top = position_of(order, m.count, 0);
	for (int id = 2; id <= 6; id++)
		assert_true(position_of(order, m.count, id) < top);
	assert_true(position_of(order, m.count, 7) > top && position_of(order, m.count, 8) > top);
	lx_meshes_free(&m);
}

/* lx_poly_rows_inside: every pixel it gives has its centre, and the points `inset` either
 * side of it along the row, inside the polygon in every row of the band; the pixels just
 * beyond either end do not, in some row. Random convex polygons and bands. */
static void rows_inside_a_polygon(void **state)
{
	(void)state;
	unsigned long long seq = 12345;
	int checked = 0;
	for (int t = 0; t < 300; t++) {
		vec2 pts[8];
		for (int k = 0; k < 8; k++) {
			seq = seq * 6364136223846793005ull + 1442695040888963407ull;
			pts[k] = (vec2){(double)(seq >> 40 & 255), (double)(seq >> 20 & 255)};
		}
		struct lx_poly p;
		if (!lx_poly_hull(pts, 8, &p) || p.n < 3)
			continue;
		int y0 = (int)(seq >> 50 & 127), y1 = y0 + 1 + (int)(seq >> 58 & 31), x0, x1;
		double inset = (t % 3) * 0.75;
		if (!lx_poly_rows_inside(&p, y0, y1, inset, &x0, &x1))
			continue;
		checked++;
		for (int y = y0; y < y1; y++)
			for (int x = x0; x < x1; x++)
				for (int d = -1; d <= 1; d++)
					assert_true(lx_poly_contains(&p, (vec2){x + 0.5 + d * inset, y + 0.5}, -1e-9));
		for (int end = 0; end < 2; end++) { /* x0 - 1, then x1: outside in some row */
			int x = end ? x1 : x0 - 1;
			bool out = false;
			for (int y = y0; y < y1 && !out; y++)
				for (int d = -1; d <= 1; d++)
					out |= !lx_poly_contains(&p, (vec2){x + 0.5 + d * inset, y + 0.5}, 1e-9);
			assert_true(out);
		}
	}
	assert_true(checked > 50);
}

/* A table top hides the floor under it from an eye above it, not the other way round;
 * the default scene's floor and wall, which meet, hide nothing of each other; a top that
 * reaches behind the eye (the near plane cuts it) is not taken to hide anything. */
static void a_plane_in_front_hides_the_one_behind(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f;
	struct lx_poly win;
	char err[256];
	lx_scene_table(&s);
	assert_true(lx_meshes_build(&s, &m));
	assert_true(lx_frame_setup(&f, &s, &m, 0, 256, 192, err, sizeof err));
	assert_true(lx_frame_plane_hides(&f, 0, 1, &win));
	assert_int_equal(win.n, 4);
	double x0, y0, x1, y1;
	lx_poly_bounds(&win, &x0, &y0, &x1, &y1);
	assert_true(x0 > 0 && x1 < 256 && y0 > 0 && y1 < 192 && x1 - x0 > 64); /* the top, well in view */
	assert_false(lx_frame_plane_hides(&f, 1, 0, &win));
	assert_false(lx_frame_plane_hides(&f, 0, 0, &win));
	s.camera.eye = v3(0, 0.9, 0.3), s.camera.at = v3(0, 0.5, -3); /* over the top: part of it behind the eye */
	assert_true(lx_frame_setup(&f, &s, &m, 0, 256, 192, err, sizeof err));
	assert_false(lx_frame_plane_hides(&f, 0, 1, &win));
	lx_meshes_free(&m);
	lx_scene_default(&s);
	assert_true(lx_meshes_build(&s, &m));
	assert_true(lx_frame_setup(&f, &s, &m, 0, 256, 192, err, sizeof err));
	assert_false(lx_frame_plane_hides(&f, 0, 1, &win));
	assert_false(lx_frame_plane_hides(&f, 1, 0, &win));
	lx_meshes_free(&m);
}

/* The boxes that hide a plane from the eye (lx_frame_box_hides): in the table scene seen
 * from above, a leg standing on the floor and the table top hide the floor, the slab
 * under the top does not hide the top, and nothing hides itself; a leg behind the eye
 * hides nothing, the one ahead does. The corners come back in the window. */
static void a_box_on_the_eyes_side_hides_the_plane(void **state)
{
	(void)state;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f;
	char err[256];
	vec2 w[8];
	lx_scene_table(&s);
	assert_true(lx_meshes_build(&s, &m));
	assert_true(lx_frame_setup(&f, &s, &m, 0, 256, 192, err, sizeof err));
	int top = 0, floor = 1, slab = s.plane_count, leg = s.plane_count + 1;
	assert_true(lx_frame_box_hides(&f, leg, floor, w)); /* touching the floor counts */
	vec4 c = m4_mul_point(&f.view.view_proj, v3_box_corner(f.bmin[leg], f.bmax[leg], 7));
	assert_true(fabs(w[7].x - (c.x / c.w * 0.5 + 0.5) * 256) < 1e-9 && fabs(w[7].y - (c.y / c.w * 0.5 + 0.5) * 192) < 1e-9);
	assert_true(lx_frame_box_hides(&f, top, floor, w));
	assert_true(lx_frame_box_hides(&f, slab, floor, w));
	assert_false(lx_frame_box_hides(&f, slab, top, w)); /* below the top, the eye above */
	assert_false(lx_frame_box_hides(&f, floor, floor, w));
	int back_leg = s.plane_count + 2; /* at x 1.1, z -0.7 */
	s.camera.eye = v3(1.1, 0.3, -0.5), s.camera.at = v3(1.1, 0.3, 3); /* just past it, facing away */
	assert_true(lx_frame_setup(&f, &s, &m, 0, 256, 192, err, sizeof err));
	assert_false(lx_frame_box_hides(&f, back_leg, floor, w));
	assert_true(lx_frame_box_hides(&f, s.plane_count + 4, floor, w)); /* the leg at x 1.1, z 0.7, ahead */
	lx_meshes_free(&m);
}

/* The largest of v . x over the n points. */
static double support(const vec3 *x, int n, vec3 v)
{
	double best = -INFINITY;
	for (int k = 0; k < n; k++)
		best = fmax(best, v3_dot(v, x[k]));
	return best;
}

/* A round caster's outline (lx_frame_object_outline) holds its exact shape, so its mesh:
 * in every direction v the outline reaches at least as far as any point of the shape
 * (two convex sets, one inside the other), checked over random directions and the
 * shape's points, for point lights near and far and directional ones. And it is tighter
 * than the box: a cylinder's and cone's points lie within it (but for the outline's
 * millionth of margin), and a sphere's image from
 * a point light (its angle around the ray to the centre) is at most 9% wider than the
 * sphere's own (the octagon's corners, 1 / cos(pi/8) out). */
static void round_outlines_hold_their_shapes(void **state)
{
	(void)state;
	uint64_t seed = 11;
	struct lx_scene s;
	struct lx_scene_meshes m;
	struct lx_frame f;
	char err[256];
	lx_scene_default(&s);
	assert_true(lx_meshes_build(&s, &m));
	long checked = 0;
	for (int trial = 0; trial < 60; trial++) {
		vec3 d = v3(test_rand(&seed) * 2 - 1, -0.1 - test_rand(&seed), test_rand(&seed) * 2 - 1);
		double far = trial % 3 == 0 ? 1.3 : trial % 3 == 1 ? 4 : 40; /* metres from the centre of the scene */
		s.light = trial % 4 == 3 ? (struct lx_light){.directional = true, .color = v3(1, 1, 1)}
					 : lx_light_white(v3_scale(d, -far));
		if (s.light.directional)
			assert_true(v3_normalize(d, &s.light.direction));
		assert_true(lx_frame_setup(&f, &s, &m, test_rand(&seed) * 5, 64, 48, err, sizeof err));
		for (int id = s.plane_count; id < f.object_count; id++) {
			const struct lx_caster *c = &s.casters[id - s.plane_count];
			vec3 x[LX_OUTLINE_POINTS], o = f.offset[id];
			int n = lx_frame_object_outline(&f, id, false, x);
			double r = c->size.x, h = c->size.y;
			vec3 centre = v3_add(o, v3(0, c->shape == LX_SPHERE ? r : h / 2, 0));
			bool inside_light = !f.light.directional && v3_len(v3_sub(f.light.position, centre)) <= r * 1.0001;
			assert_int_equal(n, c->shape == LX_BOX || (c->shape == LX_SPHERE && inside_light) ? 8 : c->shape == LX_CONE ? 9 : 16);
			for (int k = 0; k < 200; k++) {
				vec3 v = v3(0, 0, 0);
				if (!v3_normalize(v3(test_rand(&seed) - 0.5, test_rand(&seed) - 0.5, test_rand(&seed) - 0.5), &v))
					continue;
				double reach; /* of the exact shape along v */
				double hv = hypot(v.x, v.z);
				if (c->shape == LX_SPHERE)
					reach = v3_dot(v, centre) + r;
				else if (c->shape == LX_CYLINDER)
					reach = v3_dot(v, o) + r * hv + fmax(0, v.y * h);
				else if (c->shape == LX_CONE)
					reach = v3_dot(v, o) + fmax(r * hv, v.y * h); /* the base's rim or the apex */
				else
					reach = support((vec3[8]){v3_box_corner(f.bmin[id], f.bmax[id], 0), v3_box_corner(f.bmin[id], f.bmax[id], 1),
								  v3_box_corner(f.bmin[id], f.bmax[id], 2), v3_box_corner(f.bmin[id], f.bmax[id], 3),
								  v3_box_corner(f.bmin[id], f.bmax[id], 4), v3_box_corner(f.bmin[id], f.bmax[id], 5),
								  v3_box_corner(f.bmin[id], f.bmax[id], 6), v3_box_corner(f.bmin[id], f.bmax[id], 7)},
							8, v);
				if (!(support(x, n, v) >= reach - 1e-12 * (1 + fabs(reach))))
					fail_msg("trial %d, object %d: the outline reaches %.17g along (%g, %g, %g), the shape %.17g", trial,
						 id, support(x, n, v), v.x, v.y, v.z, reach);
				checked++;
			}
			if (c->shape == LX_CYLINDER || c->shape == LX_CONE)
				for (int k = 0; k < n; k++)
					assert_true(x[k].x >= f.bmin[id].x - 2e-6 * r && x[k].x <= f.bmax[id].x + 2e-6 * r &&
						    x[k].z >= f.bmin[id].z - 2e-6 * r && x[k].z <= f.bmax[id].z + 2e-6 * r);
			if (c->shape == LX_SPHERE && !inside_light) { /* image_only: the near half, on the same rays */
				vec3 y[LX_OUTLINE_POINTS];
				assert_int_equal(lx_frame_object_outline(&f, id, true, y), 8);
				for (int k = 0; k < 8; k++) {
					vec3 a = f.light.directional ? f.light.direction : v3_sub(y[k], f.light.position);
					vec3 b = f.light.directional ? v3_sub(x[k + 8], y[k]) : v3_sub(x[k + 8], f.light.position);
					vec3 c3 = v3_cross(a, b);
					assert_true(v3_len(c3) <= 1e-12 * v3_len(a) * v3_len(b));
				}
			}
			if (c->shape == LX_SPHERE && !f.light.directional && !inside_light) {
				vec3 to = v3_sub(centre, f.light.position), u = v3(0, 0, 0);
				assert_true(v3_normalize(to, &u));
				double own = asin(r / v3_len(to)), widest = 0;
				for (int k = 0; k < n; k++) {
					vec3 w = v3(0, 0, 0);
					assert_true(v3_normalize(v3_sub(x[k], f.light.position), &w));
					widest = fmax(widest, acos(fmin(1, v3_dot(w, u))));
				}
				assert_true(widest >= own && tan(widest) <= tan(own) * 1.0825 + 1e-9);
			}
		}
	}
	print_message("%ld directions checked: every outline holds its shape\n", checked);
	lx_meshes_free(&m);
}

/* A projective light's matrix, image look-up and fall-off [Segal], against values worked
 * out by hand: a spotlight 5 m above the origin looking straight down, fov 60 degrees. */
static void projective_light_geometry(void **state)
{
	(void)state;
	struct lx_light l = lx_light_white(v3(0, 5, 0));
	l.projective = LX_LIGHT_SPOT, l.at = v3(0, 0, 0), l.up = v3(0, 0, -1), l.fov_deg = 60;
	l.range_near = 2, l.range_far = 6;
	mat4 m;
	assert_true(lx_light_projection(&l, &m));
	vec4 q = m4_mul_point(&m, v3(0, 0, 0)); /* on the axis, 5 m away: the image's centre */
	assert_true(fabs(q.x / q.w - 0.5) < 1e-12 && fabs(q.y / q.w - 0.5) < 1e-12 && fabs(q.w - 5) < 1e-12);
	double edge = 5 * tan(M_PI / 6); /* the frustum's side on the floor: s = 1 there */
	q = m4_mul_point(&m, v3(edge, 0, 0));
	assert_true(fabs(q.x / q.w - 1) < 1e-12);
	q = m4_mul_point(&m, v3(0, 0, -edge)); /* up is -z: t = 1 */
	assert_true(fabs(q.y / q.w - 1) < 1e-12);
	assert_true(lx_light_reaches(&l, &m, v3(0.99 * edge, 0, 0)));
	assert_false(lx_light_reaches(&l, &m, v3(1.01 * edge, 0, 0)));
	assert_false(lx_light_reaches(&l, &m, v3(0, 7, 0)));  /* behind the light */
	assert_false(lx_light_reaches(&l, &m, v3(0, -1.5, 0))); /* past range_far (6.5 m away) */
	/* the frustum's corners: the image's corners, the far face just past range_far */
	vec3 fc[8];
	assert_true(lx_light_frustum(&l, v3(-5, 0, -5), v3(5, 5, 5), fc));
	static const double st[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
	for (int k = 0; k < 8; k++) {
		vec4 c = m4_mul_point(&m, fc[k]);
		assert_true(fabs(c.x / c.w - st[k % 4][0]) < 1e-9 && fabs(c.y / c.w - st[k % 4][1]) < 1e-9);
		assert_true(k < 4 ? c.w > 0 && c.w < 1e-6 : fabs(c.w - 6 * 1.001) < 1e-9);
	}
	struct lx_image beam;
	char err[256];
	assert_true(lx_light_image_load(&l, &beam, err, sizeof err));
	assert_int_equal(beam.width, LX_ROUND_BEAM_SIZE);
	/* the round beam: full near the axis, none past the cone's half-angle, round */
	vec3 c = lx_image_bilinear(&beam, 0.5, 0.5), corner = lx_image_bilinear(&beam, 0.999, 0.999);
	assert_true(c.x == 1 && corner.x == 0);
	vec3 a = lx_image_bilinear(&beam, 0.8, 0.5), b = lx_image_bilinear(&beam, 0.5, 0.8);
	assert_true(fabs(a.x - b.x) < 1e-12 && a.x > 0 && a.x < 1);
	/* the fall-off with depth: full up to range_near, half way at 4 m, none at 6 m */
	assert_true(fabs(lx_projective_light_at(&l, &m, &beam, v3(0, 3.5, 0)).x - 1) < 1e-12);
	assert_true(fabs(lx_projective_light_at(&l, &m, &beam, v3(0, 1, 0)).x - 0.5) < 1e-12);
	assert_true(lx_projective_light_at(&l, &m, &beam, v3(0, 7, 0)).x == 0);
	lx_image_free(&beam);
	/* bilinear as GL's LINEAR filter: texel centres exact, half way between them the mean,
	 * clamped to the edge outside */
	uint8_t px[2 * 4] = {0, 100, 200, 255, 255, 50, 0, 255};
	struct lx_image im = {2, 1, px};
	assert_true(fabs(lx_image_bilinear(&im, 0.25, 0.5).y - 100 / 255.0) < 1e-12);
	assert_true(fabs(lx_image_bilinear(&im, 0.5, 0.5).x - 127.5 / 255.0) < 1e-12);
	assert_true(fabs(lx_image_bilinear(&im, 1.5, 0.5).z - 0) < 1e-12);
	assert_true(fabs(lx_image_bilinear(&im, -3, 7).z - 200 / 255.0) < 1e-12);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(default_scene_is_the_specified_one),
		cmocka_unit_test(scene_files_match_the_built_in_scenes),
		cmocka_unit_test(malformed_files_name_the_line_and_what_was_expected),
		cmocka_unit_test(missing_and_binary_files),
		cmocka_unit_test(projective_light_geometry),
		cmocka_unit_test(any_scale_parses),
		cmocka_unit_test(directional_light_and_defaults),
		cmocka_unit_test(lights_are_white_unless_coloured),
		cmocka_unit_test(several_lights_keep_their_order_and_scale),
		cmocka_unit_test(caster_meshes_are_closed_and_outward),
		cmocka_unit_test(silhouette_fans_cover_the_faces_turned_away),
		cmocka_unit_test(fan_polygons_only_where_convex),
		cmocka_unit_test(short_polygons_cut_along_their_length_once),
		cmocka_unit_test(flat_meshes_carry_their_face_normals),
		cmocka_unit_test(draw_order_draws_what_hides_first),
		cmocka_unit_test(rows_inside_a_polygon),
		cmocka_unit_test(a_plane_in_front_hides_the_one_behind),
		cmocka_unit_test(round_outlines_hold_their_shapes),
		cmocka_unit_test(a_box_on_the_eyes_side_hides_the_plane),
	};
	return cmocka_run_group_tests_name("scene", tests, NULL, NULL);
}
