/* libFuzzer harness: method specs ("plane/square/lpp0.5", "uniform/all"; the parser
 * lx_shadow_method_spec) and display modes ("1920x1080@60"; lx_parse_mode), each fed the
 * whole input. A spec that parses names a known method, leaves the lixel budgets alone,
 * changes the plane options only for the plane method and gives a density cap in range;
 * one that does not says why. A mode that parses is within 1..16384 (refresh 0..1000) and
 * reads back the same when printed. */
#include "board.h"
#include "fuzz_util.h"
#include "shadow_method.h"

static void check_spec(const char *text)
{
	struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT, before = o;
	char err[128];
	memset(err, 0x55, sizeof err);
	const struct lx_shadow_method *m = lx_shadow_method_spec(text, &o, err, sizeof err);
	if (!m) {
		FUZZ_CHECK(memchr(err, 0, sizeof err) && err[0]);
		char small[8]; /* a short buffer only truncates the message */
		FUZZ_CHECK(!lx_shadow_method_spec(text, &o, small, sizeof small) && memchr(small, 0, sizeof small));
		return;
	}
	size_t nl = strcspn(text, "/");
	FUZZ_CHECK(strlen(m->name) == nl && !strncmp(m->name, text, nl));
	FUZZ_CHECK(lx_shadow_method_find(m->name) == m);
	FUZZ_CHECK(!m->build != !m->warp); /* a method builds its maps, or warps the uniform map */
	struct lx_scene scene;
	lx_scene_default(&scene);
	struct lx_region_request req[LX_ATLAS_MAX_REGIONS];
	int n = lx_shadow_method_regions(m, &scene, &o, req);
	FUZZ_CHECK(n >= 0 && n <= LX_ATLAS_MAX_REGIONS);
	FUZZ_CHECK(o.uniform_lixels == before.uniform_lixels && o.plane_lixels == before.plane_lixels &&
		   o.fallback_lixels == before.fallback_lixels);
	FUZZ_CHECK(o.plane_max_lpp == before.plane_max_lpp || o.plane_max_lpp == -1 ||
		   (o.plane_max_lpp > 0 && o.plane_max_lpp <= 1e4));
	if (strcmp(m->name, "plane"))
		FUZZ_CHECK(o.square_regions == before.square_regions && o.shared_budget == before.shared_budget &&
			   o.plane_twist == before.plane_twist && o.plane_one_piece == before.plane_one_piece &&
			   o.plane_max_lpp == before.plane_max_lpp);
}

static void check_mode(const char *text)
{
	int w = -7, h = -7, hz = -7;
	if (!lx_parse_mode(text, &w, &h, &hz))
		return;
	FUZZ_CHECK(w >= 1 && w <= 16384 && h >= 1 && h <= 16384 && hz >= 0 && hz <= 1000);
	char again[64];
	if (hz)
		snprintf(again, sizeof again, "%dx%d@%d", w, h, hz);
	else
		snprintf(again, sizeof again, "%dx%d", w, h);
	int w2, h2, hz2;
	FUZZ_CHECK(lx_parse_mode(again, &w2, &h2, &hz2) && w2 == w && h2 == h && hz2 == hz);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text = fuzz_text(data, size);
	check_spec(text);
	check_mode(text);
	free(text);
	return 0;
}
