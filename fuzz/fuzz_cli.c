/* libFuzzer harness: the command line's value parsers. The first byte picks one, the rest
 * is the value: a number (lx_number_real), a whole number (lx_number_whole), a point X,Y,Z
 * (lx_arg_triple), a comma list (lx_list_next), the maps' options (lx_arg_plane_option),
 * --depth-precision, --filter and --light-size, and the kiosk's button overrides, which it applies as one profile
 * line (lx_board_apply). Whatever parses is in range and reads back the same; whatever
 * does not says so, in one line. */
#include "board.h"
#include "cli_args.h"
#include "fuzz_util.h"
#include "number.h"
#include "shadow_method.h"
#include <math.h>

static void check_real(const char *v)
{
	double x = 12345;
	enum lx_number_error e = lx_number_real(v, -1e15, 1e15, &x);
	if (e) {
		FUZZ_CHECK(x == 12345 && lx_number_why(e)[0]);
		return;
	}
	FUZZ_CHECK(isfinite(x) && x >= -1e15 && x <= 1e15 && !(x == 0 && signbit(x))); /* no -0 */
	char again[64];
	snprintf(again, sizeof again, "%.17g", x);
	double y;
	/* %.17g may print an exponent form lx_number_real takes; it never prints hex or inf */
	FUZZ_CHECK(lx_number_real(again, -1e15, 1e15, &y) == LX_NUMBER_OK && y == x);
}

static void check_whole(const char *v)
{
	long x = 777;
	enum lx_number_error e = lx_number_whole(v, -1000000, 1000000, &x);
	if (e) {
		FUZZ_CHECK(x == 777);
		return;
	}
	FUZZ_CHECK(x >= -1000000 && x <= 1000000);
	char again[32];
	snprintf(again, sizeof again, "%ld", x);
	long y;
	FUZZ_CHECK(lx_number_whole(again, -1000000, 1000000, &y) == LX_NUMBER_OK && y == x);
}

static void check_triple(const char *v)
{
	vec3 p = {1, 2, 3};
	if (lx_arg_triple(v, &p) == LX_NUMBER_OK)
		FUZZ_CHECK(isfinite(p.x) && isfinite(p.y) && isfinite(p.z) && fabs(p.x) <= LX_SCENE_NUMBER_MAX &&
			   fabs(p.y) <= LX_SCENE_NUMBER_MAX && fabs(p.z) <= LX_SCENE_NUMBER_MAX);
	else
		FUZZ_CHECK(p.x == 1 && p.y == 2 && p.z == 3);
}

/* Items are never empty and hold no comma; when every item is good, joining them with
 * commas gives the list back. */
static void check_list(const char *v)
{
	const char *s = v;
	char item[16], joined[4096] = "";
	size_t used = 0;
	int r, items = 0;
	bool good = true;
	while ((r = lx_list_next(&s, ',', item, sizeof item)) != 0) {
		FUZZ_CHECK(r == 1 || r == -1);
		FUZZ_CHECK(items++ < 4096); /* it ends */
		if (r < 0) {
			good = false;
			continue;
		}
		FUZZ_CHECK(item[0] && !strchr(item, ','));
		size_t l = strlen(item);
		if (used + l + 2 < sizeof joined) {
			if (used)
				joined[used++] = ',';
			memcpy(joined + used, item, l + 1);
			used += l;
		} else
			good = false;
	}
	if (good)
		FUZZ_CHECK(!strcmp(joined, v));
}

static void check_options(const char *v)
{
	static const char *const names[] = {"--region-shape", "--budget-split", "--plane-max-lpp", "--lookup-region"};
	for (int i = 0; i < 4; i++) {
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		int st = lx_arg_plane_option("fuzz", names[i], v, &o);
		FUZZ_CHECK(st == 0 || st == 2);
		FUZZ_CHECK(o.plane_max_lpp == 0 || o.plane_max_lpp == -1 || (o.plane_max_lpp > 0 && o.plane_max_lpp <= 1e4));
	}
	enum lx_depth_precision d = LX_DEPTH_AUTO;
	int st = lx_arg_depth_precision("fuzz", "--depth-precision", v, &d);
	FUZZ_CHECK(st == 0 || st == 2);
	/* --filter and --light-size: a known filter, a size within [0, 20] degrees */
	for (int i = 0; i < 2; i++) {
		enum lx_filter f = LX_FILTER_NONE;
		double size = 0.5;
		st = lx_arg_filter("fuzz", i ? "--light-size" : "--filter", v, &f, &size);
		FUZZ_CHECK(st == 0 || st == 2);
		FUZZ_CHECK((unsigned)f < LX_FILTER_COUNT && isfinite(size) && size >= 0 && size <= 20);
		if (st == 0 && i == 0)
			FUZZ_CHECK(!strcmp(lx_filter_name(f), v));
	}
}

/* As lixel kiosk does with --gpio-chip, --gpio-line, ...: one profile line per override,
 * refused when the value holds a line break. */
static void check_override(const char *v)
{
	static const char *const keys[] = {"gpio-chip", "gpio-line", "gpio-line-name", "gpio-active", "gpio-bias",
					   "debounce-ms", "long-press-ms", "plane-lixels", "methods", "mode", "filters"};
	if (strpbrk(v, "\n\r"))
		return;
	for (int i = 0; i < 11; i++) {
		struct lx_board b;
		lx_board_defaults(&b);
		char line[600], err[256];
		if ((size_t)snprintf(line, sizeof line, "%s %s\n", keys[i], v) >= sizeof line)
			continue;
		if (!lx_board_apply(line, "--override", &b, err, sizeof err)) {
			FUZZ_CHECK(memchr(err, 0, sizeof err) && !strchr(err, '\n') && err[0]);
			continue;
		}
		FUZZ_CHECK(b.method_count >= 1 && b.method_count <= LX_BOARD_MAX_METHODS);
		for (int m = 0; m < b.method_count; m++)
			FUZZ_CHECK(lx_shadow_method_find(b.methods[m]) != NULL);
		FUZZ_CHECK(b.gpio_line >= -1 && b.gpio_line <= 1023 && b.debounce_ms >= 0 && b.debounce_ms <= 1000);
		FUZZ_CHECK(b.long_press_ms >= 100 && b.long_press_ms <= 10000);
		FUZZ_CHECK(b.lixels.plane_lixels >= 0 && b.lixels.plane_lixels <= 8192);
		FUZZ_CHECK(b.filter_count >= 1 && b.filter_count <= LX_FILTER_COUNT);
		for (int f = 0; f < b.filter_count; f++)
			FUZZ_CHECK((unsigned)b.filters[f] < LX_FILTER_COUNT);
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (size < 1)
		return 0;
	char *v = fuzz_text(data + 1, size - 1);
	switch (data[0] % 6) {
	case 0: check_real(v); break;
	case 1: check_whole(v); break;
	case 2: check_triple(v); break;
	case 3: check_list(v); break;
	case 4: check_options(v); break;
	default: check_override(v); break;
	}
	free(v);
	return 0;
}
