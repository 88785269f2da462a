/* The plane-optimal method: its light camera, its sampling guarantees over a sweep of
 * configurations, its degenerate cases, and the coverage of every shadow. GL-free. */
#include "configs.h"
#include "light_space.h"
#include "metrics.h"
#include "plane_cover.h"
#include "plane_optimal.h"
#include "shadow_method.h"
#include "test_util.h"
#include "method_fixture.h"
#include "shadow_coverage.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static vec4 row(const mat4 *m, int r) { return (vec4){m->m[r], m->m[4 + r], m->m[8 + r], m->m[12 + r]}; }
static double dot4(vec4 a, vec4 b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

/* The five-point solve agrees with the closed form of the same camera: its x, y, w rows
 * are R - (R L) pi^T / (pi . L), R the view's window rows (x w, y w, w). */
static void camera_matches_closed_form(void **state)
{
	(void)state;
	uint64_t seed = 11;
	int solved = 0;
	for (int k = 0; k < 500; k++) {
		struct lx_scene sc;
		lx_scene_default(&sc);
		sc.camera.eye = v3(test_rand(&seed) * 12 - 6, 0.3 + test_rand(&seed) * 6, test_rand(&seed) * 12 - 4);
		sc.camera.at = v3(test_rand(&seed) * 4 - 2, test_rand(&seed) * 2, test_rand(&seed) * 4 - 3);
		if (k % 4 == 0) {
			sc.light.directional = true;
			assert_true(v3_normalize(v3(test_rand(&seed) - 0.5, -0.2 - test_rand(&seed), test_rand(&seed) - 0.5),
						 &sc.light.direction));
		} else
			sc.light.position = v3(test_rand(&seed) * 14 - 7, 0.5 + test_rand(&seed) * 8, test_rand(&seed) * 14 - 7);
		struct lx_scene_meshes me;
		struct lx_frame f;
		char err[128];
		assert_true(lx_meshes_build(&sc, &me));
		if (!lx_frame_setup(&f, &sc, &me, 0, 400, 300, err, sizeof err)) {
			lx_meshes_free(&me);
			continue;
		}
		for (int p = 0; p < sc.plane_count; p++) {
			vec4 pi = lx_plane_equation(&sc.planes[p]), L = lx_light_point(&sc.light);
			struct lx_plane_camera cam;
			vec3 c = v3_add(sc.planes[p].corner, v3_scale(v3_add(sc.planes[p].edge1, sc.planes[p].edge2), 0.5));
			if (lx_plane_camera_solve(&f.view, L, pi, (vec4){c.x, c.y, c.z, 1}, &cam) != LX_PLANE_CAMERA_OK)
				continue;
			solved++;
			assert_true(cam.residual < 1e-7);
			/* R: window rows of the view */
			vec4 r[3];
			const mat4 *vp = &f.view.view_proj;
			vec4 r0 = row(vp, 0), r1 = row(vp, 1), r3 = row(vp, 3);
			r[0] = (vec4){(r0.x + r3.x) * 200, (r0.y + r3.y) * 200, (r0.z + r3.z) * 200, (r0.w + r3.w) * 200};
			r[1] = (vec4){(r1.x + r3.x) * 150, (r1.y + r3.y) * 150, (r1.z + r3.z) * 150, (r1.w + r3.w) * 150};
			r[2] = r3;
			double pl = dot4(pi, L);
			double ref[12], got[12], nref = 0, ngot = 0;
			const int rows[3] = {0, 1, 3};
			for (int i = 0; i < 3; i++) {
				double rl = dot4(r[i], L);
				vec4 q = row(&cam.m, rows[i]);
				double rv[4] = {r[i].x - rl * pi.x / pl, r[i].y - rl * pi.y / pl, r[i].z - rl * pi.z / pl,
						r[i].w - rl * pi.w / pl};
				double gv[4] = {q.x, q.y, q.z, q.w};
				for (int j = 0; j < 4; j++) {
					ref[i * 4 + j] = rv[j], got[i * 4 + j] = gv[j];
					nref += rv[j] * rv[j], ngot += gv[j] * gv[j];
				}
			}
			double sgn = 0;
			for (int j = 0; j < 12; j++)
				sgn += ref[j] * got[j];
			sgn = sgn < 0 ? -1 : 1;
			for (int j = 0; j < 12; j++)
				assert_near(got[j] / sqrt(ngot), sgn * ref[j] / sqrt(nref), 1e-8);
			/* and points of the plane keep their window coordinates */
			for (int t = 0; t < 5; t++) {
				vec3 q = v3_add(sc.planes[p].corner, v3_add(v3_scale(sc.planes[p].edge1, test_rand(&seed)),
									     v3_scale(sc.planes[p].edge2, test_rand(&seed))));
				vec4 a = m4_mul_point(&cam.m, q), b = m4_mul_point(vp, q);
				if (fabs(b.w) < 1e-6 || fabs(a.w) < 1e-12)
					continue;
				assert_near(a.x / a.w, (b.x / b.w + 1) * 200, 1e-6 * (1 + fabs(a.x / a.w)));
				assert_near(a.y / a.w, (b.y / b.w + 1) * 150, 1e-6 * (1 + fabs(a.y / a.w)));
			}
		}
		lx_meshes_free(&me);
	}
	print_message("%d plane cameras solved and checked\n", solved);
	assert_true(solved > 700);
}

/* A public engine fixed m33 = 1 after an unpivoted solve, which breaks when the true
 * m33 is 0: the world origin on the light camera's principal plane, which holds the
 * light. With the whole scene moved so that the light sits at the origin, m33 is 0
 * and the solve must still meet every constraint (and keep the window coordinates). */
static void m33_zero_is_solved(void **state)
{
	(void)state;
	struct lx_scene sc;
	lx_scene_default(&sc);
	vec3 shift = v3_scale(sc.light.position, -1);
	for (int p = 0; p < sc.plane_count; p++)
		sc.planes[p].corner = v3_add(sc.planes[p].corner, shift);
	for (int c = 0; c < sc.caster_count; c++)
		sc.casters[c].x += shift.x, sc.casters[c].z += shift.z, sc.casters[c].low += shift.y, sc.casters[c].high += shift.y;
	sc.camera.eye = v3_add(sc.camera.eye, shift);
	sc.camera.at = v3_add(sc.camera.at, shift);
	sc.light.position = v3(0, 0, 0);
	struct lx_scene_meshes me;
	struct lx_frame f;
	char err[128];
	assert_true(lx_meshes_build(&sc, &me));
	assert_true(lx_frame_setup(&f, &sc, &me, 0, 400, 300, err, sizeof err));
	for (int p = 0; p < sc.plane_count; p++) {
		struct lx_plane_camera cam;
		vec3 c = v3_add(sc.planes[p].corner, v3_scale(v3_add(sc.planes[p].edge1, sc.planes[p].edge2), 0.5));
		assert_int_equal(lx_plane_camera_solve(&f.view, lx_light_point(&sc.light), lx_plane_equation(&sc.planes[p]),
						       (vec4){c.x, c.y, c.z, 1}, &cam),
				 LX_PLANE_CAMERA_OK);
		double big = 0;
		for (int i = 0; i < 16; i++)
			big = fmax(big, fabs(cam.m.m[i]));
		assert_true(fabs(cam.m.m[15]) < 1e-12 * big); /* m33 is 0 here */
		assert_true(cam.residual < 1e-7);
		vec3 q = v3_add(sc.planes[p].corner, v3_scale(sc.planes[p].edge1, 0.3));
		vec4 a = m4_mul_point(&cam.m, q), b = m4_mul_point(&f.view.view_proj, q);
		assert_near(a.x / a.w, (b.x / b.w + 1) * 200, 1e-6);
		assert_near(a.y / a.w, (b.y / b.w + 1) * 150, 1e-6);
	}
	lx_meshes_free(&me);
}

/* View k of a sweep of the default scene: the standard configurations, then cameras and
 * lights drawn from seed (every fifth light directional, every seventh a lamp on the eye). */
static void sweep_view(struct lx_scene *sc, int k, uint64_t *seed)
{
	lx_scene_default(sc);
	if (k < lx_config_count) {
		lx_config_apply(&lx_configs[k], sc);
		return;
	}
	sc->camera.eye = v3(test_rand(seed) * 12 - 6, 0.05 + test_rand(seed) * 6, test_rand(seed) * 12 - 4.9);
	sc->camera.at = v3(test_rand(seed) * 6 - 3, test_rand(seed) * 2.5, test_rand(seed) * 6 - 4);
	sc->camera.fovy_deg = 30 + test_rand(seed) * 70;
	if (k % 5 == 0) {
		sc->light.directional = true;
		assert_true(v3_normalize(v3(test_rand(seed) - 0.5, -0.05 - test_rand(seed), test_rand(seed) - 0.5),
					 &sc->light.direction));
	} else if (k % 7 == 0)
		sc->light.position = v3_add(sc->camera.eye, v3(0, 0.05, 0)); /* a lamp on a helmet */
	else
		sc->light.position = v3(test_rand(seed) * 14 - 7, 0.2 + test_rand(seed) * 8, test_rand(seed) * 14 - 4.5);
}

/* Window point (wx, wy) on the plane eq the plain way, for the row form to answer to: the
 * near and far points unprojected by inv_view_proj and divided, the ray cut by the plane.
 * False for a point at infinity or a ray along the plane. */
static bool unprojected_on_plane(const struct lx_view *v, vec4 eq, double wx, double wy, vec3 *q, double *t)
{
	double nx = 2 * wx / v->width - 1, ny = 2 * wy / v->height - 1;
	vec4 a = m4_mul_v4(&v->inv_view_proj, (vec4){nx, ny, -1, 1}), b = m4_mul_v4(&v->inv_view_proj, (vec4){nx, ny, 1, 1});
	if (!(fabs(a.w) > 1e-300) || !(fabs(b.w) > 1e-300))
		return false;
	vec3 pn = v3(a.x / a.w, a.y / a.w, a.z / a.w), d = v3_sub(v3(b.x / b.w, b.y / b.w, b.z / b.w), pn);
	double den = v3_dot(v3(eq.x, eq.y, eq.z), d);
	if (!(fabs(den) > 1e-300))
		return false;
	*t = -v4_dot_point(eq, pn) / den;
	*q = v3_add(pn, v3_scale(d, *t));
	return true;
}

/* The pixel points of the metrics and the set-up (lx_pixel_on_plane, lx_window_on_plane:
 * a row's rays made once) against two unprojections for each pixel: the same pixels on each plane but
 * where the ray meets the parallelogram's edge or the view's depth range within rounding,
 * the same points to a billionth of the scene, on the standard views and random ones,
 * among them views looking along a plane (the horizon, the eye on the floor). */
static void pixel_points_match_the_unprojection(void **state)
{
	(void)state;
	uint64_t seed = 77;
	long compared = 0, on = 0, edge = 0;
	for (int k = 0; k < 60; k++) {
		struct setup s;
		memset(&s, 0, sizeof s);
		sweep_view(&s.scene, k, &seed);
		if (k >= lx_config_count && k % 4 == 0) /* the eye on the floor, looking along it */
			s.scene.camera.eye.y = s.scene.camera.at.y = 1e-9;
		int w = 97 + k, h = 61 + 2 * k;
		assert_true(build(&s, "uniform", w, h, 0));
		for (int p = 0; p < s.scene.plane_count; p++) {
			const struct lx_plane *pl = &s.scene.planes[p];
			struct lx_plane_gram g = lx_plane_gram(pl);
			double size = v3_len(pl->edge1) + v3_len(pl->edge2);
			for (int y = 0; y < h; y += 3)
				for (int x = 0; x < w; x += 2) {
					vec3 a = v3(0, 0, 0), b = v3(0, 0, 0);
					double t = -1;
					bool got = lx_pixel_on_plane(&s.frame, p, x, y, &a);
					vec3 c = v3(0, 0, 0);
					double tc = -1;
					bool want = unprojected_on_plane(&s.frame.view, lx_plane_equation(pl), x + 0.5, y + 0.5, &b, &t) &&
						    t >= 0 && t <= 1 && lx_plane_gram_contains(&g, b);
					/* the set-up's entry point gives the metrics' point, bit for bit */
					if (got && !(lx_window_on_plane(&s.frame.view, lx_plane_equation(pl), x + 0.5, y + 0.5, &c, &tc) &&
						     c.x == a.x && c.y == a.y && c.z == a.z))
						fail_msg("view %d, plane %d, pixel (%d, %d): lx_window_on_plane %g %g %g against %g %g %g", k,
							 p, x, y, c.x, c.y, c.z, a.x, a.y, a.z);
					compared++;
					on += got;
					if (got != want) { /* only where rounding decides: at the depth range's ends or an edge */
						vec3 r = v3_sub(want ? b : a, g.corner);
						double su = (v3_dot(r, g.edge1) * g.e22 - v3_dot(r, g.edge2) * g.e12) / g.det,
						       sv = (v3_dot(r, g.edge2) * g.e11 - v3_dot(r, g.edge1) * g.e12) / g.det;
						double near_edge = fmin(fmin(fabs(su), fabs(su - 1)), fmin(fabs(sv), fabs(sv - 1)));
						if (!(near_edge < 1e-9 || fabs(t) < 1e-9 || fabs(t - 1) < 1e-9))
							fail_msg("view %d, plane %d, pixel (%d, %d): on the plane %d, by the unprojection %d (t %g)",
								 k, p, x, y, got, want, t);
						edge++;
					} else if (got && !(v3_len(v3_sub(a, b)) <= 1e-9 * size))
						fail_msg("view %d, plane %d, pixel (%d, %d): point %g %g %g against %g %g %g", k, p, x, y,
							 a.x, a.y, a.z, b.x, b.y, b.z);
				}
		}
		lx_meshes_free(&s.meshes);
	}
	print_message("%ld pixel rays compared, %ld on a plane, %ld decided otherwise at an edge\n", compared, on, edge);
	assert_true(on > compared / 4);
}

/* Sampling of one setup's plane maps: one affine image of the screen on every pixel each
 * serves (lpp and lixel span each within 1.001 over them), lpp = scale^2 (1 where the
 * budget suffices), and aniso = stretch^2: a similarity unless stretched, which only a
 * map short of a lixel per pixel is. Returns maps checked; *stretched counts those. */
static int check_sampling(const struct setup *s, const char *what, int *stretched)
{
	int checked = 0;
	struct lx_plane_sampling per_plane[LX_MAX_PLANES]; /* a plane's pieces share its figures */
	bool sampled[LX_MAX_PLANES] = {false}, any[LX_MAX_PLANES] = {false};
	for (int k = 0; k < s->res.warning_count; k++) /* every map packed as sized: none shrunk */
		if (strstr(s->res.warnings[k], "atlas:"))
			fail_msg("%s: %s", what, s->res.warnings[k]);
	for (int m = 0; m < s->res.map_count; m++) {
		const struct lx_shadow_map *map = &s->res.maps[m];
		if (!m4_finite(&map->light_clip))
			fail_msg("%s: map %d has a non-finite matrix", what, m);
		if (!map->rendered || map->plane < 0)
			continue;
		const struct lx_region *g = &s->atlas.regions[map->region];
		if (g->w != map->w || g->h != map->h) /* the region holds the map's lixels (cut_to_regions) */
			fail_msg("%s: map %d sized %dx%d, placed %dx%d", what, m, map->w, map->h, g->w, g->h);
		if (!sampled[map->plane])
			any[map->plane] = lx_plane_sampling(&s->frame, &s->atlas, &s->res, map->plane, NULL, NULL, NULL,
							    &per_plane[map->plane]),
			sampled[map->plane] = true;
		if (!any[map->plane])
			continue;
		const struct lx_plane_sampling ps = per_plane[map->plane];
		double k2 = map->lixel_scale * map->lixel_scale, st = map->lixel_stretch;
		double aniso = fmax(st * st, 1 / (st * st));
		if (!(fabs(ps.aniso_max - aniso) <= 1e-3 * aniso && ps.lpp_max / ps.lpp_min <= 1.001 &&
		      ps.m_max / ps.m_median <= 1.001 && fabs(ps.lpp_median - k2) <= 1e-3 * k2))
			fail_msg("%s: plane %s: %ld px, aniso_max %.6f (stretch %.4f), lpp %.6f..%.6f, m %.4f..%.4f, scale^2 %.6f",
				 what, s->scene.planes[map->plane].name, ps.pixels, ps.aniso_max, st, ps.lpp_min, ps.lpp_max,
				 ps.m_median, ps.m_max, k2);
		if (map->lixel_scale == 1.0)
			assert_true(ps.lpp_min >= 0.999 && ps.lpp_max <= 1.001);
		if (st != 1) { /* short of lpp 1, within 3, the finer axis whole where it reaches 1 */
			double fine = map->lixel_scale * fmax(st, 1 / st);
			assert_true(map->lixel_scale < 1 && st >= 1 / 3.0 && st <= 3.0);
			assert_true(fine < 1 || fabs(fine - round(fine)) < 1e-9 * fine);
			++*stretched;
		}
		checked++;
	}
	return checked;
}

static void sweep_is_one_affine_map_on_every_plane(void **state)
{
	(void)state;
	uint64_t seed = 2024;
	int configs = 0, maps = 0, full = 0, stretched = 0, most_reads = 0, pieces = 0;
	for (int k = 0; k < 320; k++) {
		struct setup s;
		memset(&s, 0, sizeof s);
		sweep_view(&s.scene, k, &seed);
		int w = k % 6 == 3 ? 1920 : k % 3 == 0 ? 640 : 160, h = k % 6 == 3 ? 1080 : k % 3 == 0 ? 480 : 120;
		if (!build(&s, "plane", w, h, test_rand(&seed) * 5))
			continue;
		char what[64];
		snprintf(what, sizeof what, "configuration %d", k);
		int n = check_sampling(&s, what, &stretched);
		maps += n;
		for (int id = 0; id < s.frame.object_count; id++) { /* what one draw of it reads (LX_MAX_READS) */
			/* the method's own choice, before lx_shadow_receiver_maps keeps the first four */
			unsigned chosen = s.res.object_maps[id];
			for (int m = 0; !chosen && m < s.res.map_count; m++)
				chosen |= s.res.maps[m].rendered && s.res.maps[m].plane == id ? 1u << m : 0;
			int reads = __builtin_popcount(chosen ? chosen : lx_shadow_receiver_maps(&s.res, id));
			most_reads = reads > most_reads ? reads : most_reads;
			if (reads > LX_MAX_READS)
				fail_msg("%s: object %d reads %d maps", what, id, reads);
		}
		for (int m = 0; m < s.res.map_count; m++)
			pieces += s.res.maps[m].rendered && m >= s.scene.plane_count && m < s.res.map_count - 1; /* the spare pieces: between the planes' maps and the fallback */
		for (int m = 0; m < s.res.map_count; m++)
			full += s.res.maps[m].rendered && s.res.maps[m].plane >= 0 && s.res.maps[m].lixel_scale >= 1.0;
		configs++;
		lx_meshes_free(&s.meshes);
	}
	print_message("%d configurations, %d plane maps checked (%d with a lixel or more for every pixel, %d stretched, "
		      "%d spare pieces); at most %d maps read by one object\n", configs, maps, full, stretched, pieces, most_reads);
	assert_true(configs >= 300 && maps >= 300 && full >= 100 && stretched >= 10 && pieces >= 30);
}

/* Shared budgets: a map keeps the scale its own budget gives when that covers what it
 * needs, and hands on the rest, which a map short of lpp 1 takes; the total stays within
 * the two plane budgets. Every standard configuration of both scenes at two sizes, against
 * fixed budgets, under which only a map with nothing to serve hands its budget on: a map
 * short of lpp 1 beside a plane without a map holds more than its own 350^2 either way.
 * The default scene's light facing the camera at 1024x1024 is such a case: the floor,
 * short at scale 0.78 with its own budget, reaches 1 with the wall's, which serves
 * nothing there. */
static void shared_budgets_hand_on_the_rest(void **state)
{
	(void)state;
	static const int sizes[2][2] = {{1024, 1024}, {1920, 1080}};
	int compared = 0, raised = 0, stretched = 0, short_alone = 0, lent = 0;
	bool facing_whole = false;
	for (int k = 0; k < 4 * lx_config_count; k++) {
		struct setup fx, sh;
		struct lx_method_options of = LX_METHOD_OPTIONS_DEFAULT, os = LX_METHOD_OPTIONS_DEFAULT;
		os.shared_budget = true;
		/* what the budgets give, past a lixel per pixel too: the readers' density, which
		 * lowers a map there, is readers_set_the_density_past_one's */
		of.plane_dense_budget = os.plane_dense_budget = true;
		int c = k / 4, table = k % 2, z = k / 2 % 2;
		memset(&fx, 0, sizeof fx);
		table ? lx_scene_table(&fx.scene) : lx_scene_default(&fx.scene);
		lx_config_apply(&lx_configs[c], &fx.scene);
		memset(&sh, 0, sizeof sh);
		sh.scene = fx.scene;
		assert_true(build_with(&fx, "plane", sizes[z][0], sizes[z][1], 0, &of));
		assert_true(build_with(&sh, "plane", sizes[z][0], sizes[z][1], 0, &os));
		char what[96];
		snprintf(what, sizeof what, "%s scene, %s, %dx%d, shared", table ? "table" : "default", lx_configs[c].name,
			 sizes[z][0], sizes[z][1]);
		long total = 0;
		for (int m = 0; m < sh.res.map_count; m++) {
			const struct lx_shadow_map *a = &fx.res.maps[m], *b = &sh.res.maps[m];
			if (b->rendered && b->plane >= 0)
				total += (long)b->w * b->h;
			if (!a->rendered || a->plane < 0 || m >= 2)
				continue; /* the spare pieces follow their plane's scale */
			if (!b->rendered || b->lixel_scale < a->lixel_scale)
				fail_msg("%s: plane map %d lost lixels: scale %.4f against %.4f with fixed budgets", what, m,
					 b->rendered ? b->lixel_scale : 0.0, a->lixel_scale);
			raised += b->lixel_scale > a->lixel_scale;
			compared++;
			long own_held = 0; /* with fixed budgets: more than its own, only beside a plane without a map */
			for (int q = 0; q < fx.res.map_count; q++)
				own_held += fx.res.maps[q].rendered && fx.res.maps[q].plane == m ? (long)fx.res.maps[q].w * fx.res.maps[q].h : 0;
			if (own_held > 350L * 350 && fx.res.maps[1 - m].rendered)
				fail_msg("%s: plane map %d holds %ld lixels beside a plane with a map, with fixed budgets", what, m,
					 own_held);
			lent += own_held > 350L * 350;
			if (a->lixel_scale < 1 && !fx.res.maps[1 - m].rendered) { /* the other's budget all spare */
				short_alone++;
				long held = 0;
				for (int q = 0; q < fx.res.map_count; q++)
					held += fx.res.maps[q].rendered && fx.res.maps[q].plane == m ? (long)fx.res.maps[q].w * fx.res.maps[q].h : 0;
				if (!(held > 350L * 350))
					fail_msg("%s: plane map %d short at scale %.4f beside a plane without a map holds %ld lixels, "
						 "its own budget alone, with fixed budgets", what, m, a->lixel_scale, held);
			}
		}
		if (total > 2L * 350 * 350)
			fail_msg("%s: the plane maps hold %ld lixels, more than the two budgets", what, total);
		check_sampling(&sh, what, &stretched);
		if (!table && !strcmp(lx_configs[c].name, "facing") && z == 0)
			facing_whole = fx.res.maps[0].lixel_scale == 1.0 && sh.res.maps[0].lixel_scale == 1.0;
		lx_meshes_free(&fx.meshes);
		lx_meshes_free(&sh.meshes);
	}
	print_message("%d plane maps compared, %d denser with shared budgets; with fixed ones %d took the budget of a plane "
		      "without a map, %d of them still short of a lixel per pixel\n", compared, raised, lent, short_alone);
	assert_true(facing_whole);
	/* the rest goes to the fallback (the table seen from close to the floor), but not under
	 * a density cap, which is there to spend less fill */
	for (int capped = 0; capped < 2; capped++) {
		struct setup t;
		struct lx_method_options os = LX_METHOD_OPTIONS_DEFAULT;
		os.shared_budget = true;
		os.plane_max_lpp = capped ? 1 : 0;
		memset(&t, 0, sizeof t);
		lx_scene_table(&t.scene);
		lx_config_apply(lx_config_find("floor-close"), &t.scene);
		assert_true(build_with(&t, "plane", 1024, 1024, 0, &os));
		const struct lx_shadow_map *fb = &t.res.maps[t.res.map_count - 1]; /* the fallback: read last */
		assert_true(fb->rendered && fb->plane < 0);
		if (capped)
			assert_int_equal(fb->w, 128);
		else
			assert_true(fb->w > 256 && fb->w == fb->h);
		lx_meshes_free(&t.meshes);
	}
	assert_true(compared >= 3 * lx_config_count && lent >= 4 && short_alone >= 1 && raised >= 1);
}

/* Past a lixel per pixel a plane map is only as dense as the casters reading it need
 * (method_plane.c, readers_scale): against the budget's density (plane_dense_budget) on
 * every standard configuration of both scenes at 320x240 and 1024x1024, each plane map is
 * the same map or the same at a smaller whole-number scale, never short of a lixel per
 * pixel where the budget gives one; the casters another's shadow may reach (the others
 * look nothing up) keep reading every plane map they read.
 * Some are lowered (the default scene's low light: the wall from 2x2 lixels a pixel to
 * one) and some kept (its floor, read by the cone at 3x3; the floor under the table seen
 * from below its top at 320x240, read by the legs). Under a filter nothing moves; under
 * a cap the readers ask within it. */
static void readers_set_the_density_past_one(void **state)
{
	(void)state;
	static const int sizes[2][2] = {{320, 240}, {1024, 1024}};
	int compared = 0, lowered = 0, kept = 0, moved_filtered = 0;
	for (int k = 0; k < 4 * lx_config_count + 2; k++) {
		struct setup bu, rd;
		struct lx_method_options ob = LX_METHOD_OPTIONS_DEFAULT, orr = LX_METHOD_OPTIONS_DEFAULT;
		ob.plane_dense_budget = true;
		bool below = k >= 4 * lx_config_count; /* the table seen from below its top */
		int c = below ? 0 : k / 4, table = below || k % 2, z = below ? 0 : k / 2 % 2;
		orr.filtered = below && k % 2; /* the second: filtered */
		memset(&bu, 0, sizeof bu);
		table ? lx_scene_table(&bu.scene) : lx_scene_default(&bu.scene);
		if (below) {
			bu.scene.camera.eye = (vec3){0, 0.5, 3};
			bu.scene.camera.at = (vec3){0, 0.5, 0};
		} else
			lx_config_apply(&lx_configs[c], &bu.scene);
		memset(&rd, 0, sizeof rd);
		rd.scene = bu.scene;
		double t = below ? 0.4 : 0;
		assert_true(build_with(&bu, "plane", sizes[z][0], sizes[z][1], t, &ob));
		assert_true(build_with(&rd, "plane", sizes[z][0], sizes[z][1], t, &orr));
		char what[96];
		snprintf(what, sizeof what, "%s scene, %s, %dx%d%s", table ? "table" : "default",
			 below ? "from below the top" : lx_configs[c].name, sizes[z][0], sizes[z][1],
			 orr.filtered ? ", filtered" : "");
		assert_int_equal(bu.res.map_count, rd.res.map_count);
		for (int m = 0; m < rd.res.map_count; m++) {
			const struct lx_shadow_map *a = &bu.res.maps[m], *b = &rd.res.maps[m];
			if (a->rendered != b->rendered || a->plane != b->plane)
				fail_msg("%s: map %d drawn or placed otherwise", what, m);
			if (!a->rendered || a->plane < 0)
				continue;
			compared++;
			double sa = a->lixel_scale, sb = b->lixel_scale;
			bool same = sa == sb && a->w == b->w && a->h == b->h;
			if (!same && !(sa > 1 && sb >= 1 && sb < sa && sb == floor(sb) && b->lixel_stretch == 1))
				fail_msg("%s: map %d at scale %.4f (%dx%d) against the budget's %.4f (%dx%d)", what, m, sb, b->w, b->h,
					 sa, a->w, a->h);
			lowered += !same;
			kept += same && sa > 1;
			if (orr.filtered && !same)
				moved_filtered++;
			if (below && m == 1 && !(same && sa > 1))
				fail_msg("%s: the floor map at scale %.4f, expected the budget's (above one) for the legs", what, sb);
		}
		unsigned plane_reads = 0, fb = 1u << (bu.res.map_count - 1); /* the plane maps; the fallback, last */
		for (int m = 0; m < bu.res.map_count - 1; m++)
			plane_reads |= bu.res.maps[m].plane >= 0 ? 1u << m : 0;
		for (int id = rd.scene.plane_count; id < rd.frame.object_count; id++) {
			unsigned ra = bu.res.object_maps[id] & plane_reads, rb = rd.res.object_maps[id] & plane_reads;
			if (rd.res.shadow_reaches[id] != bu.res.shadow_reaches[id])
				fail_msg("%s: object %d reached otherwise", what, id);
			if (rd.res.shadow_reaches[id] && (bu.res.object_maps[id] & fb) && (ra & ~rb))
				fail_msg("%s: object %d reads plane maps %#x, %#x with the budget's density", what, id, rb, ra);
		}
		lx_meshes_free(&bu.meshes);
		lx_meshes_free(&rd.meshes);
	}
	/* under a cap (--plane-max-lpp 4) the readers ask within it: the low light's floor,
	 * which the cone reads at 3x3 but would find less dense than the fallback at the cap's
	 * 2x2 (0.41 against 0.44 lixels per pixel in its worst direction), is read by none and
	 * goes to one, as the wall */
	struct setup cap;
	struct lx_method_options oc = LX_METHOD_OPTIONS_DEFAULT;
	oc.plane_max_lpp = 4;
	memset(&cap, 0, sizeof cap);
	lx_scene_default(&cap.scene);
	lx_config_apply(lx_config_find("low"), &cap.scene);
	assert_true(build_with(&cap, "plane", 1024, 1024, 0, &oc));
	assert_true(cap.res.maps[0].rendered && cap.res.maps[1].rendered);
	assert_true(cap.res.maps[0].lixel_scale == 1 && cap.res.maps[1].lixel_scale == 1);
	lx_meshes_free(&cap.meshes);
	print_message("%d plane maps compared with the budget's density: %d lowered to what their readers need, %d kept "
		      "above a lixel per pixel\n", compared, lowered, kept);
	assert_int_equal(moved_filtered, 0);
	assert_true(compared >= 2 * lx_config_count && lowered >= 5 && kept >= 1);
}

/* --caster-maps fallback (caster_fallback_only): on every standard configuration of both
 * scenes at 1024x1024 each caster reads the fallback alone, and no plane map is denser
 * than a lixel per pixel (none of them read by a caster), the same maps drawn for the same
 * planes, the same casters reached, as by default; by default some caster reads a plane
 * map (the default view's ball the floor's, which the cylinder's shadow may reach). The
 * plane maps take a lixel per pixel from the first fit, so with shared budgets what they
 * leave goes to the fallback, which is never smaller than by default and on some view
 * larger. */
static void casters_read_the_fallback_alone(void **state)
{
	(void)state;
	int views = 0, plane_readers = 0, fallback_grew = 0;
	for (int k = 0; k < 2 * lx_config_count; k++) {
		struct setup d, fo;
		struct lx_method_options od = LX_METHOD_OPTIONS_DEFAULT, of = LX_METHOD_OPTIONS_DEFAULT;
		of.caster_fallback_only = true;
		bool table = k % 2;
		const char *config = lx_configs[k / 2].name;
		memset(&d, 0, sizeof d);
		table ? lx_scene_table(&d.scene) : lx_scene_default(&d.scene);
		lx_config_apply(&lx_configs[k / 2], &d.scene);
		memset(&fo, 0, sizeof fo);
		fo.scene = d.scene;
		assert_true(build_with(&d, "plane", 1024, 1024, 0, &od));
		assert_true(build_with(&fo, "plane", 1024, 1024, 0, &of));
		int fbm = fo.res.map_count - 1; /* the fallback, last */
		assert_int_equal(d.res.map_count, fo.res.map_count);
		for (int m = 0; m < fo.res.map_count; m++) {
			const struct lx_shadow_map *a = &d.res.maps[m], *b = &fo.res.maps[m];
			if (a->rendered != b->rendered || a->plane != b->plane)
				fail_msg("%s scene, %s: map %d drawn or placed otherwise", table ? "table" : "default", config, m);
			if (b->rendered && b->plane >= 0 && !(b->lixel_scale <= 1))
				fail_msg("%s scene, %s: map %d at %.4f lixels a pixel along each axis, read by no caster",
					 table ? "table" : "default", config, m, b->lixel_scale);
		}
		for (int id = fo.scene.plane_count; id < fo.frame.object_count; id++) {
			unsigned want = fo.res.maps[fbm].rendered ? 1u << fbm : 0;
			if (lx_shadow_receiver_maps(&fo.res, id) != want || fo.res.shadow_reaches[id] != d.res.shadow_reaches[id])
				fail_msg("%s scene, %s: caster %d reads maps %#x, expected the fallback's %#x",
					 table ? "table" : "default", config, id, lx_shadow_receiver_maps(&fo.res, id), want);
			plane_readers += (lx_shadow_receiver_maps(&d.res, id) & ~(1u << fbm)) != 0;
		}
		struct setup ds, fs;
		od.shared_budget = of.shared_budget = true;
		memset(&ds, 0, sizeof ds);
		memset(&fs, 0, sizeof fs);
		ds.scene = fs.scene = d.scene;
		assert_true(build_with(&ds, "plane", 1024, 1024, 0, &od));
		assert_true(build_with(&fs, "plane", 1024, 1024, 0, &of));
		const struct lx_shadow_map *fd = &ds.res.maps[fbm], *ff = &fs.res.maps[fbm];
		if (ff->rendered && (long)ff->w * ff->h < (long)fd->w * fd->h)
			fail_msg("%s scene, %s, shared budgets: the fallback %dx%d, by default %dx%d", table ? "table" : "default",
				 config, ff->w, ff->h, fd->w, fd->h);
		fallback_grew += ff->rendered && (long)ff->w * ff->h > (long)fd->w * fd->h;
		views++;
		lx_meshes_free(&d.meshes);
		lx_meshes_free(&fo.meshes);
		lx_meshes_free(&ds.meshes);
		lx_meshes_free(&fs.meshes);
	}
	print_message("%d views: casters read the fallback alone; by default %d casters read a plane map; with shared "
		      "budgets the fallback larger on %d\n",
		      views, plane_readers, fallback_grew);
	assert_true(views == 2 * lx_config_count && plane_readers >= 1 && fallback_grew >= 1);
}

/* A frame's maps do not depend on the frames before it: a build on an atlas that packed
 * another view's maps (the fallback's size, the plane maps' shapes) gives the same maps as
 * on a fresh one. Every configuration of both scenes after every other one's, with fixed
 * and shared budgets (the bench reuses a run over its configurations: a density check that
 * read the fallback's last size once moved the table's shared mismatch from 0.0447% to
 * 0.1079%). */
static void maps_do_not_depend_on_the_frame_before(void **state)
{
	(void)state;
	int pairs = 0;
	for (int shared = 0; shared < 2; shared++)
		for (int k = 0; k < 2 * lx_config_count; k++) {
			struct setup fresh, before;
			struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
			o.shared_budget = shared;
			int c = k / 2, prev = (c + 1 + k % 3) % lx_config_count;
			memset(&fresh, 0, sizeof fresh);
			memset(&before, 0, sizeof before);
			k % 2 ? lx_scene_table(&fresh.scene) : lx_scene_default(&fresh.scene);
			before.scene = fresh.scene;
			lx_config_apply(&lx_configs[prev], &before.scene);
			lx_config_apply(&lx_configs[c], &fresh.scene);
			assert_true(build_with(&fresh, "plane", 1024, 1024, 0, &o));
			assert_true(build_with(&before, "plane", 1024, 1024, 0, &o));
			/* the same view again, on the atlas the other view left */
			const struct lx_shadow_method *m = lx_shadow_method_find("plane");
			lx_meshes_free(&before.meshes);
			before.scene = fresh.scene;
			char err[256];
			assert_true(lx_meshes_build(&before.scene, &before.meshes));
			assert_true(lx_frame_setup(&before.frame, &before.scene, &before.meshes, 0, 1024, 1024, err, sizeof err));
			lx_shadow_method_frame(m, &before.frame, &before.atlas, &o, &before.res);
			for (int i = 0; i < fresh.res.map_count; i++) {
				const struct lx_shadow_map *a = &fresh.res.maps[i], *b = &before.res.maps[i];
				if (a->rendered != b->rendered || a->w != b->w || a->h != b->h ||
				    memcmp(&a->light_clip, &b->light_clip, sizeof a->light_clip))
					fail_msg("%s scene, %s after %s, %s budgets: map %d differs", k % 2 ? "table" : "default",
						 lx_configs[c].name, lx_configs[prev].name, shared ? "shared" : "fixed", i);
			}
			if (memcmp(fresh.res.object_maps, before.res.object_maps, sizeof fresh.res.object_maps))
				fail_msg("%s scene, %s after %s, %s budgets: the maps an object reads differ",
					 k % 2 ? "table" : "default", lx_configs[c].name, lx_configs[prev].name,
					 shared ? "shared" : "fixed");
			pairs++;
			lx_meshes_free(&fresh.meshes);
			lx_meshes_free(&before.meshes);
		}
	print_message("%d views built after another, the same maps\n", pairs);
}

/* The plane points a frame's methods share (lx_plane_points_make) give each method's
 * plane figures bit for bit as each pixel's own ray does, and are what is read: a pixel
 * dropped from them drops from the figures. */
static void shared_plane_points_give_the_same_figures(void **state)
{
	(void)state;
	enum { w = 160, h = 120 };
	int16_t *obj = malloc((size_t)w * h * sizeof(int16_t));
	uint8_t *sh = malloc((size_t)w * h);
	assert_true(obj && sh);
	int compared = 0;
	for (int k = 0; k < 2 * lx_config_count; k++) {
		for (const char *const *method = (const char *const[]){"plane", "uniform", "lispsm", NULL}; *method; method++) {
			struct setup s;
			memset(&s, 0, sizeof s);
			k % 2 ? lx_scene_table(&s.scene) : lx_scene_default(&s.scene);
			lx_config_apply(&lx_configs[k / 2], &s.scene);
			if (!build(&s, *method, w, h, 0.4))
				continue;
			assert_true(lx_reference_image(&s.frame, obj, sh, 1));
			struct lx_plane_points pts;
			assert_true(lx_plane_points_make(&s.frame, obj, &pts));
			for (int p = 0; p < s.scene.plane_count; p++) {
				struct lx_plane_sampling own, shared;
				bool a = lx_plane_sampling(&s.frame, &s.atlas, &s.res, p, obj, NULL, NULL, &own);
				bool b = lx_plane_sampling(&s.frame, &s.atlas, &s.res, p, obj, &pts, NULL, &shared);
				assert_int_equal(a, b);
				if (memcmp(&own, &shared, sizeof own))
					fail_msg("%s, configuration %s, plane %d: the shared points change the figures (%ld against %ld pixels)",
						 *method, lx_configs[k / 2].name, p, shared.pixels, own.pixels);
				for (long i = 0; a && i < (long)w * h; i++)
					if (obj[i] == p && pts.on[i]) { /* drop one pixel of the plane */
						pts.on[i] = 0;
						assert_true(lx_plane_sampling(&s.frame, &s.atlas, &s.res, p, obj, &pts, NULL, &shared) ||
							    own.pixels == 1);
						assert_true(shared.pixels + shared.unserved + shared.degenerate ==
							    own.pixels + own.unserved + own.degenerate - 1);
						pts.on[i] = 1;
						break;
					}
				compared += a;
			}
			lx_plane_points_free(&pts);
			lx_meshes_free(&s.meshes);
		}
	}
	print_message("%d plane figures the same with the shared points\n", compared);
	assert_true(compared >= 2 * lx_config_count);
	free(obj);
	free(sh);
}

static void every_shadow_is_covered(void **state)
{
	(void)state;
	uint64_t seed = 99;
	long total = 0;
	int fallback_used = 0;
	for (int k = 0; k < 120; k++) {
		struct setup s;
		memset(&s, 0, sizeof s);
		if (k % 4 == 3)
			lx_scene_table(&s.scene);
		else
			lx_scene_default(&s.scene);
		if (k < lx_config_count)
			lx_config_apply(&lx_configs[k], &s.scene);
		else
			test_random_view(&s.scene, &seed, k % 5 == 0, 0.1);
		if (!build(&s, "plane", 320, 240, test_rand(&seed) * 5))
			continue;
		bool wide = false;
		for (int i = 0; i < s.res.warning_count; i++)
			wide |= strstr(s.res.warnings[i], "150 degrees") != NULL;
		char what[256];
		snprintf(what, sizeof what, "configuration %d (eye %.2f %.2f %.2f at %.2f %.2f %.2f light %.2f %.2f %.2f%s)", k,
			 s.scene.camera.eye.x, s.scene.camera.eye.y, s.scene.camera.eye.z, s.scene.camera.at.x,
			 s.scene.camera.at.y, s.scene.camera.at.z,
			 s.scene.light.directional ? s.scene.light.direction.x : s.scene.light.position.x,
			 s.scene.light.directional ? s.scene.light.direction.y : s.scene.light.position.y,
			 s.scene.light.directional ? s.scene.light.direction.z : s.scene.light.position.z,
			 s.scene.light.directional ? " dir" : "");
		if (!wide)
			total += check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 60, what);
		fallback_used += s.res.maps[s.res.map_count - 1].rendered; /* the last map (plane_build) */
		lx_meshes_free(&s.meshes);
	}
	print_message("%ld caster/receiver pairs covered; the fallback map ran in %d configurations\n", total, fallback_used);
	assert_true(total > 10000);
	assert_true(fallback_used > 0);
}

/* A lit front's shadow is the cover test's (plane_cover.h): plane-optimal leaves it out
 * of the plane maps' wanted rectangles (method_plane.c, covered_part). Every shadow is
 * still captured: by a map, or, for a plane's receiver in the front's shadow, by the
 * test. The shelf's box casts on the floor mostly inside the shelf's shadow, and the
 * floor's map leaves that part out. On the table the slab's pair of fronts decides its
 * whole shadow, and the floor's rectangles hold the legs' and the other casters'; on the
 * default scene's default view, 0.3 s into its animation, two of the floor's rectangles
 * overlap (plane_splits: one rectangle would hold more pixels than the budget has lixels). */
static bool rects_meet(const double *a, const double *b) { return a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]; }

static void a_lit_fronts_shadow_is_left_to_its_test(void **state)
{
	(void)state;
	uint64_t seed = 5;
	struct setup s;
	memset(&s, 0, sizeof s);
	test_scene_load("shelf.scene", &s.scene);
	assert_true(build(&s, "plane", 640, 480, 0));
	coverage_left_to_cover = 0;
	long pairs = check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 400, "shelf");
	long left = coverage_left_to_cover;
	struct lx_plane_covers cv;
	lx_plane_covers(&s.frame, &cv);
	struct lx_poly img;
	assert_int_equal(cv.of[0][0], 1); /* the shelf over the floor */
	assert_true(lx_plane_cover_image(&s.frame, &cv, 1, 0, &img));
	vec2 mid = {0, 0};
	for (int k = 0; k < img.n; k++)
		mid.x += img.v[k].x / img.n, mid.y += img.v[k].y / img.n;
	const struct lx_shadow_map *floor = &s.res.maps[0];
	assert_true(floor->rendered && floor->has_screen);
	print_message("shelf: %ld pairs, %ld floor points left to the cover test; floor map over (%.0f, %.0f)-(%.0f, %.0f), the shelf's shadow around (%.0f, %.0f)\n",
		      pairs, left, floor->screen[0], floor->screen[1], floor->screen[2], floor->screen[3], mid.x, mid.y);
	assert_true(pairs > 300 && left > 100);
	assert_false(mid.x >= floor->screen[0] && mid.x <= floor->screen[2] && mid.y >= floor->screen[1] &&
		     mid.y <= floor->screen[3]);
	lx_meshes_free(&s.meshes);

	long table_pairs = 0, table_left = 0;
	bool overlapping = false;
	for (int c = 0; c < lx_config_count; c++) {
		memset(&s, 0, sizeof s);
		lx_scene_table(&s.scene);
		lx_config_apply(&lx_configs[c], &s.scene);
		assert_true(build(&s, "plane", 1024, 1024, 0));
		coverage_left_to_cover = 0;
		table_pairs += check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 200, lx_configs[c].name);
		table_left += coverage_left_to_cover;
		lx_meshes_free(&s.meshes);
	}
	memset(&s, 0, sizeof s);
	lx_scene_default(&s.scene);
	assert_true(build(&s, "plane", 1024, 1024, 0.3)); /* the ball a little up its bounce */
	for (int m = 0; m < s.res.map_count; m++)
		for (int n = m + 1; n < s.res.map_count; n++) {
			const struct lx_shadow_map *a = &s.res.maps[m], *b = &s.res.maps[n];
			if (a->rendered && b->rendered && a->plane >= 0 && a->plane == b->plane &&
			    rects_meet(a->screen, b->screen))
				overlapping = true, print_message("maps %d and %d of plane %d overlap\n", m, n, a->plane);
		}
	lx_meshes_free(&s.meshes);
	print_message("table, 1024x1024: %ld pairs, %ld floor points left to the cover test\n", table_pairs, table_left);
	assert_true(table_pairs > 10000);
	assert_true(overlapping);
}

/* A view of tools/random-views.py: its scene, eye, target, point light and time. */
struct random_view {
	bool table;
	vec3 eye, at, light;
	double time;
};

/* s emptied and set to view v (build_with then takes v->time). */
static void random_view_scene(struct setup *s, const struct random_view *v)
{
	memset(s, 0, sizeof *s);
	v->table ? lx_scene_table(&s->scene) : lx_scene_default(&s->scene);
	s->scene.camera.eye = v->eye, s->scene.camera.at = v->at;
	s->scene.light.position = v->light;
}

/* Random view 35 of the table (tools/random-views.py, seed 7) at 1024x768: the floor's
 * shadows lie in five clusters across 934x521 pixels. One rectangle gives them a quarter
 * of a lixel per pixel, stretched 4 to 1; the spare pieces give the floor three more
 * rectangles at one scale near a lixel per pixel, within its budget, and the sampling
 * checks hold on each. */
static void scattered_shadows_take_pieces(void **state)
{
	(void)state;
	double scale[2] = {0, 0};
	int floor_maps[2] = {0, 0};
	for (int whole = 0; whole < 2; whole++) {
		struct setup s;
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		o.plane_one_piece = whole;
		static const struct random_view v35 = {true, {1.3444, 4.06765, -0.413802}, {1.06869, 0.079947, 0.4511},
						       {-0.554718, 3.03491, 1.53064}, 4.63335};
		random_view_scene(&s, &v35);
		assert_true(build_with(&s, "plane", 1024, 768, v35.time, &o));
		long lixels = 0;
		for (int m = 0; m < s.res.map_count; m++) {
			const struct lx_shadow_map *map = &s.res.maps[m];
			if (!map->rendered || map->plane != 1) /* the floor */
				continue;
			if (floor_maps[whole]++ && map->lixel_scale != scale[whole])
				fail_msg("the floor's pieces at scales %.4f and %.4f", map->lixel_scale, scale[whole]);
			scale[whole] = map->lixel_scale;
			lixels += (long)map->w * map->h;
		}
		int stretched = 0;
		check_sampling(&s, whole ? "view 35, one rectangle" : "view 35", &stretched);
		print_message("view 35, %s: the floor in %d map%s at scale %.3f, %ld lixels\n",
			      whole ? "one rectangle" : "pieces", floor_maps[whole], floor_maps[whole] > 1 ? "s" : "",
			      scale[whole], lixels);
		assert_true(lixels <= 350L * 350);
		lx_meshes_free(&s.meshes);
	}
	assert_true(floor_maps[0] >= 3 && floor_maps[1] == 1);
	assert_true(scale[0] > 0.9 && scale[1] < 0.6);
}

/* A map whose pieces' area gives a lixel per pixel, but whose rows and columns rounded
 * out do not fit, is fitted as short of one: stretched, its finer axis snapped to a lixel
 * per pixel. Random view 19 of the table (tools/random-views.py --seed 13, 1024x768), the
 * floor at 0.995 lixels per pixel in four pieces: it was an unsnapped similarity just
 * under one, its lixel centres drifting off the pixel centres along every edge, 0.2223%
 * against uniform's 0.1948% (snapped: 0.0199%). Since the floor hidden behind the casters
 * needs no lixel (take_hidden) the view's floor gets a lixel per pixel; with 288x288
 * lixels a plane it is short of one again, as long as its footprints are not cut in
 * slabs (slab_feet), which give it one. */
static void just_short_of_one_is_snapped(void **state)
{
	(void)state;
	struct setup s;
	static const struct random_view v19 = {true, {3.12422, 2.8079, 1.09659}, {1.38558, 0.357422, -2.65246},
					       {-5.37498, 1.18244, 3.26935}, 0.535772};
	struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
	o.plane_lixels = 288, o.plane_unslabbed = true;
	random_view_scene(&s, &v19);
	assert_true(build_with(&s, "plane", 1024, 768, v19.time, &o));
	int floor_maps = 0, stretched = 0;
	for (int m = 0; m < s.res.map_count; m++) {
		const struct lx_shadow_map *map = &s.res.maps[m];
		if (!map->rendered || map->plane != 1) /* the floor */
			continue;
		floor_maps++;
		double st = fmax(map->lixel_stretch, 1 / map->lixel_stretch);
		print_message("view 19: floor map %d at scale %.5f, stretch %.5f\n", m, map->lixel_scale, st);
		assert_true(map->lixel_scale > 0.99 && map->lixel_scale < 1 && st > 1);
		assert_near(map->lixel_scale * st, 1, 1e-9); /* the finer axis: a lixel per pixel */
	}
	assert_true(floor_maps >= 2);
	check_sampling(&s, "view 19", &stretched);
	lx_meshes_free(&s.meshes);
}

/* With fixed budgets a frame without a plane map is a one-map frame: on random view 72 of
 * the default scene (tools/random-views.py) no shadow in view falls on the floor or the
 * wall, and the fallback, serving every shadow, takes all three budgets (511x511, as
 * uniform's 512x512); the default view, which has a floor map, keeps it at 128x128, as
 * does a density cap (there to spend less fill). */
static void fallback_alone_takes_every_budget(void **state)
{
	(void)state;
	for (int k = 0; k < 3; k++) {
		struct setup s;
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		static const struct random_view v72 = {false, {1.65294, 4.75918, 0.0246814}, {-0.31962, 0.255539, 0.896479},
						       {-4.29707, 1.31104, -3.39865}, 1.96661};
		if (k > 0)
			random_view_scene(&s, &v72);
		else {
			memset(&s, 0, sizeof s);
			lx_scene_default(&s.scene);
		}
		o.plane_max_lpp = k == 2 ? 1 : 0;
		assert_true(build_with(&s, "plane", 1024, 768, k > 0 ? v72.time : 0, &o));
		int plane_maps = 0, side = 0;
		for (int m = 0; m < s.res.map_count; m++) {
			const struct lx_shadow_map *map = &s.res.maps[m];
			plane_maps += map->rendered && map->plane >= 0;
			if (map->rendered && map->plane < 0) {
				const struct lx_region *g = &s.atlas.regions[map->region];
				assert_int_equal(g->w, g->h);
				side = g->w;
			}
		}
		print_message("%s: %d plane maps, the fallback %dx%d\n",
			      k == 0 ? "default view" : k == 1 ? "view 72" : "view 72, at most 1 lixel per pixel", plane_maps, side,
			      side);
		assert_int_equal(plane_maps, k == 0 ? 1 : 0);
		if (k == 0) /* the wall's idle budget (idle_plane_budget_goes_to_the_fallback) */
			assert_true(side > 128 && side <= 350);
		else
			assert_int_equal(side, k == 1 ? 511 : 128);
		lx_meshes_free(&s.meshes);
	}
}

/* The lixels per unit of G that map clip gives along the light view's axis `axis` (0: x,
 * 1: y) at point p, for a map `side` lixels across: the map's NDC moves by 2 across it. */
static double g_density(const struct lx_light_space *ls, const mat4 *clip, vec3 p, int axis, int side)
{
	vec4 r = m4_row(&ls->view, axis), a = m4_mul_point(clip, p);
	vec4 q = m4_mul_point(&ls->view, p); /* its depth along the light's axis: -q.z */
	double h = 1e-4 * ls->size;
	vec4 b = m4_mul_point(clip, v3_add(p, v3_scale(v3(r.x, r.y, r.z), h)));
	double da = axis ? b.y / b.w - a.y / a.w : b.x / b.w - a.x / a.w, dg = ls->directional ? h : h / -q.z;
	return fabs(da) / dg * 0.5 * side;
}

/* With fixed budgets a plane without a map this frame hands what the other plane's map
 * does not take to the fallback, up to a plane's budget and up to the density of a
 * one-map frame (every budget, 511x511, over C_tot as uniform maps it) along the
 * fallback's sparser axis, and up to what its casters need (a lixel per pixel; at 160x120
 * far less than that); with both planes mapped, or a density cap, it keeps 128x128.
 * Random view 186 of the default scene (seed 7, 640x480), the wall without a map: the
 * box near the eye read the 128x128 fallback, 0.0458% against uniform's 0.0112%
 * (test_render idle_budget_serves_the_casters). */
static void idle_plane_budget_goes_to_the_fallback(void **state)
{
	(void)state;
	static const struct {
		const char *what;
		bool table;
		const char *config;
		int w, h;
		double max_lpp;
		int mapless; /* planes without a map */
		bool grows, needed; /* needed: its casters' need (fallback_need) sets its side */
	} cases[] = {
		{"default view", false, NULL, 1024, 768, 0, 1, true, false},
		{"facing", false, "facing", 1024, 1024, 0, 1, true, false},
		{"horizon, 1920x1080", false, "horizon", 1920, 1080, 0, 1, true, false},
		{"table, low", true, "low", 1024, 1024, 0, 1, true, false},
		{"default view, 160x120", false, NULL, 160, 120, 0, 1, true, true},
		{"table, default view", true, NULL, 1024, 768, 0, 0, false, false},
		{"default view, at most 1 lixel per pixel", false, NULL, 1024, 768, 1, 1, false, false},
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct setup s, u;
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		o.plane_max_lpp = cases[i].max_lpp;
		for (int k = 0; k < 2; k++) {
			struct setup *x = k ? &u : &s;
			memset(x, 0, sizeof *x);
			cases[i].table ? lx_scene_table(&x->scene) : lx_scene_default(&x->scene);
			if (cases[i].config)
				lx_config_apply(lx_config_find(cases[i].config), &x->scene);
			assert_true(build_with(x, k ? "uniform" : "plane", cases[i].w, cases[i].h, 0, &o));
		}
		int mapless = 0, side = 0, fbm = -1;
		for (int m = 0; m < s.res.map_count; m++) {
			const struct lx_shadow_map *map = &s.res.maps[m];
			if (m < 2)
				mapless += !map->rendered;
			if (map->rendered && map->plane < 0)
				fbm = m, side = s.atlas.regions[map->region].w;
		}
		assert_true(fbm >= 0 && u.res.maps[0].rendered);
		/* the densities at the first caster in view, the one-map frame's from uniform's
		 * matrix at 511 lixels */
		struct lx_light_space ls;
		lx_light_space_build(&s.frame, &ls);
		int id = s.scene.plane_count;
		vec3 p = v3_scale(v3_add(s.frame.bmin[id], s.frame.bmax[id]), 0.5);
		double ratio = INFINITY; /* along the fallback's sparser axis */
		for (int axis = 0; axis < 2; axis++)
			ratio = fmin(ratio, g_density(&ls, &s.res.maps[fbm].light_clip, p, axis, side) /
						    g_density(&ls, &u.res.maps[0].light_clip, p, axis, 511));
		print_message("%-40s %d plane%s without a map, the fallback %dx%d: %.3f of the one-map density along its sparser axis\n",
			      cases[i].what, mapless, mapless == 1 ? "" : "s", side, side, ratio);
		assert_int_equal(mapless, cases[i].mapless);
		if (!cases[i].grows) {
			assert_int_equal(side, 128);
		} else {
			assert_true(side > 128 && side <= 350);
			/* as dense as the one-map frame along both axes, no denser along both, but
			 * for the side's rounding down; at a plane's budget, or where the casters
			 * need fewer lixels (a small image), less dense */
			assert_true(ratio <= 1 + 1e-6);
			if (cases[i].needed)
				assert_true(side < 350 && ratio < 0.9);
			else if (side < 350)
				assert_true(ratio >= (double)side / (side + 1) - 1e-6);
		}
		lx_meshes_free(&s.meshes);
		lx_meshes_free(&u.meshes);
	}
}

/* What one draw reads is at most LX_MAX_READS maps, the first of the set: a method that
 * chose more (none does: scattered_shadows_take_pieces, the sweep) loses the last. */
static void receiver_maps_keep_the_first_four(void **state)
{
	(void)state;
	static struct lx_shadow_result r;
	memset(&r, 0, sizeof r);
	r.map_count = 8;
	r.object_maps[3] = 0xF6u; /* maps 1, 2, 4, 5, 6 and 7 */
	assert_int_equal(lx_shadow_receiver_maps(&r, 3), 0x36u);
	for (int m = 0; m < 8; m++) /* object 0's own maps: all eight, a plane cut too far */
		r.maps[m].rendered = true, r.maps[m].plane = 0;
	assert_int_equal(lx_shadow_receiver_maps(&r, 0), 0x0Fu);
	r.object_maps[5] = 0x81u;
	assert_int_equal(lx_shadow_receiver_maps(&r, 5), 0x81u);
}

struct degenerate {
	const char *what;
	vec3 eye, at;
	int light; /* 0 point at pos, 1 directional along pos, 2 at the eye + pos */
	vec3 pos;
	const char *warning; /* a fragment expected among the warnings, or NULL */
};

/* Every singular or degenerate configuration gives
 * finite matrices, a similarity where a plane map runs, and the documented warning. */
static void degenerate_configurations(void **state)
{
	(void)state;
	static const struct degenerate cases[] = {
		{"light on the floor", {0, 2, 6}, {0, 0.8, 0}, 0, {1, 0, 1}, "plane floor: the light is within"},
		{"light 1 mm above the floor", {0, 2, 6}, {0, 0.8, 0}, 0, {1, 0.001, 1}, "plane floor: the light is within"},
		{"light on the wall", {0, 2, 6}, {0, 0.8, 0}, 0, {0.5, 3, -5}, "plane wall: the light is within"},
		{"light behind the wall", {0, 2, 6}, {0, 0.8, 0}, 0, {0.5, 3, -6}, NULL},
		{"horizon in view", {0, 1, 4.5}, {0, 1, -5}, 0, {2.5, 6, 3}, NULL},
		{"looking up: two corner rays miss the floor", {0, 0.6, 4.5}, {0, 2.5, -5}, 0, {2.5, 6, 3}, NULL},
		{"floor seen edge-on", {0, 0, 6}, {0, 0, -5}, 0, {2.5, 6, 3}, "plane floor is seen edge-on"},
		{"wall seen edge-on", {-3, 2, -5}, {3, 1, -5}, 0, {2.5, 6, 3}, "plane wall is seen edge-on"},
		{"miner's lamp", {0.5, 2.2, 5}, {0, 0.5, -1}, 2, {0, 0, 0}, "the point light is at the eye"},
		{"lamp 5 cm above the eye", {0.5, 2.2, 5}, {0, 0.5, -1}, 2, {0, 0.05, 0}, NULL},
		{"directional light", {0, 2, 6}, {0, 0.8, 0}, 1, {-0.4, -1, -0.3}, NULL},
		{"grazing directional light", {0, 2, 6}, {0, 0.8, 0}, 1, {1, -0.0001, 0}, "plane floor: the light grazes"},
		{"camera 2 cm above the floor", {0.3, 0.02, 2}, {0, 0.01, -3}, 0, {2.5, 6, 3}, NULL},
		{"camera 1 cm from the wall", {0.2, 1.5, -4.99}, {0.2, 1.4, -5}, 0, {2.5, 6, 3}, NULL},
	};
	int stretched = 0; /* counted, not required */
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct setup s;
		memset(&s, 0, sizeof s);
		lx_scene_default(&s.scene);
		s.scene.camera.eye = cases[i].eye;
		s.scene.camera.at = cases[i].at;
		if (cases[i].light == 1) {
			s.scene.light.directional = true;
			assert_true(v3_normalize(cases[i].pos, &s.scene.light.direction));
		} else
			s.scene.light.position = cases[i].light == 2 ? v3_add(cases[i].eye, cases[i].pos) : cases[i].pos;
		assert_true(build(&s, "plane", 320, 240, 0.4));
		check_sampling(&s, cases[i].what, &stretched);
		char ws[512] = "";
		for (int k = 0; k < s.res.warning_count; k++)
			snprintf(ws + strlen(ws), sizeof ws - strlen(ws), "%s%s", k ? "; " : "", s.res.warnings[k]);
		print_message("%-44s maps %d%d%d  %s\n", cases[i].what, s.res.maps[0].rendered, s.res.maps[1].rendered,
			      s.res.maps[s.res.map_count - 1].rendered, ws[0] ? ws : "no warning"); /* the fallback last */
		if (cases[i].warning && !strstr(ws, cases[i].warning))
			fail_msg("%s: expected a warning with \"%s\", got \"%s\"", cases[i].what, cases[i].warning, ws);
		uint64_t seed = i + 1;
		if (!strstr(ws, "150 degrees"))
			check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 40, cases[i].what);
		lx_meshes_free(&s.meshes);
	}
}

/* A frame whose floor map is skipped leaves nothing of the previous frame's matrix. */
static void no_stale_matrix(void **state)
{
	(void)state;
	struct setup s;
	memset(&s, 0, sizeof s);
	lx_scene_default(&s.scene);
	assert_true(build(&s, "plane", 320, 240, 0));
	assert_true(s.res.maps[0].rendered);
	lx_meshes_free(&s.meshes);
	s.scene.light.position = v3(1, 0, 1); /* on the floor */
	assert_true(build(&s, "plane", 320, 240, 0));
	assert_false(s.res.maps[0].rendered);
	mat4 id = m4_identity();
	assert_memory_equal(&s.res.maps[0].light_clip, &id, sizeof id);
	lx_meshes_free(&s.meshes);
}

/* A plane not in view gets no pass; a view without shadows gets none at all. */
static void only_what_the_scene_requires(void **state)
{
	(void)state;
	struct setup s;
	memset(&s, 0, sizeof s);
	lx_scene_default(&s.scene);
	s.scene.camera.eye = v3(0, 1.5, 4);
	s.scene.camera.at = v3(0, 0, 3); /* looking down at the floor: the wall is out of view */
	assert_true(build(&s, "plane", 320, 240, 0));
	struct lx_poly win;
	vec3 world[32];
	int nw;
	assert_false(lx_plane_visible(&s.frame.view, &s.scene.planes[1], &win, world, &nw));
	assert_false(s.res.maps[1].rendered);
	lx_meshes_free(&s.meshes);
	s.scene.camera.at = v3(0, 6, 20); /* looking away from the scene */
	s.scene.camera.eye = v3(0, 6, 10);
	assert_true(build(&s, "plane", 320, 240, 0));
	for (int m = 0; m < s.res.map_count; m++)
		assert_false(s.res.maps[m].rendered);
	lx_meshes_free(&s.meshes);
}

/* Casters wholly under a plane shadow none of it, though their images in the plane's light
 * view cover part of it: the table's top gets the same map with its legs as without
 * them, on every standard view and 40 random ones, the ball the one caster over the top
 * (before, on the default view, 125x30 lixels with them against 30x12: the legs' images
 * reached the top's corners). */
static void casters_under_a_plane_shadow_none_of_it(void **state)
{
	(void)state;
	uint64_t seed = 5;
	int tops = 0, views = 0;
	for (int k = 0; k < lx_config_count + 40; k++) {
		struct setup with, without;
		memset(&with, 0, sizeof with);
		lx_scene_table(&with.scene);
		assert_int_equal(with.scene.casters[5].shape, LX_SPHERE); /* after the slab and four legs */
		with.scene.caster_count = 6;
		if (k < lx_config_count)
			lx_config_apply(&lx_configs[k], &with.scene);
		else
			test_random_view(&with.scene, &seed, k % 4 == 0, 0.1);
		without = with;
		without.scene.casters[1] = without.scene.casters[5]; /* the slab and the ball */
		without.scene.caster_count = 2;
		double t = 0.25 * (k % 7);
		if (!build(&with, "plane", 320, 240, t))
			continue;
		assert_true(build(&without, "plane", 320, 240, t));
		const struct lx_shadow_map *a = &with.res.maps[0], *b = &without.res.maps[0]; /* map 0: the top */
		if (a->rendered != b->rendered || a->w != b->w || a->h != b->h)
			fail_msg("view %d: the top's map %dx%d (%s) with the legs, %dx%d (%s) without", k, a->w, a->h,
				 a->rendered ? "drawn" : "none", b->w, b->h, b->rendered ? "drawn" : "none");
		tops += a->rendered, views++;
		lx_meshes_free(&with.meshes);
		lx_meshes_free(&without.meshes);
	}
	assert_true(tops >= 10);
	printf("the table's top: the same map with its legs as without on %d views (%d with a map)\n", views, tops);
}

/* A caster reaching through a plane shadows it with its part on the light's side alone:
 * a cylinder standing on the floor through the table's top (its slab and legs left in)
 * gives the top the map a box of that part gives it, at the standard configurations' and
 * at 20 random points lights. Before, the outline of its part under the top, whose image
 * lies towards the light's foot, widened the top's map. */
static void a_caster_through_a_plane_counts_above_it(void **state)
{
	(void)state;
	uint64_t seed = 17;
	int compared = 0;
	for (int k = 0; k < lx_config_count + 20; k++) {
		struct setup through, above;
		memset(&through, 0, sizeof through);
		lx_scene_table(&through.scene);
		struct lx_caster *c = &through.scene.casters[5];
		*c = (struct lx_caster){.shape = LX_CYLINDER, .size = v3(0.15, 1.1, 0.15), .x = 0.3, .z = -0.2, .low = 0,
					.high = 0, .period = 1, .color = v3(0.3, 0.75, 0.35)};
		through.scene.caster_count = 6;
		if (k < lx_config_count)
			lx_config_apply(&lx_configs[k], &through.scene);
		else
			test_random_view(&through.scene, &seed, false, 0);
		above = through;
		if (!build(&through, "plane", 320, 240, 0))
			continue;
		int id = through.scene.plane_count + 5;
		vec3 lo = through.frame.bmin[id], hi = through.frame.bmax[id];
		assert_true(lo.y < 0.75 && hi.y > 0.75);
		above.scene.casters[5] = (struct lx_caster){.shape = LX_BOX, .size = v3(hi.x - lo.x, hi.y - 0.75, hi.z - lo.z),
							    .x = 0.5 * (lo.x + hi.x), .z = 0.5 * (lo.z + hi.z), .low = 0.75,
							    .high = 0.75, .period = 1};
		assert_true(build(&above, "plane", 320, 240, 0));
		const struct lx_shadow_map *a = &through.res.maps[0], *b = &above.res.maps[0]; /* map 0: the top */
		if (a->rendered != b->rendered || a->w != b->w || a->h != b->h)
			fail_msg("view %d: the top's map %dx%d (%s) with the cylinder through it, %dx%d (%s) with its part above",
				 k, a->w, a->h, a->rendered ? "drawn" : "none", b->w, b->h, b->rendered ? "drawn" : "none");
		compared += a->rendered;
		lx_meshes_free(&through.meshes);
		lx_meshes_free(&above.meshes);
	}
	assert_true(compared >= 10);
}

/* A plane whose casters' outlines span it only between their footprints, none of which
 * meets its visible part, gets no map: on random view 193 of seed 11 the table's top held
 * a 235x202 map no pixel read, with the budget its floor then lacked (0.0425% against
 * 0.0309%, uniform 0.1199%, at 1024x768). */
static void no_footprint_on_a_plane_no_map(void **state)
{
	(void)state;
	struct setup s;
	memset(&s, 0, sizeof s);
	lx_scene_table(&s.scene);
	s.scene.camera.eye = v3(0.161908, 3.84277, -0.628689);
	s.scene.camera.at = v3(-1.2215, 0.302362, -1.91952);
	s.scene.light.position = v3(3.54779, 3.55311, 4.60052);
	assert_true(build(&s, "plane", 1024, 768, 2.01146));
	assert_false(s.res.maps[0].rendered);
	assert_true(s.res.maps[1].rendered);
	lx_meshes_free(&s.meshes);
}

/* A plane served by one rectangle over its budget takes its footprints' bounds, not those
 * of the hull of every caster's outline, which also spans the space between them: on this
 * random view (tools/random-views.py, seed 1204, view 138) the floor's one map gave 0.73
 * lixels per pixel before (mismatch 0.0389% at 1024x768), a lixel per pixel now
 * (0.0150%). The density is the map's Jacobian on the plane at the window's centre. */
static void one_rectangle_shrinks_to_its_footprints(void **state)
{
	(void)state;
	struct setup s;
	memset(&s, 0, sizeof s);
	lx_scene_default(&s.scene);
	s.scene.camera.eye = v3(0.99693654358533035, 1.7408205060692403, 4.0625883661573834);
	s.scene.camera.at = v3(0.21584616961938297, 0.56157050782357876, -2.7935193704747867);
	s.scene.light.position = v3(-2.2089563387325684, 1.8057643959296985, 1.8776525972667386);
	assert_true(build(&s, "plane", 1024, 768, 0.55108901883926031));
	const struct lx_shadow_map *floor = &s.res.maps[0];
	assert_true(floor->rendered);
	int pieces = 0;
	for (int m = 0; m < s.res.map_count; m++) /* a plane's pieces carry its index */
		pieces += s.res.maps[m].rendered && s.res.maps[m].plane == 0;
	assert_int_equal(pieces, 1);
	mat3 h;
	double s_max, s_min;
	assert_true(lx_plane_homography(&s.frame, &s.atlas, floor, 0, &h));
	assert_true(lx_homography_jacobian(&h, 512, 200, &s_max, &s_min));
	printf("one floor map over its footprints: %.4f lixels per pixel\n", s_max * s_min);
	assert_true(s_max * s_min >= 1 - 1e-9);
	lx_meshes_free(&s.meshes);
}

/* A low light behind the table throws its legs' shadows past the eye: those casters are
 * bounded by their clipped footprints, not charted whole (caster_reach). Their footprints'
 * edges run along the shadows too, and tell the stretch which way the floor's lixels should
 * lie (chart_stretch): the floor, short of a lixel per pixel (0.58; 0.73 since its
 * footprints are cut in slabs), takes lixels a pixel apart along those shadows. Without them the model saw no edge and kept square lixels (random
 * view 243 of tools/random-views.py --seed 2026 at 1024x768: 0.2561% of the pixels
 * wrong against 0.1409% stretched; uniform 0.1409%). */
static void shadows_past_the_eye_stretch_the_map(void **state)
{
	(void)state;
	struct setup s;
	static const struct random_view v243 = {true, {-4.89512, 1.49231, -0.201789}, {0.841314, 0.372905, 0.390751},
						{5.18483, 1.18071, 4.09316}, 0.802724};
	random_view_scene(&s, &v243);
	assert_true(build(&s, "plane", 1024, 768, v243.time));
	const struct lx_shadow_map *fm = &s.res.maps[1]; /* the floor's own map: plane i's is map i */
	assert_true(fm->rendered && fm->plane == 1);
	printf("floor: %.3f lixels per pixel, stretched %.3f\n", fm->lixel_scale * fm->lixel_scale, fm->lixel_stretch);
	assert_true(fm->lixel_scale < 1);
	assert_true(fabs(fm->lixel_stretch - 1) > 0.1);
	lx_meshes_free(&s.meshes);
}

/* The table seen from above under a low light: its shadow on the floor, seen in
 * perspective, is a wedge, and the floor's one rectangle around it held 595,000 pixels
 * for its 122,500 lixels (0.21 lixels per pixel; random view 39 of tools/random-views.py
 * --seed 3031 at 1024x768: 0.1256% of the pixels wrong, uniform 0.0820%). Cut in slabs
 * (slab_feet), the footprints leave the pieces less area: the floor denser, the top at a
 * lixel per pixel, and every shadow still in a map that serves it. */
/* How many pieces plane `plane`'s map is in, their lixels (*lixels, where asked) and
 * their density (*lpp); each piece checked to fit its region's budget (cut_to_regions). */
static int plane_pieces_of(const struct setup *s, int plane, double *lpp, long *lixels)
{
	int n = 0;
	long total = 0;
	for (int m = 0; m < s->res.map_count; m++) {
		const struct lx_shadow_map *mp = &s->res.maps[m];
		if (!mp->rendered || mp->plane != plane) /* a plane's pieces carry its index */
			continue;
		assert_true((long)mp->w * mp->h <= s->atlas.regions[mp->region].budget);
		n++, total += (long)mp->w * mp->h, *lpp = mp->lixel_scale * mp->lixel_scale; /* one scale for all */
	}
	if (lixels)
		*lixels = total;
	return n;
}

static void wedge_footprints_cut_in_slabs(void **state)
{
	(void)state;
	double lpp[2][2] = {{0, 0}, {0, 0}};
	int pieces[2][2];
	for (int slabbed = 0; slabbed < 2; slabbed++) {
		struct setup s;
		static const struct random_view v39 = {true, {0.561439, 3.15733, 1.48349}, {-0.670806, 0.371238, -1.61821},
						       {3.0832, 1.54921, 2.42205}, 2.75631};
		random_view_scene(&s, &v39);
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		o.plane_unslabbed = !slabbed;
		assert_true(build_with(&s, "plane", 1024, 768, v39.time, &o));
		pieces[slabbed][0] = plane_pieces_of(&s, 1, &lpp[slabbed][0], NULL); /* the floor */
		pieces[slabbed][1] = plane_pieces_of(&s, 0, &lpp[slabbed][1], NULL); /* the table top */
		printf("%s: floor %d pieces at %.3f lixels per pixel, top %d at %.3f\n", slabbed ? "slabbed" : "unslabbed",
		       pieces[slabbed][0], lpp[slabbed][0], pieces[slabbed][1], lpp[slabbed][1]);
		if (slabbed) {
			uint64_t seed = 3;
			assert_true(check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 400, "slabs") > 1000);
		}
		lx_meshes_free(&s.meshes);
	}
	assert_true(pieces[1][0] > 1 && lpp[1][0] > 1.3 * lpp[0][0]);
	assert_true(lpp[1][1] > lpp[0][1]);
}

/* A floor that takes the table top's budget (245,000 lixels) must keep each of its
 * pieces within a region's 122,500 (cut_to_regions). Held to that by a bound on any
 * stretch's lixels, random view 147 of tools/random-views.py --seed 2026 at 1920x1080
 * kept the floor at 0.977 lixels per pixel (0.0119% of the pixels wrong; 0.0001% at one,
 * uniform 0.0620%); with its four pieces taken and the largest over its region, random
 * view 65 of --seed 909 spent 126,139 of the lixels (0.59 lixels per pixel, 0.0186%;
 * two pieces made one and the largest cut in two: 214,603, 0.76, 0.0144%). And the
 * bound cut pieces the fit did not need: random view 14 of --seed 909 (the default scene)
 * took four pieces where two hold its lixels within their regions, for the same density. */
static void pieces_spend_the_budget_within_their_regions(void **state)
{
	(void)state;
	static const struct random_view views[3] = {
		{true, {-4.75144, 3.39811, 3.28221}, {1.4433, 0.0178003, -0.0770384}, {2.58052, 1.80475, 3.20943}, 0.771709},
		{true, {-0.155278, 4.36617, 1.47463}, {-0.763035, 1.08169, -2.95323}, {1.66175, 3.27591, 5.95594}, 2.1828},
		{false, {2.67254, 3.46226, 2.20226}, {-0.484712, 0.303761, -0.915184}, {4.50581, 2.95616, -3.58118}, 3.95995}};
	for (int k = 0; k < 3; k++) {
		struct setup s;
		random_view_scene(&s, &views[k]);
		assert_true(build(&s, "plane", 1920, 1080, views[k].time));
		double lpp = 0;
		long lixels;
		int pieces = plane_pieces_of(&s, views[k].table ? 1 : 0, &lpp, &lixels); /* the floor */
		printf("view %d: the floor's %d pieces hold %ld lixels at %.3f lixels per pixel\n", k, pieces, lixels, lpp);
		if (k == 0)
			assert_true(lpp >= 1 - 1e-9);
		else if (k == 1)
			assert_true(lixels > 200000);
		else
			assert_true(pieces == 2 && lpp >= 1 - 1e-9);
		uint64_t seed = 5;
		long pairs = check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 200, "pieces");
		printf("view %d: %ld caster/receiver pairs covered\n", k, pairs);
		assert_true(pairs > 100);
		lx_meshes_free(&s.meshes);
	}
}

/* Every shadow in a map that serves it on random views large enough that planes fall
 * short of their budgets and footprints are cut in slabs (counted: the views whose maps
 * differ from the unslabbed ones). */
static void slabs_keep_every_shadow(void **state)
{
	(void)state;
	uint64_t seed = 2026;
	long total = 0;
	int slabbed = 0;
	for (int k = 0; k < 100; k++) {
		struct setup s, u;
		memset(&s, 0, sizeof s);
		memset(&u, 0, sizeof u);
		k % 2 ? lx_scene_table(&s.scene) : lx_scene_default(&s.scene);
		test_random_view(&s.scene, &seed, false, 0.1);
		u.scene = s.scene;
		double t = test_rand(&seed) * 5;
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		o.plane_unslabbed = true;
		bool built = build(&s, "plane", 1600, 1200, t), plain = build_with(&u, "plane", 1600, 1200, t, &o);
		assert_true(built == plain);
		if (built) {
			bool differ = false;
			for (int m = 0; m < s.res.map_count; m++)
				differ |= s.res.maps[m].rendered != u.res.maps[m].rendered || s.res.maps[m].w != u.res.maps[m].w ||
					  s.res.maps[m].h != u.res.maps[m].h;
			slabbed += differ;
			char what[64];
			snprintf(what, sizeof what, "random view %d", k);
			total += check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 60, what);
		}
		lx_meshes_free(&s.meshes);
		lx_meshes_free(&u.meshes);
	}
	print_message("%ld caster/receiver pairs covered; slabs on %d of 100 views\n", total, slabbed);
	assert_true(total > 5000);
	assert_true(slabbed >= 5);
}

/* The miner's lamp (the light at the eye, lx_shadows_hidden) leaves every method without a
 * map and without a front to test (lx_plane_covers_none): the table's slab would make the
 * main pass test its fronts over the floor and the table top, for no shadow in sight.
 * 5 cm above the eye the slab's fronts are tested again. */
static void no_test_for_shadows_hidden(void **state)
{
	(void)state;
	for (int table = 0; table < 2; table++)
		for (int lift = 0; lift < 2; lift++)
			for (int i = 0; i < lx_shadow_method_count(); i++) {
				const char *name = lx_shadow_method_at(i)->name;
				struct setup s;
				memset(&s, 0, sizeof s);
				table ? lx_scene_table(&s.scene) : lx_scene_default(&s.scene);
				lx_config_apply(lx_config_find("miner"), &s.scene);
				s.scene.light.position = v3_add(s.scene.camera.eye, v3(0, lift ? 0.05 : 0, 0));
				assert_true(build(&s, name, 320, 240, 0));
				assert_true(lx_shadows_hidden(&s.frame) == !lift);
				int tested = 0;
				for (int id = 0; id < s.frame.object_count; id++)
					tested += lx_plane_cover_count(&s.res.covers, id);
				if (!lift) {
					for (int m = 0; m < s.res.map_count; m++)
						assert_false(s.res.maps[m].rendered);
					if (s.res.covers.count != 0 || tested != 0)
						fail_msg("%s, %s scene, the light at the eye: %d fronts, %d tested", name,
							 table ? "table" : "default", s.res.covers.count, tested);
				} else if (table && strcmp(name, "none") != 0 && tested == 0)
					fail_msg("%s, table scene, the light 5 cm above the eye: no front tested", name);
				lx_meshes_free(&s.meshes);
			}
}

/* Where caster id's box centre lies in map m's clip square (x, y), false behind its light. */
static bool box_centre_in_map(const struct setup *s, int m, int id, double *x, double *y)
{
	vec4 c = m4_mul_point(&s->res.maps[m].light_clip, v3_scale(v3_add(s->frame.bmin[id], s->frame.bmax[id]), 0.5));
	if (!(c.w > 0))
		return false;
	*x = c.x / c.w, *y = c.y / c.w;
	return true;
}

/* The fallback's lixels go only where a caster may be shadowed by another: the table
 * seen from close to the floor, the ball and the cone float over it in view, in no other
 * object's shadow (their own lit faces need no lixel), so the fallback's square leaves
 * them out and holds the legs, which the slab shadows; and still holds every shadow. */
static void fallback_serves_only_what_needs_it(void **state)
{
	(void)state;
	struct setup s;
	memset(&s, 0, sizeof s);
	lx_scene_table(&s.scene);
	lx_config_apply(lx_config_find("floor-close"), &s.scene);
	assert_true(build(&s, "plane", 1024, 1024, 0));
	int np = s.scene.plane_count, fb = s.res.map_count - 1, left_out = 0, held = 0; /* the fallback last */
	assert_true(s.res.maps[fb].rendered);
	for (int id = np; id < s.frame.object_count; id++) {
		enum lx_shape shape = s.scene.casters[id - np].shape;
		double x, y;
		bool inside = box_centre_in_map(&s, fb, id, &x, &y) && fabs(x) <= 1 && fabs(y) <= 1;
		if (shape == LX_SPHERE || shape == LX_CONE) {
			if (inside)
				fail_msg("the %s's centre lies in the fallback at (%g, %g)", lx_shape_name(shape), x, y);
			left_out++;
		} else if (shape == LX_BOX && s.frame.bmax[id].y < 0.71) { /* a leg */
			if (!inside)
				fail_msg("leg %d's centre lies outside the fallback at (%g, %g)", id, x, y);
			held++;
		}
	}
	assert_int_equal(left_out, 2);
	assert_int_equal(held, 4);
	uint64_t seed = 5;
	long pairs = check_coverage(&s.frame, &s.res, np, &seed, 200, "table, floor-close");
	print_message("table, floor-close: the ball and the cone left out of the fallback, the 4 legs in; %ld pairs covered\n",
		      pairs);
	assert_true(pairs > 500);
	lx_meshes_free(&s.meshes);
}

/* Random view 70 of the default scene (tools/random-views.py, seed 13): the eye over the
 * green cylinder, the light just beside the sphere, whose image on the light's chart
 * covers the cylinder's. Yet no ray from the light to the sphere passes the cylinder
 * (both the light and the sphere lie on one side of it along x), and no other caster
 * reaches the sphere: the fallback leaves the sphere out and spends its 128x128 on the
 * cylinder, which the sphere shadows, and of it only what the view holds. With the
 * sphere in, the cylinder's shadowed top read the fallback at about 36 pixels per lixel. */
static void fallback_leaves_out_what_nothing_reaches(void **state)
{
	(void)state;
	static const struct random_view v70 = {false, {-0.611149, 2.02308, 0.333994}, {-0.646251, 1.00542, 0.85989},
					       {-1.50432, 2.72382, -0.628421}, 4.31861};
	struct setup s;
	struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
	random_view_scene(&s, &v70);
	assert_true(build_with(&s, "plane", 1024, 768, v70.time, &o));
	int np = s.scene.plane_count, fb = s.res.map_count - 1; /* the fallback last */
	assert_true(s.res.maps[fb].rendered);
	int sphere = -1, cylinder = -1;
	for (int id = np; id < s.frame.object_count; id++) {
		enum lx_shape shape = s.scene.casters[id - np].shape;
		sphere = shape == LX_SPHERE ? id : sphere;
		cylinder = shape == LX_CYLINDER ? id : cylinder;
	}
	assert_true(sphere >= 0 && cylinder >= 0);
	double x, y;
	if (box_centre_in_map(&s, fb, sphere, &x, &y) && fabs(x) <= 1 && fabs(y) <= 1)
		fail_msg("the sphere's centre lies in the fallback at (%g, %g)", x, y);
	/* the cylinder's width in the fallback, in lixels: at least a tenth of the map */
	double lo = INFINITY, hi = -INFINITY;
	for (int k = 0; k < 8; k++) {
		vec4 c = m4_mul_point(&s.res.maps[fb].light_clip, v3_box_corner(s.frame.bmin[cylinder], s.frame.bmax[cylinder], k));
		assert_true(c.w > 0);
		lo = fmin(lo, c.x / c.w), hi = fmax(hi, c.x / c.w);
	}
	int side = s.res.maps[fb].w;
	uint64_t seed = 7;
	long pairs = check_coverage(&s.frame, &s.res, np, &seed, 2000, "view 70");
	print_message("view 70: the sphere left out of the fallback, the cylinder's box %.0f lixels wide in its %d; %ld pairs covered\n",
		      (hi - lo) / 2 * side, side, pairs);
	/* the fallback keeps to the part of the cylinder the view holds: its box now spans
	 * 1.7 times the map (1.28 when the fallback took the whole cylinder) */
	assert_true((hi - lo) / 2 > 1.5);
	assert_true(pairs > 500);
	lx_meshes_free(&s.meshes);
}

/* Random view 132 of the default scene (tools/random-views.py, seed 13): the sphere,
 * near the eye, hides most of its own shadow on the floor. The floor's map leaves out
 * what the casters hide (take_hidden): a lixel per pixel on what is left, within the
 * floor's own budget, where the whole footprints gave it 0.53 lixels per pixel (stretched
 * 1.89 to 1); every shadow on the floor the eye sees is still in it. */
static void hidden_floor_takes_no_lixels(void **state)
{
	(void)state;
	static const struct random_view v132 = {false, {-2.78897, 3.07978, 1.92653}, {-0.403308, 0.0241855, 0.946119},
						{-0.174909, 2.25104, 2.6265}, 0.455596};
	struct setup s;
	struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
	random_view_scene(&s, &v132);
	assert_true(build_with(&s, "plane", 1024, 768, v132.time, &o));
	long lixels = 0;
	int floor_maps = 0;
	for (int m = 0; m < s.res.map_count; m++) {
		const struct lx_shadow_map *map = &s.res.maps[m];
		if (!map->rendered || map->plane != 0) /* the floor */
			continue;
		floor_maps++;
		lixels += (long)map->w * map->h;
		assert_true(map->lixel_scale == 1 && map->lixel_stretch == 1);
	}
	uint64_t seed = 11;
	coverage_hidden = 0;
	long pairs = check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 2000, "view 132");
	print_message("view 132: the floor in %d map%s of %ld lixels at a lixel per pixel; %ld pairs covered, %ld receivers "
		      "hidden from the eye\n", floor_maps, floor_maps > 1 ? "s" : "", lixels, pairs, coverage_hidden);
	assert_true(floor_maps >= 1 && lixels <= 350L * 350);
	assert_true(pairs > 500 && coverage_hidden > 0);
	lx_meshes_free(&s.meshes);
}

/* The flat boxes' faces the maps leave out (lx_slab_faces_left_out): on the table the
 * slab's underside, as a plane in the slab's own space (its bottom, the normal towards
 * the light above), and with it the whole slab, whose pair of fronts every object under
 * it tests; with the light under the table top's plane, its top (the slab's own underside
 * then the pair's top: no plane lies under it); and none where a third front over one
 * object leaves the slab's out of some object's tests (a third shelf over
 * two-shelves.scene: the floor tests two fronts only). */
static void faces_left_out(struct setup *s, vec4 *front, bool *has, bool *whole, struct lx_plane_covers *cv)
{
	assert_true(build(s, "none", 320, 240, 0)); /* no map: no front tested, no face left out */
	for (int id = 0; id < s->frame.object_count; id++)
		assert_true(s->res.covers.of[id][0] == -1 && !s->res.covers.paired[id] && !s->res.slab_out[id] &&
			    !s->res.slab_face_out[id]);
	assert_int_equal(s->res.covers.count, 0);
	lx_meshes_free(&s->meshes);
	assert_true(build(s, "uniform", 320, 240, 0));
	lx_plane_covers(&s->frame, cv);
	lx_slab_faces_left_out(&s->frame, cv, front, has, whole);
	for (int id = 0; id < s->frame.object_count; id++) /* what lx_shadow_method_frame keeps */
		assert_true(s->res.slab_out[id] == whole[id] && s->res.slab_face_out[id] == has[id]);
	assert_int_equal(s->res.covers.count, cv->count);
}

static void slab_underside_left_out_of_maps(void **state)
{
	(void)state;
	for (int below = 0; below < 2; below++) {
		struct setup s;
		memset(&s, 0, sizeof s);
		lx_scene_table(&s.scene);
		if (below)
			s.scene.light.position = v3(2.0, 0.5, 2.5);
		vec4 front[LX_MAX_PLANES + LX_MAX_CASTERS];
		bool has[LX_MAX_PLANES + LX_MAX_CASTERS], whole[LX_MAX_PLANES + LX_MAX_CASTERS];
		struct lx_plane_covers cv;
		faces_left_out(&s, front, has, whole, &cv);
		int slab = s.scene.plane_count;
		for (int id = 0; id < s.frame.object_count; id++) {
			assert_int_equal(has[id], id == slab);
			assert_int_equal(whole[id], id == slab);
		}
		/* the face's plane holds the box's bottom (top) corners, in the slab's own space */
		const struct lx_mesh *m = &s.meshes.mesh[slab];
		double y = below ? m->bmax.y : m->bmin.y;
		assert_near(front[slab].x, 0, 1e-12);
		assert_near(front[slab].z, 0, 1e-12);
		assert_near(front[slab].y, below ? -1 : 1, 1e-12);
		assert_near(front[slab].y * y + front[slab].w, 0, 1e-9);
		/* the pair: above, the table top's plane (front 0) lies on the slab; below, the
		 * slab's own underside, a front after the bottoms */
		assert_int_equal(cv.slabs, 1);
		assert_int_equal(cv.count, s.scene.plane_count + 1 + below);
		assert_int_equal(cv.top[slab], below ? s.scene.plane_count + 1 : 0);
		lx_meshes_free(&s.meshes);
	}
	/* the low light (x = 6 m, 1.6 m up): the two legs on its side see it through the
	 * slab's bottom and thin side only, not its top, yet test the pair (their rays may
	 * pass through the box), so the slab still leaves the maps */
	struct setup s;
	memset(&s, 0, sizeof s);
	lx_scene_table(&s.scene);
	lx_config_apply(lx_config_find("low"), &s.scene);
	vec4 front[LX_MAX_PLANES + LX_MAX_CASTERS];
	bool has[LX_MAX_PLANES + LX_MAX_CASTERS], whole[LX_MAX_PLANES + LX_MAX_CASTERS];
	struct lx_plane_covers cv;
	faces_left_out(&s, front, has, whole, &cv);
	int np = s.scene.plane_count;
	for (int leg = np + 1; leg <= np + 4; leg++)
		assert_true(cv.paired[leg] && cv.of[leg][0] == 0 && cv.of[leg][1] == np);
	assert_true(whole[np]);
	lx_meshes_free(&s.meshes);
	memset(&s, 0, sizeof s);
	test_scene_load("two-shelves.scene", &s.scene);
	s.scene.casters[s.scene.caster_count++] = (struct lx_caster){.shape = LX_BOX, .size = v3(1.6, 0.04, 1.0),
		.x = 0, .z = -0.1, .low = 1.9, .high = 1.9, .period = 1, .color = v3(0.5, 0.5, 0.5)};
	faces_left_out(&s, front, has, whole, &cv);
	/* the board above the shelves has a bottom front, and a top one (no plane lies on it) */
	int bottom = s.scene.plane_count;
	assert_int_equal(cv.slabs, 1);
	assert_int_equal(cv.count, s.scene.plane_count + 2);
	assert_int_equal(cv.top[bottom], bottom + 1);
	assert_true(cv.lit[bottom] && !lx_plane_cover_complete(&s.frame, &cv, bottom));
	for (int id = 0; id < s.frame.object_count; id++)
		assert_false(has[id] || whole[id]); /* so its faces stay in the maps */
	lx_meshes_free(&s.meshes);
}

static void polygon_difference(void **state)
{
	(void)state;
	struct lx_poly sq = {4, {{0, 0}, {2, 0}, {2, 2}, {0, 2}}}, left = {4, {{-1, -1}, {1, -1}, {1, 3}, {-1, 3}}},
		       right = {4, {{1, -1}, {3, -1}, {3, 3}, {1, 3}}}, none = {0}, out;
	lx_poly_hull_of_difference(&sq, &left, &right, &out);
	assert_int_equal(out.n, 0); /* the halves cover the square: only their shared edge remains */
	lx_poly_hull_of_difference(&sq, &left, &none, &out);
	assert_near(fabs(lx_poly_area(&out)), 2, 1e-9);
	struct lx_poly hole = {4, {{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}}};
	lx_poly_hull_of_difference(&sq, &hole, &none, &out);
	assert_near(fabs(lx_poly_area(&out)), 4, 1e-9); /* a hole does not shrink the hull */
	lx_poly_intersect(&sq, &hole, &out);
	assert_near(fabs(lx_poly_area(&out)), 1, 1e-12);
}

/* A half-plane that holds all of a polygon keeps it as it is, but for a last corner that
 * repeats the first; one that holds none of it leaves nothing; one through it, a part. */
static void halfplane_keeps_all_none_or_part(void **state)
{
	(void)state;
	struct lx_poly sq = {4, {{0, 0}, {2, 0}, {2, 2}, {0, 2}}}, out;
	struct lx_poly closed = {5, {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 0}}};
	lx_poly_clip_halfplane(&closed, 1, 0, 1, &out); /* x >= -1 */
	assert_int_equal(out.n, 4);
	assert_memory_equal(out.v, sq.v, 4 * sizeof(vec2));
	lx_poly_clip_halfplane(&sq, 0, 1, 0, &out); /* y >= 0: an edge on the line, all kept */
	assert_int_equal(out.n, 4);
	assert_memory_equal(out.v, sq.v, 4 * sizeof(vec2));
	lx_poly_clip_halfplane(&sq, 1, 0, -3, &out); /* x >= 3 */
	assert_int_equal(out.n, 0);
	lx_poly_clip_halfplane(&sq, 1, 0, -1, &out); /* x >= 1: half of it */
	assert_near(fabs(lx_poly_area(&out)), 2, 1e-12);
}

/* Whether every point lies in the convex counter-clockwise polygon p (on its edges counts). */
static bool holds_all(const struct lx_poly *p, const vec2 *pts, int n)
{
	for (int k = 0; k < n; k++)
		for (int i = 0; i < p->n; i++) {
			vec2 a = p->v[i], b = p->v[(i + 1) % p->n];
			if ((b.x - a.x) * (pts[k].y - a.y) - (b.y - a.y) * (pts[k].x - a.x) < -1e-9)
				return false;
		}
	return true;
}

/* lx_poly_inset, which moves a front's shadow in from its edges (method_plane.c,
 * covered_part): over random convex polygons every corner of the inset lies inside by
 * the margin; a rotated square inset past its middle is empty; in place, a triangle. */
static void polygon_inset(void **state)
{
	(void)state;
	uint64_t seed = 17;
	int kept = 0;
	for (int t = 0; t < 500; t++) {
		vec2 pts[12];
		int n = 3 + (int)(test_rand(&seed) * 9);
		for (int k = 0; k < n; k++)
			pts[k] = (vec2){400 * test_rand(&seed) - 200, 300 * test_rand(&seed)};
		struct lx_poly p, in;
		lx_poly_hull(pts, n, &p);
		if (p.n < 3)
			continue;
		double d = 5 * test_rand(&seed);
		lx_poly_inset(&p, d, &in);
		kept += in.n >= 3;
		for (int k = 0; k < in.n; k++)
			for (int i = 0; i < p.n; i++) {
				vec2 a = p.v[i], b = p.v[(i + 1) % p.n];
				double len = hypot(b.x - a.x, b.y - a.y);
				assert_true(((b.x - a.x) * (in.v[k].y - a.y) - (b.y - a.y) * (in.v[k].x - a.x)) / len > d - 1e-6);
			}
	}
	assert_true(kept > 400);
	struct lx_poly tri = {3, {{0, 0}, {4, 0}, {0, 4}}}, diamond = {4, {{0, -1}, {1, 0}, {0, 1}, {-1, 0}}}, out;
	lx_poly_inset(&diamond, 0.8, &out); /* the inscribed circle's radius is 0.707 */
	assert_int_equal(out.n, 0);
	lx_poly_inset(&tri, 0.5, &tri); /* in place */
	assert_int_equal(tri.n, 3);
	assert_near(tri.v[0].x, 0.5, 1e-9);
	assert_near(tri.v[0].y, 0.5, 1e-9);
}

/* lx_poly_bounds_outside gives the bounds of HULL(a - b), along turned axes, that
 * lx_poly_hull_of_difference's hull gives; lx_poly_shrink keeps within the inset. */
static void polygon_bounds_outside_and_shrink(void **state)
{
	(void)state;
	uint64_t seed = 23;
	int compared = 0, empty = 0, shrunk = 0;
	for (int t = 0; t < 2000; t++) {
		vec2 pa[10], pb[10];
		int na = 3 + (int)(test_rand(&seed) * 7), nb = 3 + (int)(test_rand(&seed) * 7);
		for (int k = 0; k < na; k++)
			pa[k] = (vec2){100 * test_rand(&seed), 100 * test_rand(&seed)};
		double cx = 100 * test_rand(&seed), cy = 100 * test_rand(&seed), r = 150 * test_rand(&seed);
		for (int k = 0; k < nb; k++)
			pb[k] = (vec2){cx + r * (2 * test_rand(&seed) - 1), cy + r * (2 * test_rand(&seed) - 1)};
		struct lx_poly a, b, diff;
		lx_poly_hull(pa, na, &a);
		lx_poly_hull(pb, nb, &b);
		if (a.n < 3 || b.n < 3)
			continue;
		double ang = 2 * M_PI * test_rand(&seed), out[4];
		vec2 ex = {cos(ang), sin(ang)}, ey = {-sin(ang), cos(ang)};
		bool some = lx_poly_bounds_outside(&a, &b, ex, ey, out);
		lx_poly_hull_of_difference(&a, &b, NULL, &diff);
		if (diff.n < 3) { /* b covers a, or what is left has no area: at most a sliver's bounds */
			empty++;
			assert_true(!some || (out[2] - out[0]) * (out[3] - out[1]) < 1e-6 * fabs(lx_poly_area(&a)) + 1e-9 ||
				    fabs(lx_poly_area(&diff)) < 1e-9);
			continue;
		}
		assert_true(some);
		double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
		for (int k = 0; k < diff.n; k++) {
			double u = ex.x * diff.v[k].x + ex.y * diff.v[k].y, v = ey.x * diff.v[k].x + ey.y * diff.v[k].y;
			lo[0] = fmin(lo[0], u), lo[1] = fmin(lo[1], v), hi[0] = fmax(hi[0], u), hi[1] = fmax(hi[1], v);
		}
		assert_near(out[0], lo[0], 1e-6);
		assert_near(out[1], lo[1], 1e-6);
		assert_near(out[2], hi[0], 1e-6);
		assert_near(out[3], hi[1], 1e-6);
		compared++;
		/* shrink: every vertex at least d inside every edge of b */
		struct lx_poly in;
		double d = 3 * test_rand(&seed);
		lx_poly_shrink(&b, d, &in);
		shrunk += in.n >= 3;
		for (int k = 0; k < in.n; k++)
			for (int i = 0; i < b.n; i++) {
				vec2 u = b.v[i], w = b.v[(i + 1) % b.n];
				double len = hypot(w.x - u.x, w.y - u.y);
				assert_true(((w.x - u.x) * (in.v[k].y - u.y) - (w.y - u.y) * (in.v[k].x - u.x)) / len >= d - 1e-9);
			}
	}
	print_message("bounds outside: %d pairs against the hull of the difference, %d with nothing left; %d shrunk\n",
		      compared, empty, shrunk);
	assert_true(compared > 1000 && empty > 20 && shrunk > 800);
	struct lx_poly sq = {4, {{0, 0}, {2, 0}, {2, 2}, {0, 2}}}, left = {4, {{-1, -1}, {1, -1}, {1, 3}, {-1, 3}}};
	double out[4];
	assert_true(lx_poly_bounds_outside(&sq, &left, (vec2){1, 0}, (vec2){0, 1}, out));
	assert_near(out[0], 1, 1e-12); /* the square's right half */
	assert_near(out[2], 2, 1e-12);
	assert_near(out[1], 0, 1e-12);
	assert_near(out[3], 2, 1e-12);
	struct lx_poly all = {4, {{-1, -1}, {3, -1}, {3, 3}, {-1, 3}}};
	assert_false(lx_poly_bounds_outside(&sq, &all, (vec2){1, 0}, (vec2){0, 1}, out));
}

static void polygon_edges_inside(void **state)
{
	(void)state;
	struct lx_poly big = {4, {{-1, -1}, {3, -1}, {3, 3}, {-1, 3}}}, square = {4, {{0, 0}, {2, 0}, {2, 2}, {0, 2}}};
	struct lx_poly strip = {4, {{0, 0}, {10, 0}, {10, 1}, {0, 1}}}, right = {4, {{5, -5}, {20, -5}, {20, 5}, {5, 5}}};
	struct lx_poly cw = {4, {{5, -5}, {5, 5}, {20, 5}, {20, -5}}}, far = {3, {{30, 0}, {40, 0}, {30, 9}}};
	struct lx_poly diamond = {4, {{0, -1}, {1, 0}, {0, 1}, {-1, 0}}};
	double dx, dy;
	lx_poly_edges_inside(&square, &big, &dx, &dy); /* all inside */
	assert_true(fabs(dx - 4) < 1e-12 && fabs(dy - 4) < 1e-12);
	lx_poly_edges_inside(&strip, &right, &dx, &dy); /* the long edges from x = 5 on, the right end */
	assert_true(fabs(dx - 10) < 1e-12 && fabs(dy - 1) < 1e-12);
	lx_poly_edges_inside(&strip, &cw, &dx, &dy); /* the same, clockwise */
	assert_true(fabs(dx - 10) < 1e-12 && fabs(dy - 1) < 1e-12);
	lx_poly_edges_inside(&strip, &far, &dx, &dy); /* apart */
	assert_true(dx == 0 && dy == 0);
	lx_poly_edges_inside(&diamond, &big, &dx, &dy); /* diagonal edges count along both */
	assert_true(fabs(dx - 4) < 1e-12 && fabs(dy - 4) < 1e-12);
	struct lx_poly empty = {0};
	lx_poly_edges_inside(&square, &empty, &dx, &dy);
	assert_true(dx == 0 && dy == 0);
}

/* Where a point of plane `plane` lands in that plane's map's lixels (a piece's or the
 * map's): (u, v) in lixels of its atlas region, or false when no rendered map of the
 * plane serves it. */
static bool plane_lixel(const struct setup *s, int plane, vec3 p, double *u, double *v)
{
	for (int m = 0; m < s->res.map_count; m++) {
		const struct lx_shadow_map *map = &s->res.maps[m];
		if (!map->rendered || map->plane != plane)
			continue;
		vec4 c = m4_mul_point(&map->light_clip, p);
		double x = c.x / c.w, y = c.y / c.w;
		if (x < map->bounds[0] || x > map->bounds[2] || y < map->bounds[1] || y > map->bounds[3])
			continue;
		const struct lx_region *r = &s->atlas.regions[map->region];
		*u = (x + 1) / 2 * r->w, *v = (y + 1) / 2 * r->h;
		return true;
	}
	return false;
}

/* A caster whose shadow passes the eye (the light facing the camera, or near the wall) no
 * longer makes a plane's whole visible part wanted: its footprint clipped to the near
 * plane bounds the map's pieces. Under the low light the cylinder straddles the light's
 * level as seen from the wall: its shadow there runs to the wall's horizon, and is
 * bounded where it falls on the wall's parallelogram (straddling_reach). With the light
 * inside the box's bounds nothing bounds its shadow, and the whole visible floor stays
 * wanted. Counted over the plane's pixel centres in view at 1024x768 (hidden by a caster
 * or not, alike); every_shadow_is_covered and the sweep's random lights check that the
 * bounded maps still hold every shadow. */
static void clipped_footprints_bound_the_planes(void **state)
{
	(void)state;
	static const struct {
		const char *config; /* NULL: the light inside the box's bounds */
		int plane;
		bool bounded;
	} cases[] = {{"facing", 0, true}, {"near-wall", 0, true}, {"low", 0, true}, {"low", 1, true}, {NULL, 0, false}};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct setup s;
		memset(&s, 0, sizeof s);
		lx_scene_default(&s.scene);
		if (cases[i].config)
			lx_config_apply(lx_config_find(cases[i].config), &s.scene);
		else { /* the box's centre at time 0 */
			assert_true(build(&s, "plane", 1024, 768, 0));
			int box = s.scene.plane_count + 1;
			s.scene.light.position = v3_scale(v3_add(s.frame.bmin[box], s.frame.bmax[box]), 0.5);
			lx_meshes_free(&s.meshes);
		}
		assert_true(build(&s, "plane", 1024, 768, 0));
		const struct lx_plane *P = &s.scene.planes[cases[i].plane];
		vec4 eq = lx_plane_equation(P);
		long seen = 0, served = 0;
		for (int y = 0; y < 768; y++)
			for (int x = 0; x < 1024; x++) {
				vec3 g;
				double t, u, v;
				if (!lx_window_on_plane(&s.frame.view, eq, x + 0.5, y + 0.5, &g, &t) || !(t > 0 && t < 1) ||
				    !lx_plane_contains(P, g))
					continue;
				seen++;
				served += plane_lixel(&s, cases[i].plane, g, &u, &v);
			}
		print_message("%-10s %-5s pixels %ld, in its map's pieces %ld\n", cases[i].config ? cases[i].config : "in the box",
			      P->name, seen, served);
		assert_true(seen > 10000);
		if (cases[i].bounded)
			assert_true(served < 0.9 * seen);
		else
			assert_true(served == seen);
		lx_meshes_free(&s.meshes);
	}
}

/* Points repeated but for rounding (a flat box's corners come in pairs; a sphere's
 * outline sends two points down each ray) make no edge of length about 0 in the hull:
 * such an edge, pointing anywhere, once made a clip against the hull keep 21 of a
 * plane's 96,000 square pixels, and the cone's shadow on the wall went missing (0.285%
 * of a random view). */
static void polygon_hull_of_repeated_points(void **state)
{
	(void)state;
	enum { N = 8 };
	vec2 pts[2 * N];
	for (int k = 0; k < N; k++) { /* an octagon, every point twice, once off by a rounding */
		pts[k] = (vec2){100 + 40 * cos(2 * M_PI * k / N), -50 + 40 * sin(2 * M_PI * k / N)};
		pts[2 * N - 1 - k] = (vec2){pts[k].x * (1 + 3e-16 * (k % 3 - 1)), pts[k].y * (1 - 4e-16 * (k % 2))};
	}
	struct lx_poly h, win = {4, {{0, -200}, {300, -200}, {300, 200}, {0, 200}}}, in;
	assert_true(lx_poly_hull(pts, 2 * N, &h));
	assert_int_equal(h.n, N);
	for (int k = 0; k < h.n; k++) { /* no short edge, every corner turning the same way */
		vec2 a = h.v[k], b = h.v[(k + 1) % h.n], c = h.v[(k + 2) % h.n];
		assert_true(fabs(a.x - b.x) + fabs(a.y - b.y) > 1);
		assert_true((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) > 0);
	}
	lx_poly_intersect(&win, &h, &in);
	assert_true(fabs(fabs(lx_poly_area(&in)) - fabs(lx_poly_area(&h))) < 1e-9 * fabs(lx_poly_area(&h)));
	vec2 flat[8] = {{0, 0}, {0, 0}, {1, 0}, {1, 0}, {1, 1}, {1, 1}, {0, 1}, {0, 1}}; /* a flat box's corners */
	assert_true(lx_poly_hull(flat, 8, &h));
	assert_int_equal(h.n, 4);
	assert_true(fabs(fabs(lx_poly_area(&h)) - 1) < 1e-12);
	/* a point far out (near the light's plane) takes no corner off the near ones: a
	 * tolerance on the turns scaled by the extent did, and the lookup region lost a notch
	 * of 109 pixels from a shadow's corner (directional light, 1920x1080) */
	vec2 far[5] = {{0, 0}, {10, 0}, {10, 3}, {0, 3}, {4e12, 1e12}};
	assert_true(lx_poly_hull(far, 5, &h));
	assert_true(holds_all(&h, far, 5));
	assert_int_equal(h.n, 4); /* (10, 3) is no corner */
}

static void polygon_caps_keep_a_superset(void **state)
{
	(void)state;
	enum { N = 100 };
	vec2 ring[N];
	for (int k = 0; k < N; k++)
		ring[k] = (vec2){cos(2 * M_PI * k / N), sin(2 * M_PI * k / N)};
	struct lx_poly h;
	assert_false(lx_poly_hull(ring, N, &h)); /* 100 hull vertices: the cap said */
	assert_true(h.n >= 3 && h.n <= LX_POLY_MAX);
	assert_true(holds_all(&h, ring, N));
	assert_true(fabs(lx_poly_area(&h)) < 1.01 * M_PI); /* and still tight */
	assert_true(lx_poly_hull(ring, 40, &h)); /* 40 vertices: exact */
	assert_int_equal(h.n, 40);
	/* a 64-gon cut by a line through two of its edges: 65 vertices would be needed */
	vec2 g[LX_POLY_MAX];
	for (int k = 0; k < LX_POLY_MAX; k++)
		g[k] = (vec2){cos(2 * M_PI * k / LX_POLY_MAX), sin(2 * M_PI * k / LX_POLY_MAX)}; /* one vertex at the bottom */
	assert_true(lx_poly_hull(g, LX_POLY_MAX, &h));
	assert_int_equal(h.n, LX_POLY_MAX);
	struct lx_poly cut;
	lx_poly_clip_halfplane(&h, 0, 1, 0.999, &cut); /* y >= -0.999: cuts off that vertex, adds two */
	assert_true(cut.n >= 3 && cut.n <= LX_POLY_MAX);
	int kept = 0;
	vec2 inside[LX_POLY_MAX];
	for (int k = 0; k < LX_POLY_MAX; k++)
		if (g[k].y >= -0.999)
			inside[kept++] = g[k];
	assert_int_equal(kept, LX_POLY_MAX - 1);
	assert_int_equal(cut.n, 32); /* 65 vertices: the 32-sided polygon around them */
	assert_true(holds_all(&cut, inside, kept));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(polygon_edges_inside),
		cmocka_unit_test(polygon_caps_keep_a_superset),
		cmocka_unit_test(polygon_hull_of_repeated_points),
		cmocka_unit_test(clipped_footprints_bound_the_planes),
		cmocka_unit_test(camera_matches_closed_form),
		cmocka_unit_test(m33_zero_is_solved),
		cmocka_unit_test(pixel_points_match_the_unprojection),
		cmocka_unit_test(sweep_is_one_affine_map_on_every_plane),
		cmocka_unit_test(shared_plane_points_give_the_same_figures),
		cmocka_unit_test(shared_budgets_hand_on_the_rest),
		cmocka_unit_test(readers_set_the_density_past_one),
		cmocka_unit_test(casters_read_the_fallback_alone),
		cmocka_unit_test(maps_do_not_depend_on_the_frame_before),
		cmocka_unit_test(every_shadow_is_covered),
		cmocka_unit_test(a_lit_fronts_shadow_is_left_to_its_test),
		cmocka_unit_test(scattered_shadows_take_pieces),
		cmocka_unit_test(fallback_alone_takes_every_budget),
		cmocka_unit_test(idle_plane_budget_goes_to_the_fallback),
		cmocka_unit_test(just_short_of_one_is_snapped),
		cmocka_unit_test(receiver_maps_keep_the_first_four),
		cmocka_unit_test(degenerate_configurations),
		cmocka_unit_test(no_stale_matrix),
		cmocka_unit_test(only_what_the_scene_requires),
		cmocka_unit_test(casters_under_a_plane_shadow_none_of_it),
		cmocka_unit_test(one_rectangle_shrinks_to_its_footprints),
		cmocka_unit_test(shadows_past_the_eye_stretch_the_map),
		cmocka_unit_test(wedge_footprints_cut_in_slabs),
		cmocka_unit_test(pieces_spend_the_budget_within_their_regions),
		cmocka_unit_test(slabs_keep_every_shadow),
		cmocka_unit_test(a_caster_through_a_plane_counts_above_it),
		cmocka_unit_test(no_footprint_on_a_plane_no_map),
		cmocka_unit_test(no_test_for_shadows_hidden),
		cmocka_unit_test(fallback_serves_only_what_needs_it),
		cmocka_unit_test(fallback_leaves_out_what_nothing_reaches),
		cmocka_unit_test(hidden_floor_takes_no_lixels),
		cmocka_unit_test(polygon_difference),
		cmocka_unit_test(halfplane_keeps_all_none_or_part),
		cmocka_unit_test(polygon_inset),
		cmocka_unit_test(polygon_bounds_outside_and_shrink),
		cmocka_unit_test(slab_underside_left_out_of_maps),
	};
	return cmocka_run_group_tests_name("plane", tests, NULL, NULL);
}
