/* `lixel render`: one frame of a scene with a shadow method, into a PNG, and its
 * figures (text or JSON). Parsing, the scene the options make, the run, the report. */
#include "cli_args.h"
#include "commands.h"
#include "board.h"
#include "configs.h"
#include "json.h"
#include "out_file.h"
#include "platform.h"
#include "render_job.h"
#include "soft_reference.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void render_usage(FILE *f)
{
	fprintf(f,
		"usage: lixel render [OPTIONS]\n"
		"\n"
		"Renders one frame of the scene with a shadow method into a PNG and prints the\n"
		"frame's figures (median frame time over the timed frames, light-matrix set-up).\n"
		"\n"
		"  --method NAME        shadow method: %s (default plane)\n"
		"  --scene NAME|FILE    built-in scene default, table, spotlight, projector or\n"
		"                       twolights (two lights), or a scene file (docs/scene-format.md)\n"
		"  --config NAME        a named view/light configuration applied to the scene:\n",
		lx_shadow_method_names());
	for (int i = 0; i < lx_config_count; i++)
		fprintf(f, "                         %-12s %s\n", lx_configs[i].name, lx_configs[i].summary);
	fprintf(f,
		"  --size WxH           image size in pixels (default 1024x768)\n"
		"  --eye X,Y,Z          camera position in metres\n"
		"  --at X,Y,Z           point the camera looks at\n"
		"  --fov DEG            vertical field of view, in (0, 180) degrees\n"
		"  --light X,Y,Z        point light at this position (white, in place of the scene's\n"
		"                       first light; its others stay)\n"
		"  --light-dir X,Y,Z    directional light travelling along this direction (the same)\n"
		"  --time SECONDS       animation time: where the bouncing casters are (default 0)\n"
		"  --platform NAME      GL platform: %s (default osmesa)\n"
		"  --out FILE.png       the shaded image (default lixel.png)\n"
		"  --decision-out FILE.png  the per-pixel shadow decision: shadowed red, lit tinted by object\n"
		"  --mismatch-out FILE.png  where the decision differs from the exact reference (implies\n"
		"                       --measure): missing shadow red, false shadow blue, silhouette yellow\n"
		"  --reference-out FILE.png  the exact reference's shaded image (implies --measure)\n"
		"  --atlas-out FILE.png the shadow atlas: depth as grey (near dark, far white), guard bands red\n"
		"  --measure            compare with the exact reference ray caster and compute the\n"
		"                       sampling figures of each plane of interest, and the soft-edge\n"
		"                       error against a small area light (soft_error_pct)\n"
		LX_FILTER_OPTION_HELP
		"  --json               print one JSON object on stdout instead of text\n"
		"  --frames N           timed frames after 3 warm-up frames (default 10)\n"
		"  --bias CODES         depth bias in 24-bit depth codes (default %g)\n"
		"  --uniform-lixels N   side of the one-map methods' map (default 512)\n"
		"  --plane-lixels N     each plane-optimal map holds N^2 lixels, in a shape fitted\n"
		"                       per frame (default 350)\n"
		"  --fallback-lixels N  side of the plane-optimal fallback map (default 128; in a\n"
		"                       frame where a plane has no map it grows from that plane's\n"
		"                       idle lixels, up to --plane-lixels)\n"
		LX_PLANE_OPTION_HELP
		LX_DEPTH_OPTION_HELP
		"  -h, --help           this text\n"
		"\n"
		"Exit status: 0 rendered; 1 the GL platform failed; 2 bad input (nothing written).\n",
		lx_platform_names(), LX_DEFAULT_BIAS_CODES);
}

static int bad(const char *opt, const char *expected, const char *got)
{
	return lx_arg_bad("render", opt, expected, got);
}

static int bad_number(const char *opt, const char *expected, const char *got, enum lx_number_error e)
{
	return lx_arg_bad_number("render", opt, expected, got, e);
}

/* WxH, each from 1 to 16384 */
static bool parse_size(const char *s, int *w, int *h)
{
	int hz;
	return lx_parse_mode(s, w, h, &hz) && hz == 0;
}

/* An output's directory must exist and be writable before anything is rendered, so a
 * bad path fails as bad input with nothing written. */
static bool writable_path(const char *opt, const char *path)
{
	char err[4300];
	if (!path || lx_out_check(path, err, sizeof err))
		return true;
	fprintf(stderr, "lixel render: %s: %s\n", opt, err);
	return false;
}

/* A warning as printed: with several lights, prefixed by the light it is about (a frame's
 * note about the light, "light: ...", becoming "light 2: ..."). */
static void light_warning(const struct lx_render_report *r, int l, const char *w, char *out, size_t room)
{
	if (r->light_count < 2)
		snprintf(out, room, "%s", w);
	else
		snprintf(out, room, "light %d: %s", l + 1, strncmp(w, "light: ", 7) ? w : w + 7);
}

/* How many rectangles plane p's own map is cut into this frame (its region and the spare
 * pieces it took), and the lixels they hold together in *lixels. */
static int own_pieces(const struct lx_light_report *lr, int p, long *lixels)
{
	int n = 0;
	*lixels = 0;
	for (int i = 0; i < lr->result.map_count; i++) {
		const struct lx_shadow_map *m = &lr->result.maps[i];
		if (m->rendered && m->plane == p) {
			const struct lx_region *g = &lr->atlas.regions[m->region];
			n++, *lixels += (long)g->w * g->h;
		}
	}
	return n;
}

/* The name of the map serving a plane's figures. */
static const char *plane_map_name(const struct lx_light_report *lr, const struct lx_plane_report *pr)
{
	return pr->s.map >= 0 ? lr->atlas.regions[lr->result.maps[pr->s.map].region].name : "serving";
}

static void print_atlas(const struct lx_render_report *r)
{
	const struct lx_atlas *a0 = &r->light[0].atlas;
	long lixels = 0;
	for (int l = 0; l < r->light_count; l++)
		lixels += lx_atlas_lixels(&r->light[l].atlas);
	printf("atlas: %dx%d, %ld lixels", a0->texture_width, a0->texture_height, lixels);
	for (int l = 0; l < r->light_count; l++) {
		const struct lx_light_report *lr = &r->light[l];
		if (r->light_count > 1)
			printf("; light %d (%s): %dx%d (%.0f%% filled)", l + 1, lr->kind, lr->atlas.width, lr->atlas.height,
			       100 * lx_atlas_fill(&lr->atlas));
		else
			printf(" (%.0f%% filled)", 100 * lx_atlas_fill(&lr->atlas));
		int idle = 0;
		for (int i = 0; i < lr->result.map_count; i++) {
			const struct lx_region *g = &lr->atlas.regions[lr->result.maps[i].region];
			if (!lr->result.maps[i].rendered && g->variable && g->counted == 0) {
				idle++; /* a spare piece no plane took this frame */
				continue;
			}
			printf("; %s %dx%d at (%d, %d)%s", g->name, g->w, g->h, g->x, g->y,
			       lr->result.maps[i].rendered ? "" : " (not rendered)");
		}
		if (idle > 0)
			printf("; %d spare piece%s unused", idle, idle > 1 ? "s" : "");
	}
	if (r->depth_slots > 1)
		printf("; cleared once every %d frames (depth slots)", r->depth_slots);
	printf("\n");
	for (int l = 0; l < r->light_count; l++)
		for (int i = 0; i < r->light[l].result.warning_count; i++) {
			char w[LX_WARNING_MAX + 16];
			light_warning(r, l, r->light[l].result.warnings[i], w, sizeof w);
			printf("warning: %s\n", w);
		}
}

static void print_mismatch(const char *what, const struct lx_mismatch *m)
{
	printf("%s: %.4f%% of %ld pixels (false shadow %.4f%%, missing shadow %.4f%%); %ld silhouette pixels", what,
	       m->mismatch_pct, m->compared, m->false_shadow_pct, m->missing_shadow_pct, m->silhouette);
	if (m->edge_on)
		printf("; %ld pixels the light grazes, not compared", m->edge_on);
	if (m->unlit)
		printf("; %ld pixels the light does not reach, not compared", m->unlit);
	printf("\n");
}

static void print_planes(const struct lx_render_report *r, int l)
{
	const struct lx_light_report *lr = &r->light[l];
	char who[32] = "";
	if (r->light_count > 1)
		snprintf(who, sizeof who, "light %d ", l + 1);
	for (int p = 0; p < r->plane_count; p++) {
		const struct lx_plane_report *pr = &lr->planes[p];
		if (!pr->present && pr->s.seen > 0)
			printf("%splane %s: %ld pixels seen, none measured: %ld ran no lookup (no shadow can fall there), "
			       "%ld no map serves\n",
			       who, pr->name, pr->s.seen, pr->s.no_lookup, pr->s.unserved);
		else if (!pr->present)
			printf("%splane %s: not in view\n", who, pr->name);
		else {
			long lixels;
			int pieces = pr->s.map >= 0 ? own_pieces(lr, p, &lixels) : 0;
			char in[32] = "";
			if (pieces > 1)
				snprintf(in, sizeof in, " in %d pieces", pieces);
			printf("%splane %s (%s map%s): %ld of its %ld pixels read a map, lpp median %.4g, m median %.4g, "
			       "m max %.4g, aniso max %.4g, lixels used %.0f\n",
			       who, pr->name, plane_map_name(lr, pr), in, pr->s.pixels, pr->s.seen, pr->s.lpp_median,
			       pr->s.m_median, pr->s.m_max, pr->s.aniso_max, pr->s.lixels_used);
		}
	}
}

static void print_text(const struct lx_render_report *r, const char *out)
{
	printf("lixel: wrote %s (%dx%d, method %s, %s on %s)\n", out, r->width, r->height, r->method, r->platform,
	       r->caps.renderer);
	printf("frame: %.3f ms median (min %.3f, max %.3f): shadow passes %.3f ms, main pass %.3f ms; set-up %.1f us\n",
	       r->frame_ms, r->frame_ms_min, r->frame_ms_max, r->shadow_ms, r->main_ms, r->setup_us);
	print_atlas(r);
	if (r->lookup_pct >= 0)
		printf("lookups: %.2f%% of the pixels ran a shadow lookup%s\n", r->lookup_pct,
		       r->light_count > 1 ? " (mean over the lights' passes)" : "");
	if (!r->measured)
		return;
	print_mismatch("mismatch", &r->mismatch);
	for (int l = 0; l < r->light_count && r->light_count > 1; l++) {
		char what[48];
		snprintf(what, sizeof what, "light %d (%s) mismatch", l + 1, r->light[l].kind);
		print_mismatch(what, &r->light[l].mismatch);
	}
	printf("colour error: %.3f levels of 255 (mean over the pixels and R, G, B)\n", r->colour_error);
	if (r->soft_measured)
		printf("soft edge: %.4f%% mean visibility error (filter %s) against a %.3g-degree area light\n",
		       r->soft_error_pct, r->filter, r->light_size_deg);
	for (int l = 0; l < r->light_count; l++)
		print_planes(r, l);
}

/* A light's measured planes, each an object under its name: the map's figures and budget use. */
static void json_planes(struct lx_json *j, const struct lx_render_report *r, int l)
{
	const struct lx_light_report *lr = &r->light[l];
	lx_json_key(j, "planes");
	lx_json_object(j);
	for (int p = 0; p < r->plane_count; p++) {
		const struct lx_plane_report *pr = &lr->planes[p];
		if (!pr->present && pr->s.seen == 0)
			continue;
		lx_json_key(j, pr->name);
		lx_json_object(j);
		/* the figures are of the plane's own map, or of whichever map serves each pixel */
		lx_json_key(j, "map");
		lx_json_string(j, pr->present ? plane_map_name(lr, pr) : "none");
		lx_json_key(j, "pixels"), lx_json_int(j, pr->s.pixels); /* those that read a map */
		lx_json_key(j, "pixels_seen"), lx_json_int(j, pr->s.seen);
		lx_json_key(j, "pixels_no_lookup"), lx_json_int(j, pr->s.no_lookup);
		if (!pr->present) { /* seen, but no pixel of it reads a map */
			lx_json_end(j);
			continue;
		}
		lx_json_key(j, "lpp_median"), lx_json_number(j, pr->s.lpp_median);
		lx_json_key(j, "m_median"), lx_json_number(j, pr->s.m_median);
		lx_json_key(j, "m_max"), lx_json_number(j, pr->s.m_max);
		lx_json_key(j, "aniso_max"), lx_json_number(j, pr->s.aniso_max);
		lx_json_key(j, "lpp_spread"), lx_json_number(j, pr->s.lpp_min > 0 ? pr->s.lpp_max / pr->s.lpp_min : NAN);
		lx_json_key(j, "degenerate_pixels"), lx_json_int(j, pr->s.degenerate);
		lx_json_key(j, "lixels_used"), lx_json_number(j, pr->s.lixels_used);
		if (pr->s.map >= 0) { /* budget use: of the plane's own map's lixels, all its pieces' */
			long lixels;
			lx_json_key(j, "map_pieces"), lx_json_int(j, own_pieces(lr, p, &lixels));
			lx_json_key(j, "map_lixels"), lx_json_int(j, lixels);
		}
		lx_json_end(j);
	}
	lx_json_end(j);
}

/* The comparison's shares of the compared pixels, then its pixel counts. */
static void json_mismatch(struct lx_json *j, const struct lx_mismatch *m)
{
	static const char *const pct_key[] = {"mismatch_pct", "false_shadow_pct", "missing_shadow_pct"};
	static const char *const count_key[] = {"compared_pixels", "silhouette_pixels", "edge_on_pixels", "unlit_pixels"};
	const double pct[] = {m->mismatch_pct, m->false_shadow_pct, m->missing_shadow_pct};
	const long count[] = {m->compared, m->silhouette, m->edge_on, m->unlit};
	for (int k = 0; k < 3; k++)
		lx_json_key(j, pct_key[k]), lx_json_number(j, pct[k]);
	for (int k = 0; k < 4; k++)
		lx_json_key(j, count_key[k]), lx_json_int(j, count[k]);
}

/* Every light's maps, each with the light it belongs to (1, 2, ...). */
static void json_maps(struct lx_json *j, const struct lx_render_report *r)
{
	lx_json_key(j, "maps");
	lx_json_array(j);
	for (int l = 0; l < r->light_count; l++) {
		const struct lx_light_report *lr = &r->light[l];
		for (int i = 0; i < lr->result.map_count; i++) {
			const struct lx_region *g = &lr->atlas.regions[lr->result.maps[i].region];
			lx_json_object(j);
			lx_json_key(j, "name"), lx_json_string(j, g->name);
			lx_json_key(j, "x"), lx_json_int(j, g->x);
			lx_json_key(j, "y"), lx_json_int(j, g->y);
			lx_json_key(j, "w"), lx_json_int(j, g->w);
			lx_json_key(j, "h"), lx_json_int(j, g->h);
			lx_json_key(j, "turned"), lx_json_bool(j, g->turned);
			lx_json_key(j, "rendered"), lx_json_bool(j, lr->result.maps[i].rendered);
			lx_json_key(j, "light"), lx_json_int(j, l + 1);
			lx_json_end(j);
		}
	}
	lx_json_end(j);
}

/* Per light: its kind, lixels and atlas part, and measured, its mismatch and planes. */
static void json_lights(struct lx_json *j, const struct lx_render_report *r)
{
	lx_json_key(j, "lights");
	lx_json_array(j);
	for (int l = 0; l < r->light_count; l++) {
		const struct lx_light_report *lr = &r->light[l];
		lx_json_object(j);
		lx_json_key(j, "kind"), lx_json_string(j, lr->kind);
		lx_json_key(j, "lixels"), lx_json_int(j, lx_atlas_lixels(&lr->atlas));
		lx_json_key(j, "atlas_part"), lx_json_array(j), lx_json_int(j, lr->atlas.x0), lx_json_int(j, lr->atlas.y0),
			lx_json_int(j, lr->atlas.width), lx_json_int(j, lr->atlas.height), lx_json_end(j);
		if (r->lookup_pct >= 0)
			lx_json_key(j, "lookup_pct"), lx_json_number(j, lr->lookup_pct);
		if (r->measured) {
			json_mismatch(j, &lr->mismatch);
			json_planes(j, r, l);
		}
		lx_json_end(j);
	}
	lx_json_end(j);
}

static void json_warnings(struct lx_json *j, const struct lx_render_report *r)
{
	lx_json_key(j, "warnings");
	lx_json_array(j);
	if (r->depth.warning[0])
		lx_json_string(j, r->depth.warning);
	for (int l = 0; l < r->light_count; l++)
		for (int i = 0; i < r->light[l].result.warning_count; i++) {
			char w[LX_WARNING_MAX + 16];
			light_warning(r, l, r->light[l].result.warnings[i], w, sizeof w);
			lx_json_string(j, w);
		}
	lx_json_end(j);
}

static void print_json(const struct lx_render_report *r)
{
	struct lx_json j;
	lx_json_begin(&j, stdout);
	lx_json_object(&j);
	lx_json_key(&j, "method"), lx_json_string(&j, r->method);
	lx_json_key(&j, "filter"), lx_json_string(&j, r->filter);
	lx_json_key(&j, "platform"), lx_json_string(&j, r->platform);
	lx_json_key(&j, "renderer"), lx_json_string(&j, r->caps.renderer);
	lx_json_key(&j, "size"), lx_json_array(&j), lx_json_int(&j, r->width), lx_json_int(&j, r->height), lx_json_end(&j);
	long lixels = 0, placed = 0;
	for (int l = 0; l < r->light_count; l++)
		lixels += lx_atlas_lixels(&r->light[l].atlas), placed += lx_atlas_placed(&r->light[l].atlas);
	const struct lx_atlas *a0 = &r->light[0].atlas;
	lx_json_key(&j, "lixels"), lx_json_int(&j, lixels);
	lx_json_key(&j, "atlas"), lx_json_array(&j), lx_json_int(&j, a0->texture_width), lx_json_int(&j, a0->texture_height),
		lx_json_end(&j);
	json_maps(&j, r);
	lx_json_key(&j, "atlas_fill"), lx_json_number(&j, (double)placed / ((double)a0->texture_width * a0->texture_height));
	lx_json_key(&j, "frame_ms"), lx_json_number(&j, r->frame_ms);
	lx_json_key(&j, "frame_ms_min"), lx_json_number(&j, r->frame_ms_min);
	lx_json_key(&j, "frame_ms_max"), lx_json_number(&j, r->frame_ms_max);
	lx_json_key(&j, "shadow_ms"), lx_json_number(&j, r->shadow_ms);
	lx_json_key(&j, "main_ms"), lx_json_number(&j, r->main_ms);
	lx_json_key(&j, "setup_us"), lx_json_number(&j, r->setup_us);
	lx_json_key(&j, "fragment_highp"), lx_json_bool(&j, r->caps.fragment_highp);
	lx_json_key(&j, "depth_path"), lx_json_string(&j, r->depth.path);
	lx_json_key(&j, "depth_selftest"), lx_json_string(&j, r->depth.selftest);
	lx_json_key(&j, "depth_slots"), lx_json_int(&j, r->depth_slots);
	if (r->lookup_pct >= 0)
		lx_json_key(&j, "lookup_pct"), lx_json_number(&j, r->lookup_pct);
	json_warnings(&j, r);
	if (r->measured) {
		json_mismatch(&j, &r->mismatch);
		lx_json_key(&j, "colour_error"), lx_json_number(&j, r->colour_error);
		if (r->soft_measured) {
			lx_json_key(&j, "soft_error_pct"), lx_json_number(&j, r->soft_error_pct);
			lx_json_key(&j, "light_size_deg"), lx_json_number(&j, r->light_size_deg);
		}
		json_planes(&j, r, 0); /* the first light's, as for a scene of one */
	}
	json_lights(&j, r);
	lx_json_end(&j);
}

/* What the command line says, before the scene it names is loaded. */
struct render_args {
	struct lx_render_job job;
	const char *scene_file, *config;
	bool json, have_eye, have_at, have_fov, have_light, have_dir, have_light_size;
	vec3 eye, at, light, dir;
	double fov;
};

/* --eye, --at, --fov, --light, --light-dir, --time: 0, 2 after the one line, -1 for
 * another option. */
static int view_option(struct render_args *r, const char *a, const char *v)
{
	enum lx_number_error e;
	if (!strcmp(a, "--eye") || !strcmp(a, "--at") || !strcmp(a, "--light")) {
		vec3 *p = a[2] == 'e' ? &r->eye : a[2] == 'a' ? &r->at : &r->light;
		if ((e = lx_arg_triple(v, p)))
			return bad_number(a, "three numbers X,Y,Z from -1e15 to 1e15", v, e);
		*(a[2] == 'e' ? &r->have_eye : a[2] == 'a' ? &r->have_at : &r->have_light) = true;
	} else if (!strcmp(a, "--fov")) {
		if ((e = lx_number_real(v, 0, 180, &r->fov)) || r->fov == 0 || r->fov == 180)
			return bad_number(a, "degrees in (0, 180)", v, e);
		r->have_fov = true;
	} else if (!strcmp(a, "--light-dir")) {
		if ((e = lx_arg_triple(v, &r->dir)) || !v3_normalize(r->dir, &r->dir))
			return bad_number(a, "three numbers X,Y,Z from -1e15 to 1e15, not all zero", v, e);
		r->have_dir = true;
	} else if (!strcmp(a, "--time")) {
		/* beyond a million seconds the animation's phase has no precision left (and
		 * near 1e308 it overflows to NaN casters) */
		if ((e = lx_number_real(v, -1e6, 1e6, &r->job.time)))
			return bad_number(a, "seconds, a number from -1000000 to 1000000", v, e);
	} else
		return -1;
	return 0;
}

/* The outputs, the platform, the frames, the budgets and the bias. */
static int job_option(struct lx_render_job *job, const char *a, const char *v)
{
	enum lx_number_error e;
	const struct lx_arg_text outputs[] = {{"--out", &job->out_png},
					      {"--decision-out", &job->decision_png},
					      {"--mismatch-out", &job->mismatch_png},
					      {"--reference-out", &job->reference_png},
					      {"--atlas-out", &job->atlas_png}};
	if (lx_arg_text(a, v, outputs, sizeof outputs / sizeof outputs[0])) {
		job->measure |= job->mismatch_png || job->reference_png; /* those images need it */
		return 0;
	}
	if (!strcmp(a, "--platform")) {
		if (!lx_platform_known(v))
			return bad(a, lx_platform_names(), v);
		job->platform = v;
	} else if (!strcmp(a, "--frames")) {
		if ((e = lx_number_int(v, 1, 100000, &job->timed_frames)))
			return bad_number(a, "a whole number of frames from 1 to 100000", v, e);
	} else if (!strcmp(a, "--uniform-lixels") || !strcmp(a, "--plane-lixels") || !strcmp(a, "--fallback-lixels")) {
		int *field = a[2] == 'u' ? &job->budgets.uniform_lixels : a[2] == 'p' ? &job->budgets.plane_lixels
										       : &job->budgets.fallback_lixels;
		if ((e = lx_number_int(v, 1, 8192, field)))
			return bad_number(a, "a whole number of lixels from 1 to 8192", v, e);
	} else if (!strcmp(a, "--bias")) {
		if ((e = lx_number_real(v, 0, 16777215, &job->bias_codes)))
			return bad_number(a, "depth codes from 0 to 16777215", v, e);
	} else if (!strcmp(a, "--size")) {
		if (!parse_size(v, &job->width, &job->height))
			return bad(a, "WxH with W and H from 1 to 16384", v);
	} else
		return -1;
	return 0;
}

/* One option and its value (the names lx_arg_value took): 0 or 2. */
static int render_option(struct render_args *r, const char *a, const char *v)
{
	int st;
	r->have_light_size |= !strcmp(a, "--light-size");
	if ((st = lx_arg_filter("render", a, v, &r->job.filter, &r->job.light_size_deg)) >= 0 ||
	    (st = lx_arg_depth_precision("render", a, v, &r->job.depth_precision)) >= 0 ||
	    (st = lx_arg_plane_option("render", a, v, &r->job.budgets)) >= 0 || (st = view_option(r, a, v)) >= 0 ||
	    (st = job_option(&r->job, a, v)) >= 0)
		return st;
	if (!strcmp(a, "--method")) {
		if ((st = lx_arg_method_spec("render", a, v, &r->job.budgets, lx_shadow_method_names())))
			return st;
		r->job.method = v;
	} else if (!strcmp(a, "--scene"))
		r->scene_file = v;
	else if (!strcmp(a, "--config")) {
		if (!lx_config_find(v))
			return bad(a, "a configuration named in lixel render --help", v);
		r->config = v;
	}
	return 0;
}

/* The command line into *r: 0, 2 after the one line, or -1 when --help was printed. */
static int render_parse(int argc, char **argv, struct render_args *r)
{
	*r = (struct render_args){.job = {.method = LX_DEFAULT_METHOD, .platform = "osmesa", .width = 1024, .height = 768,
					  .warmup_frames = 3, .timed_frames = 10, .bias_codes = LX_DEFAULT_BIAS_CODES,
					  .reference_threads = 2, .out_png = "lixel.png",
					  .light_size_deg = LX_DEFAULT_LIGHT_SIZE_DEG, .budgets = LX_METHOD_OPTIONS_DEFAULT}};
	static const char *const with_value[] = {"--method", "--scene", "--config", "--size", "--eye", "--at", "--fov",
						 "--light", "--light-dir", "--time", "--platform", "--out", "--decision-out",
						 "--mismatch-out", "--reference-out", "--atlas-out", "--frames", "--bias", "--depth-precision",
						 "--uniform-lixels", "--plane-lixels", "--fallback-lixels", LX_PLANE_OPTION_NAMES,
						 "--filter", "--light-size"};
	for (int i = 0; i < argc; i++) {
		const char *a = argv[i], *v;
		if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
			render_usage(stdout);
			return -1;
		}
		bool flag = true;
		if (!strcmp(a, "--measure"))
			r->job.measure = true;
		else if (!strcmp(a, "--json"))
			r->json = true;
		else if (!strcmp(a, "--mediump"))
			r->job.depth_precision = LX_DEPTH_MEDIUMP;
		else
			flag = false;
		if (flag)
			continue;
		int st = lx_arg_value("render", argc, argv, &i, with_value, sizeof with_value / sizeof with_value[0], &v);
		if (st || (st = render_option(r, a, v)))
			return st;
	}
	/* the soft reference costs seconds a frame at 1024^2: measured where it says something,
	 * with a filter on or a light size asked for */
	r->job.soft = r->job.measure && (r->job.filter != LX_FILTER_NONE || r->have_light_size);
	return 0;
}

/* The options taken together: the outputs writable, the scene loaded with the view and
 * the light they set. 0 or 2 after the one line. */
static int render_scene(struct render_args *r)
{
	struct lx_render_job *job = &r->job;
	if (r->have_light && r->have_dir) {
		fprintf(stderr, "lixel render: --light and --light-dir: expected one of them, got both\n");
		return 2;
	}
	if (!writable_path("--out", job->out_png) || !writable_path("--decision-out", job->decision_png) ||
	    !writable_path("--mismatch-out", job->mismatch_png) || !writable_path("--reference-out", job->reference_png) ||
	    !writable_path("--atlas-out", job->atlas_png) ||
	    !lx_arg_scene(r->scene_file, &job->scene))
		return 2;
	struct lx_scene *s = &job->scene;
	if (r->config)
		lx_config_apply(lx_config_find(r->config), s);
	s->camera.eye = r->have_eye ? r->eye : s->camera.eye;
	s->camera.at = r->have_at ? r->at : s->camera.at;
	s->camera.fovy_deg = r->have_fov ? r->fov : s->camera.fovy_deg;
	if (r->have_light)
		s->light = lx_light_white(r->light); /* the first light; a scene's others stay */
	if (r->have_dir)
		s->light = lx_light_white(v3(0, 0, 0)), s->light.directional = true, s->light.direction = r->dir;
	mat4 check;
	if (!m4_look_at(s->camera.eye, s->camera.at, s->camera.up, &check)) {
		fprintf(stderr, "lixel render: --eye/--at: expected a camera whose eye differs from at and does not look along up\n");
		return 2;
	}
	return 0;
}

int lx_render_main(int argc, char **argv)
{
	struct render_args r;
	int st = render_parse(argc, argv, &r);
	if (st)
		return st < 0 ? 0 : st;
	if ((st = render_scene(&r)))
		return st;
	char err[512];
	struct lx_render_report rep;
	if ((st = lx_render_run(&r.job, &rep, err, sizeof err))) {
		fprintf(stderr, "lixel: %s\n", err);
		return st;
	}
	if (rep.depth.warning[0])
		fprintf(stderr, "lixel: warning: %s\n", rep.depth.warning);
	if (r.json)
		print_json(&rep);
	else
		print_text(&rep, r.job.out_png);
	return 0;
}
