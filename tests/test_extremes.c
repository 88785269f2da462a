/* The extremes: random extreme configurations with every method (a light on or near a
 * plane, grazing and upward directional light, far lights, a light inside a caster, the
 * eye on a plane, one caster far from the rest, scenes from 1e-4 to 1e4 m), and one
 * scene at three scales. Each frame either warns or matches the exact reference within
 * 1%, and nothing the reports or the JSON carry is NaN. */
#include "method_run.h"
#include "platform.h"
#include "reference.h"
#include "renderer.h"
#include "test_util.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 320, H = 240 };
/* every method the registry (method_registry.c) holds */
enum { NM_MAX = 16 };
static const char *methods[NM_MAX];
static int NM;

/* One OSMesa context for both tests, and what it can do. */
static struct lx_platform *plat;
static struct lx_gl_caps caps;

static int group_setup(void **state)
{
	(void)state;
	NM = lx_shadow_method_count();
	if (NM < 2 || NM > NM_MAX)
		return -1;
	for (int i = 0; i < NM; i++)
		methods[i] = lx_shadow_method_at(i)->name;
	char err[512];
	if (!(plat = lx_platform_create("osmesa", err, sizeof err))) {
		print_error("%s\n", err);
		return -1;
	}
	lx_gl_caps_probe(&caps);
	return 0;
}

static int group_teardown(void **state)
{
	(void)state;
	return 0;
}

struct pixels {
	uint8_t *rgba, *sh, *ref_sh;
	int16_t *obj, *ref_obj;
};

static struct pixels pixels_new(void)
{
	struct pixels p = {malloc((size_t)W * H * 4), malloc((size_t)W * H), malloc((size_t)W * H),
			   malloc((size_t)W * H * sizeof(int16_t)), malloc((size_t)W * H * sizeof(int16_t))};
	assert_true(p.rgba && p.sh && p.ref_sh && p.obj && p.ref_obj);
	return p;
}

static void pixels_free(struct pixels *p)
{
	free(p->rgba), free(p->sh), free(p->ref_sh), free(p->obj), free(p->ref_obj);
}

static double uniform01(uint64_t *s) { return test_rand(s); }

/* A point on plane i, s and t in [0, 1]. */
static vec3 on_plane(const struct lx_plane *p, double s, double t)
{
	return v3_add(p->corner, v3_add(v3_scale(p->edge1, s), v3_scale(p->edge2, t)));
}

/* One random extreme light and eye for the scaled scene sc (k: its scale); a short name of the kind. */
static const char *extreme(struct lx_scene *sc, double k, uint64_t *rs)
{
	const struct lx_plane *pl = &sc->planes[(int)(uniform01(rs) * sc->plane_count) % sc->plane_count];
	vec3 n = lx_plane_normal(pl);
	int kind = (int)(uniform01(rs) * 9) % 9;
	double u = uniform01(rs), v = uniform01(rs);
	switch (kind) {
	case 0:
		sc->light = lx_light_white(on_plane(pl, u, v));
		return "light on a plane";
	case 1:
		sc->light = lx_light_white(v3_add(on_plane(pl, u, v), v3_scale(n, k * pow(10, -3 - 9 * uniform01(rs)))));
		return "light near a plane";
	case 2: {
		vec3 d = v3(cos(6.283 * u), -pow(10, -1 - 7 * v), sin(6.283 * u));
		v3_normalize(d, &d);
		sc->light = lx_light_white(v3(0, 0, 0)), sc->light.directional = true, sc->light.direction = d;
		return "grazing directional light";
	}
	case 3: {
		vec3 d = v3(u - 0.5, 0.2 + v, uniform01(rs) - 0.5);
		v3_normalize(d, &d);
		sc->light = lx_light_white(v3(0, 0, 0)), sc->light.directional = true, sc->light.direction = d;
		return "directional light from below";
	}
	case 4: {
		vec3 d = v3(u - 0.5, v, uniform01(rs) - 0.5);
		v3_normalize(d, &d);
		sc->light = lx_light_white(v3_scale(d, k * pow(10, 3 + 11 * uniform01(rs))));
		return "far point light";
	}
	case 5: {
		const struct lx_caster *c = &sc->casters[(int)(u * sc->caster_count) % sc->caster_count];
		sc->light = lx_light_white(v3(c->x, c->low + 0.5 * c->size.y, c->z));
		return "light inside a caster";
	}
	case 6:
		sc->camera.eye = on_plane(pl, 0.1 + 0.8 * u, 0.1 + 0.8 * v);
		sc->camera.at = v3_add(sc->camera.eye, v3_add(v3_scale(pl->edge1, 0.3), v3_scale(n, 0.05 * k)));
		return "eye on a plane";
	case 7:
		sc->camera.eye = v3_add(on_plane(pl, 0.05 + 0.9 * u, 0.5), v3_scale(n, k * 1e-3));
		sc->camera.at = v3_add(sc->camera.eye, pl->edge2);
		return "eye a hair off a plane, looking along it";
	default:
		sc->light = lx_light_white(v3(k * (8 * u - 4), k * (6 * v - 1), k * (8 * uniform01(rs) - 4)));
		return "random point light";
	}
}

/* A third of the point lights become spotlights of the same place [Segal], aimed at a random
 * point of the scene with a random fov (2 to 148 degrees) and now and then a range: the
 * maps then cover only what the light's frustum reaches, and the pixels it does not reach
 * are not compared. Their decisions are what the frame's geometry gives; the renderer
 * needs no beam image for them. */
static bool aim_spotlight(struct lx_light *light, double k, uint64_t *rs)
{
	struct lx_light l = *light;
	l.projective = LX_LIGHT_SPOT, l.aspect = 1, l.fov_deg = 2 + 146 * uniform01(rs);
	l.at = v3(k * (8 * uniform01(rs) - 4), k * 2 * uniform01(rs), k * (8 * uniform01(rs) - 4));
	l.up = lx_light_default_up(l.position, l.at);
	if (uniform01(rs) < 0.3)
		l.range_near = k * 2 * uniform01(rs), l.range_far = l.range_near + k * (0.5 + 8 * uniform01(rs));
	mat4 m;
	if (!m4_look_at(l.position, l.at, l.up, &m))
		return false; /* aimed at itself: stays as it was */
	*light = l;
	return true;
}

static const char *as_spotlight(struct lx_scene *sc, double k, const char *kind, uint64_t *rs)
{
	static char name[96];
	if (!aim_spotlight(&sc->light, k, rs))
		return kind;
	snprintf(name, sizeof name, "%s, as a spotlight (fov %.0f)", kind, sc->light.fov_deg);
	return name;
}

/* Every method set up for the scene, one run each. */
static void runs_init(struct lx_method_run *run, const struct lx_scene *s, const struct lx_scene_meshes *meshes)
{
	char err[512];
	for (int m = 0; m < NM; m++) {
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		if (lx_method_run_init(&run[m], methods[m], s, meshes, &caps, &o, W, H, LX_DEPTH_AUTO, LX_DEFAULT_BIAS_CODES,
				       false, err, sizeof err))
			fail_msg("%s: %s", methods[m], err);
	}
}

static bool finite_report(const struct lx_shadow_result *res, const struct lx_mismatch *mm,
			  const struct lx_plane_report *planes, int nplanes)
{
	for (int i = 0; i < res->map_count; i++)
		if (res->maps[i].rendered && !m4_finite(&res->maps[i].light_clip))
			return false;
	if (!isfinite(mm->mismatch_pct + mm->false_shadow_pct + mm->missing_shadow_pct))
		return false;
	for (int p = 0; p < nplanes; p++) {
		const struct lx_plane_sampling *s = &planes[p].s;
		if (planes[p].present && !isfinite(s->lpp_median + s->m_median + s->m_max + s->aniso_max + s->lixels_used))
			return false;
	}
	return true;
}

static void random_extremes_warn_or_match(void **state)
{
	(void)state;
	char err[512];
	struct pixels px = pixels_new();
	uint64_t rs = 20261130;
	long frames = 0, warned = 0, refused = 0, configs = 0, spots = 0;
	double worst_quiet = 0;
	static const double scales[] = {1e-4, 1e-2, 1, 1e2, 1e4};
	/* 300 configurations; 60 under the sanitizers (make asan sets LIXEL_TEST_QUICK),
	 * which look for memory errors, not for more configurations */
	int per_group = getenv("LIXEL_TEST_QUICK") ? 3 : 15;
	for (int g = 0; g < 20; g++) {
		struct lx_scene base;
		assert_true(lx_scene_builtin(g % 2 ? "table" : "default", &base));
		double k = scales[(g / 2) % 5];
		if (g >= 10 && base.caster_count < LX_MAX_CASTERS) /* one caster far from the rest */
			base.casters[base.caster_count++] = (struct lx_caster){.shape = LX_BOX, .size = v3(1, 1, 1), .x = 1e5,
									       .period = 2, .color = v3(0.5, 0.5, 0.5)};
		lx_scene_scale(&base, k);
		struct lx_scene_meshes meshes = {0};
		assert_true(lx_meshes_build(&base, &meshes));
		struct lx_method_run run[NM_MAX];
		runs_init(run, &base, &meshes);
		for (int c = 0; c < per_group; c++, configs++) {
			struct lx_scene sc = base;
			const char *kind = extreme(&sc, k, &rs);
			double t = 10 * uniform01(&rs);
			if (!sc.light.directional && uniform01(&rs) < 1.0 / 3)
				kind = as_spotlight(&sc, k, kind, &rs);
			struct lx_frame frame;
			mat4 look;
			if (!m4_look_at(sc.camera.eye, sc.camera.at, sc.camera.up, &look) ||
			    !lx_frame_setup(&frame, &sc, &meshes, t, W, H, err, sizeof err)) {
				refused++; /* the command line refuses it with exit status 2 */
				continue;
			}
			spots += sc.light.projective != LX_LIGHT_PLAIN;
			assert_true(lx_reference_image(&frame, px.ref_obj, px.ref_sh, 2));
			struct lx_plane_points pts;
			assert_true(lx_plane_points_make(&frame, px.ref_obj, &pts));
			for (int m = 0; m < NM; m++) {
				lx_method_run_shadows(&run[m], &frame); /* the decision needs no shaded frame */
				lx_method_run_decision(&run[m], 0, px.rgba, px.obj, px.sh);
				struct lx_mismatch mm;
				struct lx_plane_report planes[LX_MAX_PLANES];
				lx_measure(&frame, &run[m].lights[0].atlas, &run[m].lights[0].result, px.ref_obj, px.ref_sh, px.obj, px.sh, NULL, &pts, &mm, planes);
				lx_sampling_warnings(planes, sc.plane_count, lx_atlas_lixels(&run[m].lights[0].atlas), &run[m].lights[0].result);
				frames++;
				if (!finite_report(&run[m].lights[0].result, &mm, planes, sc.plane_count))
					fail_msg("scale %g, %s, %s: a NaN or infinity in the matrices or the report", k, kind, methods[m]);
				bool quiet = run[m].lights[0].result.warning_count == 0 && strcmp(methods[m], "none");
				if (!quiet) {
					warned++;
					continue;
				}
				worst_quiet = fmax(worst_quiet, mm.mismatch_pct);
				if (!(mm.mismatch_pct < 1.0) && sc.light.projective)
					print_message("the spotlight looks at %.9g %.9g %.9g, range %g %g\n", sc.light.at.x, sc.light.at.y,
						      sc.light.at.z, sc.light.range_near, sc.light.range_far);
				if (!(mm.mismatch_pct < 1.0))
					fail_msg("scale %g, %s (light %.9g %.9g %.9g%s, eye %g %g %g, time %.3f), %s: mismatch %.3f%% with no warning", k,
						 kind, sc.light.directional ? sc.light.direction.x : sc.light.position.x,
						 sc.light.directional ? sc.light.direction.y : sc.light.position.y,
						 sc.light.directional ? sc.light.direction.z : sc.light.position.z,
						 sc.light.directional ? " directional" : "", sc.camera.eye.x, sc.camera.eye.y,
						 sc.camera.eye.z, t, methods[m], mm.mismatch_pct);
			}
			lx_plane_points_free(&pts);
		}
		for (int m = 0; m < NM; m++)
			lx_method_run_free(&run[m]);
		lx_meshes_free(&meshes);
	}
	print_message("%ld configurations (%ld refused as bad input, %ld spotlights), %ld frames: %ld with a warning, the "
		      "worst mismatch without one %.3f%%\n", configs, refused, spots, frames, warned, worst_quiet);
	assert_true(frames > 50 * per_group); /* most configurations rendered */
	pixels_free(&px);
}

/* Two named extremes on the default scene at time 0, every method: the light on the
 * floor (the pixels it grazes left out as edge-on, the rest within 1%, warning or not),
 * and one caster 100 km from the rest (within 0.5%: the far caster must not spread the
 * maps over the whole scene). */
static void named_extremes_match(void **state)
{
	(void)state;
	char err[512];
	struct pixels px = pixels_new();
	for (int e = 0; e < 2; e++) {
		struct lx_scene sc;
		assert_true(lx_scene_builtin("default", &sc));
		if (e == 0)
			sc.light = lx_light_white(v3(0, 0, 0));
		else
			sc.casters[sc.caster_count++] = (struct lx_caster){.shape = LX_BOX, .size = v3(1, 1, 1), .x = 1e5,
									   .period = 2, .color = v3(0.5, 0.5, 0.5)};
		const char *what = e == 0 ? "the light on the floor" : "one caster 100 km away";
		double limit = e == 0 ? 1.0 : 0.5;
		struct lx_scene_meshes meshes = {0};
		assert_true(lx_meshes_build(&sc, &meshes));
		struct lx_method_run run[NM_MAX];
		runs_init(run, &sc, &meshes);
		struct lx_frame frame;
		if (!lx_frame_setup(&frame, &sc, &meshes, 0, W, H, err, sizeof err))
			fail_msg("%s: %s", what, err);
		assert_true(lx_reference_image(&frame, px.ref_obj, px.ref_sh, 2));
		struct lx_plane_points pts;
		assert_true(lx_plane_points_make(&frame, px.ref_obj, &pts));
		for (int m = 0; m < NM; m++) {
			if (!strcmp(methods[m], "none"))
				continue;
			lx_method_run_shadows(&run[m], &frame);
			lx_method_run_decision(&run[m], 0, px.rgba, px.obj, px.sh);
			struct lx_mismatch mm;
			struct lx_plane_report planes[LX_MAX_PLANES];
			lx_measure(&frame, &run[m].lights[0].atlas, &run[m].lights[0].result, px.ref_obj, px.ref_sh, px.obj,
				   px.sh, NULL, &pts, &mm, planes);
			print_message("%-24s %-8s mismatch %.4f%%, edge-on pixels %ld\n", what, methods[m], mm.mismatch_pct,
				      mm.edge_on);
			if (!(mm.mismatch_pct < limit))
				fail_msg("%s, %s: mismatch %.3f%%, expected under %g%%", what, methods[m], mm.mismatch_pct, limit);
			if (e == 0 && mm.edge_on <= 1000)
				fail_msg("%s, %s: %ld pixels edge-on, expected the floor's (over 1000)", what, methods[m], mm.edge_on);
		}
		lx_plane_points_free(&pts);
		for (int m = 0; m < NM; m++)
			lx_method_run_free(&run[m]);
		lx_meshes_free(&meshes);
	}
	pixels_free(&px);
}

/* One light of a two-light frame against its reference: a NaN-free report, and without a
 * warning a mismatch under 1% (but for the method none, which shadows nothing). Returns
 * whether it warned. */
static bool light_warns_or_matches(struct lx_method_run *run, int l, const struct pixels *px, const uint8_t *ref_sh,
				   const struct lx_plane_points *pts, const char *what)
{
	ref_sh += (size_t)l * W * H; /* every light's, light after light */
	const struct lx_light_maps *lm = &run->lights[l];
	lx_method_run_decision(run, l, px->rgba, px->obj, px->sh);
	struct lx_mismatch mm;
	struct lx_plane_report planes[LX_MAX_PLANES];
	struct lx_shadow_result res = lm->result;
	lx_measure(&lm->frame, &lm->atlas, &res, px->ref_obj, ref_sh, px->obj, px->sh, NULL, pts, &mm, planes);
	lx_sampling_warnings(planes, lm->frame.scene->plane_count, lx_atlas_lixels(&lm->atlas), &res);
	if (!finite_report(&res, &mm, planes, lm->frame.scene->plane_count))
		fail_msg("%s, light %d: a NaN or infinity in the matrices or the report", what, l + 1);
	if (res.warning_count || !strcmp(run->method->name, "none"))
		return true;
	if (!(mm.mismatch_pct < 1.0))
		fail_msg("%s, light %d: mismatch %.3f%% with no warning", what, l + 1, mm.mismatch_pct);
	return false;
}

/* Two lights at the extremes: the first an extreme light as above, the second a spotlight
 * [Segal] of an extreme kind with a random aim (so that its additive pass is cut to its
 * lit box even when that box reaches behind the eye or misses the view). Each light warns
 * or matches its own reference; when the first is a plain light the summed frame is shaded
 * too, and off the reference's sum by under two levels on average (colour_error) where
 * neither light warns. */
static void two_extreme_lights_warn_or_match(void **state)
{
	(void)state;
	char err[512];
	struct pixels px = pixels_new();
	uint8_t *ref_sh = malloc((size_t)W * H * 2), *ref_rgba = malloc((size_t)W * H * 4);
	assert_true(ref_sh && ref_rgba);
	struct lx_scene two;
	assert_true(lx_scene_builtin("twolights", &two));
	uint64_t rs = 20261201;
	long frames = 0, warned = 0, shaded = 0;
	double worst_colour = 0;
	static const double scales[] = {1e-4, 1e-2, 1, 1e2, 1e4};
	for (int g = 0; g < 6; g++) { /* every scale, both scenes; each config sets up its runs */
		struct lx_scene base;
		assert_true(lx_scene_builtin(g % 2 ? "table" : "default", &base));
		double k = scales[g % 5];
		base.lights[1] = two.lights[1], base.light_count = 2; /* a white light and the built-in spotlight */
		lx_scene_scale(&base, k);
		struct lx_scene_meshes meshes = {0};
		assert_true(lx_meshes_build(&base, &meshes));
		/* set up once per group: the configurations move the lights, not their kinds (the
		 * first stays plain, the second a spotlight, whose round beam is made here) */
		struct lx_method_run run[NM_MAX];
		runs_init(run, &base, &meshes);
		for (int c = 0; c < 2; c++) {
			struct lx_scene sc = base, second = base;
			const char *kind = extreme(&sc, k, &rs);
			(void)extreme(&second, k, &rs); /* the second light where an extreme one would be */
			struct lx_light spot = second.light.directional ? base.lights[1] : second.light;
			if (aim_spotlight(&spot, k, &rs))
				sc.lights[1] = spot;
			struct lx_frame frame;
			mat4 look;
			if (!m4_look_at(sc.camera.eye, sc.camera.at, sc.camera.up, &look) ||
			    !lx_frame_setup(&frame, &sc, &meshes, 10 * uniform01(&rs), W, H, err, sizeof err))
				continue; /* the command line refuses it with exit status 2 */
			char what[400];
			snprintf(what, sizeof what, "scale %g, %s (eye %.9g %.9g %.9g at %.9g %.9g %.9g), a spotlight at %.9g %.9g "
				 "%.9g aimed at %.9g %.9g %.9g", k, kind, sc.camera.eye.x, sc.camera.eye.y, sc.camera.eye.z,
				 sc.camera.at.x, sc.camera.at.y, sc.camera.at.z, sc.lights[1].position.x, sc.lights[1].position.y,
				 sc.lights[1].position.z, sc.lights[1].at.x, sc.lights[1].at.y, sc.lights[1].at.z);
			struct lx_plane_points pts;
			for (int m = 0; m < NM; m++) {
				lx_method_run_draw(&run[m], &frame, NULL);
				if (m == 0) { /* the lights' frames and images are every run's: one reference for all */
					assert_true(lx_method_run_reference(&run[m], px.ref_obj, ref_sh, ref_rgba, 2));
					assert_true(lx_plane_points_make(&frame, px.ref_obj, &pts));
				}
				lx_renderer_read(run[m].renderer, px.rgba);
				double colour = lx_colour_error(px.rgba, ref_rgba, (long)W * H);
				assert_true(isfinite(colour));
				if (!run[m].lights[0].result.warning_count && !run[m].lights[1].result.warning_count &&
				    strcmp(methods[m], "none")) {
					shaded++;
					worst_colour = fmax(worst_colour, colour);
					if (!(colour < 2.0))
						fail_msg("%s, %s: colour_error %.3f levels with no warning", what, methods[m], colour);
				}
				char who[440];
				snprintf(who, sizeof who, "%s, %s", what, methods[m]);
				for (int l = 0; l < 2; l++, frames++)
					warned += light_warns_or_matches(&run[m], l, &px, ref_sh, &pts, who);
			}
			lx_plane_points_free(&pts);
		}
		for (int m = 0; m < NM; m++)
			lx_method_run_free(&run[m]);
		lx_meshes_free(&meshes);
	}
	print_message("two lights: %ld light-frames, %ld with a warning; %ld shaded frames compared, worst colour_error "
		      "%.3f levels\n", frames, warned, shaded, worst_colour);
	assert_true(frames > 100 && shaded > 10);
	free(ref_sh), free(ref_rgba);
	pixels_free(&px);
}

/* One scene at 1e-4, 1 and 1e4 metres: the same decisions, pixel for pixel but for a
 * few where rounding falls the other way (at most 0.1% of the image). */
static void scale_changes_nothing(void **state)
{
	(void)state;
	enum { w = W, h = H };
	char err[512];
	struct pixels px = pixels_new(); /* W x H, as w x h */
	uint8_t *rgba = px.rgba, *sh[2] = {px.sh, px.ref_sh};
	int16_t *obj[2] = {px.obj, px.ref_obj};
	static const double scales[] = {1, 1e-4, 1e4};
	for (int m = 0; m < NM; m++) {
		long shadowed = 0;
		for (int i = 0; i < 3; i++) {
			struct lx_scene sc;
			assert_true(lx_scene_builtin("default", &sc));
			lx_scene_scale(&sc, scales[i]);
			struct lx_scene_meshes meshes = {0};
			assert_true(lx_meshes_build(&sc, &meshes));
			struct lx_method_run run;
			struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
			if (lx_method_run_init(&run, methods[m], &sc, &meshes, &caps, &o, w, h, LX_DEPTH_AUTO,
					       LX_DEFAULT_BIAS_CODES, false, err, sizeof err))
				fail_msg("%s: %s", methods[m], err);
			struct lx_frame frame;
			assert_true(lx_frame_setup(&frame, &sc, &meshes, 0.4, w, h, err, sizeof err));
			lx_method_run_shadows(&run, &frame);
			lx_method_run_decision(&run, 0, rgba, obj[i > 0], sh[i > 0]);
			for (int k = 0; k < run.lights[0].result.warning_count; k++)
				print_message("%s at scale %g: warning: %s\n", methods[m], scales[i], run.lights[0].result.warnings[k]);
			lx_method_run_free(&run);
			lx_meshes_free(&meshes);
			if (i == 0) {
				for (long p = 0; p < (long)w * h; p++)
					shadowed += sh[0][p];
				continue;
			}
			long differ = 0;
			for (long p = 0; p < (long)w * h; p++)
				differ += obj[0][p] != obj[1][p] || sh[0][p] != sh[1][p];
			print_message("%-7s scale %-6g: %ld of %d pixels differ from scale 1 (%ld shadowed there)\n", methods[m],
				      scales[i], differ, w * h, shadowed);
			if (differ > w * h / 1000)
				fail_msg("%s: %ld pixels differ between scale 1 and %g", methods[m], differ, scales[i]);
		}
		assert_true(!strcmp(methods[m], "none") || shadowed > 0); /* there were shadows to compare */
	}
	pixels_free(&px);
}

/* The budget-use warning: few of the maps' lixels on the planes' reading pixels warns only
 * where those pixels read less than a lixel each (a small shadow read densely is fine). */
static void budget_warning_only_where_coarse(void **state)
{
	(void)state;
	struct lx_plane_report planes[2] = {{.name = "floor", .present = true}, {.name = "wall", .present = false}};
	planes[0].s = (struct lx_plane_sampling){.pixels = 1000, .lpp_median = 1, .m_median = 1, .lixels_used = 1000};
	struct lx_shadow_result res = {0};
	lx_sampling_warnings(planes, 2, 261384, &res);
	assert_int_equal(res.warning_count, 0);
	planes[0].s.lpp_median = 0.5, planes[0].s.m_median = 1.4;
	lx_sampling_warnings(planes, 2, 261384, &res);
	assert_int_equal(res.warning_count, 1);
	assert_non_null(strstr(res.warnings[0], "only 0.38% of the maps' 261384 lixels"));
	res.warning_count = 0;
	planes[0].s.lixels_used = 10000; /* 3.8%: not low */
	lx_sampling_warnings(planes, 2, 261384, &res);
	assert_int_equal(res.warning_count, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(budget_warning_only_where_coarse),
		cmocka_unit_test(scale_changes_nothing),
		cmocka_unit_test(random_extremes_warn_or_match),
		cmocka_unit_test(named_extremes_match),
		cmocka_unit_test(two_extreme_lights_warn_or_match),
	};
	return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
