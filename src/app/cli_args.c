#include "cli_args.h"
#include "shadow_method.h"
#include "soft_reference.h"
#include <stddef.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

/* got as one line: control characters (a line break smuggled into a value) shown escaped */
static void print_value(const char *got)
{
	for (const unsigned char *p = (const unsigned char *)got; *p; p++)
		if (*p < 0x20 || *p == 0x7f)
			fprintf(stderr, "\\x%02x", *p);
		else
			fputc(*p, stderr);
}

int lx_arg_bad_number(const char *cmd, const char *opt, const char *expected, const char *got, enum lx_number_error e)
{
	fprintf(stderr, "lixel %s: %s: expected %s, got '", cmd, opt, expected);
	print_value(got ? got : "");
	if (e != LX_NUMBER_OK && e != LX_NUMBER_OUT_OF_RANGE)
		fprintf(stderr, "' (%s)\n", lx_number_why(e));
	else
		fprintf(stderr, "'\n");
	return 2;
}

int lx_arg_bad(const char *cmd, const char *opt, const char *expected, const char *got)
{
	if (!got) {
		fprintf(stderr, "lixel %s: %s: expected %s, got nothing\n", cmd, opt, expected);
		return 2;
	}
	return lx_arg_bad_number(cmd, opt, expected, got, LX_NUMBER_OK);
}

enum lx_number_error lx_arg_triple(const char *s, vec3 *out)
{
	double v[3];
	enum lx_number_error e = lx_number_reals(s, 3, -LX_SCENE_NUMBER_MAX, LX_SCENE_NUMBER_MAX, v, NULL);
	if (e == LX_NUMBER_OK)
		*out = (vec3){v[0], v[1], v[2]};
	return e;
}

int lx_arg_value(const char *cmd, int argc, char **argv, int *i, const char *const *names, size_t n,
		 const char **value)
{
	const char *a = argv[*i];
	size_t k = 0;
	while (k < n && strcmp(a, names[k]))
		k++;
	if (k == n) {
		fprintf(stderr, "lixel %s: unknown option '%s' (see lixel %s --help)\n", cmd, a, cmd);
		return 2;
	}
	if (*i + 1 >= argc)
		return lx_arg_bad(cmd, a, "a value", NULL);
	*value = argv[++*i];
	return 0;
}

bool lx_arg_scene(const char *arg, struct lx_scene *s)
{
	char err[512];
	if (!arg) {
		lx_scene_default(s);
		return true;
	}
	if (lx_scene_builtin(arg, s) || lx_scene_load(arg, s, err, sizeof err))
		return true;
	fprintf(stderr, "lixel: %s\n", err);
	return false;
}

int lx_arg_depth_precision(const char *cmd, const char *opt, const char *value, enum lx_depth_precision *out)
{
	if (strcmp(opt, "--depth-precision"))
		return -1;
	if (!lx_depth_precision_parse(value, out))
		return lx_arg_bad(cmd, opt, "auto, highp, mediump or texture", value);
	return 0;
}

int lx_arg_filter(const char *cmd, const char *opt, const char *value, enum lx_filter *filter, double *light_size_deg)
{
	enum lx_number_error e;
	if (!strcmp(opt, "--filter")) {
		if (!lx_filter_parse(value, filter))
			return lx_arg_bad(cmd, opt, lx_filter_names(), value);
	} else if (!strcmp(opt, "--light-size")) {
		if ((e = lx_number_real(value, 0, LX_MAX_LIGHT_SIZE_DEG, light_size_deg)))
			return lx_arg_bad_number(cmd, opt, "degrees from 0 to 20", value, e);
	} else
		return -1;
	return 0;
}

bool lx_arg_text(const char *opt, const char *value, const struct lx_arg_text *t, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (!strcmp(opt, t[i].name)) {
			*t[i].to = value;
			return true;
		}
	return false;
}

/* The options of two words: the default's (false) and the other's (true). */
struct two_way {
	const char *name, *off, *on, *expected;
	size_t field; /* a bool of struct lx_method_options */
};
static const struct two_way two_ways[] = {
	{"--region-shape", "fitted", "square", "fitted or square", offsetof(struct lx_method_options, square_regions)},
	{"--budget-split", "fixed", "shared", "fixed or shared", offsetof(struct lx_method_options, shared_budget)},
	{"--plane-density", "readers", "budget", "readers or budget", offsetof(struct lx_method_options, plane_dense_budget)},
	{"--caster-maps", "dense", "fallback", "dense or fallback", offsetof(struct lx_method_options, caster_fallback_only)},
	{"--lookup-region", "footprint", "all", "footprint or all", offsetof(struct lx_method_options, lookup_everywhere)},
	{"--caster-depth", "point", "face", "point or face", offsetof(struct lx_method_options, caster_face_depth)},
};

int lx_arg_plane_option(const char *cmd, const char *opt, const char *value, struct lx_method_options *o)
{
	for (size_t i = 0; i < sizeof two_ways / sizeof two_ways[0]; i++) {
		const struct two_way *t = &two_ways[i];
		if (strcmp(opt, t->name))
			continue;
		if (strcmp(value, t->off) && strcmp(value, t->on))
			return lx_arg_bad(cmd, opt, t->expected, value);
		*(bool *)((char *)o + t->field) = !strcmp(value, t->on);
		return 0;
	}
	if (!strcmp(opt, "--depth-slots")) {
		enum lx_number_error e = lx_number_int(value, 1, LX_DEPTH_SLOTS_MAX, &o->depth_slots);
		if (e)
			return lx_arg_bad_number(cmd, opt, "a whole number of frames from 1 to 64", value, e);
	} else if (!strcmp(opt, "--light-budget")) {
		if (!lx_light_budget_parse(value, o))
			return lx_arg_bad(cmd, opt, LX_LIGHT_BUDGET_EXPECTED, value);
	} else if (!strcmp(opt, "--plane-max-lpp")) {
		double x = -1; /* none: no cap at all */
		enum lx_number_error e;
		if (strcmp(value, "none") && ((e = lx_number_real(value, 0, 1e4, &x)) || x == 0))
			return lx_arg_bad_number(cmd, opt, "lixels per pixel, a number in (0, 10000], or none", value, e);
		o->plane_max_lpp = x;
	} else
		return -1;
	return 0;
}

int lx_arg_method_spec(const char *cmd, const char *opt, const char *spec, const struct lx_method_options *o,
		       const char *expected)
{
	struct lx_method_options probe = *o;
	char why[320];
	if (lx_shadow_method_spec(spec, &probe, why, sizeof why))
		return 0;
	if (strpbrk(spec, "\n\r\t")) /* shown escaped, on one line */
		return lx_arg_bad(cmd, opt, expected, spec);
	fprintf(stderr, "lixel %s: %s: %s\n", cmd, opt, why);
	return 2;
}
