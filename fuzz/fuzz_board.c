/* libFuzzer harness: board profiles (lx_board_parse over the defaults, and lx_board_apply,
 * the same lines without the final check, on a fresh default board). A profile that
 * parses must give a board whose every field is in its documented range, and parse and
 * apply must agree: parse succeeds exactly when apply does and the board then passes
 * lx_board_check. */
#include "board.h"
#include "fuzz_util.h"

static int terminated(const char *s, size_t n) { return memchr(s, 0, n) != NULL; }

static void check_board(const struct lx_board *b)
{
	FUZZ_CHECK(terminated(b->name, sizeof b->name) && terminated(b->description, sizeof b->description));
	FUZZ_CHECK(terminated(b->gpio_chip, sizeof b->gpio_chip) && terminated(b->display, sizeof b->display));
	FUZZ_CHECK(terminated(b->gpio_line_name, sizeof b->gpio_line_name));
	FUZZ_CHECK(b->gpio_line >= -1 && b->gpio_line <= 1023);
	FUZZ_CHECK(!(b->gpio_line >= 0 && b->gpio_line_name[0])); /* by offset or by name, not both */
	FUZZ_CHECK(b->bias >= LX_BIAS_AS_IS && b->bias <= LX_BIAS_DISABLED);
	FUZZ_CHECK(b->debounce_ms >= 0 && b->debounce_ms <= 1000);
	FUZZ_CHECK(b->long_press_ms >= 100 && b->long_press_ms <= 10000);
	if (b->mode_w == 0)
		FUZZ_CHECK(b->mode_h == 0 && b->mode_hz == 0);
	else
		FUZZ_CHECK(b->mode_w >= 1 && b->mode_w <= 16384 && b->mode_h >= 1 && b->mode_h <= 16384 &&
			   b->mode_hz >= 0 && b->mode_hz <= 1000);
	FUZZ_CHECK(b->lixels.plane_lixels >= 1 && b->lixels.plane_lixels <= 8192);
	FUZZ_CHECK(b->lixels.fallback_lixels >= 1 && b->lixels.fallback_lixels <= 8192);
	FUZZ_CHECK(b->lixels.uniform_lixels >= 1 && b->lixels.uniform_lixels <= 8192);
	FUZZ_CHECK(b->depth_precision == LX_DEPTH_AUTO || b->depth_precision == LX_DEPTH_HIGHP ||
		   b->depth_precision == LX_DEPTH_MEDIUMP);
	FUZZ_CHECK(b->method_count >= 1 && b->method_count <= LX_BOARD_MAX_METHODS);
	for (int i = 0; i < b->method_count; i++) {
		FUZZ_CHECK(terminated(b->methods[i], sizeof b->methods[i]));
		FUZZ_CHECK(lx_shadow_method_find(b->methods[i]) != NULL);
	}
	FUZZ_CHECK(b->filter_count >= 1 && b->filter_count <= LX_FILTER_COUNT);
	for (int i = 0; i < b->filter_count; i++) /* known, and each once */
		for (int j = 0; j <= i; j++)
			FUZZ_CHECK((unsigned)b->filters[i] < LX_FILTER_COUNT && (j == i || b->filters[j] != b->filters[i]));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text = fuzz_text(data, size);
	struct lx_board parsed, applied;
	char err[256], err2[256];
	memset(err, 0x55, sizeof err);
	memset(err2, 0x55, sizeof err2);
	lx_board_defaults(&parsed);
	bool parse_ok = lx_board_parse(text, "fuzz.profile", &parsed, err, sizeof err);
	if (parse_ok)
		check_board(&parsed);
	else
		fuzz_check_error(err, sizeof err, "fuzz.profile");

	lx_board_defaults(&applied);
	bool apply_ok = lx_board_apply(text, "fuzz.profile", &applied, err2, sizeof err2);
	if (apply_ok) {
		check_board(&applied);
		char err3[256];
		FUZZ_CHECK(parse_ok == lx_board_check(&applied, "fuzz.profile", 1, err3, sizeof err3));
	} else {
		fuzz_check_error(err2, sizeof err2, "fuzz.profile");
		FUZZ_CHECK(!parse_ok);
		FUZZ_CHECK(!strcmp(err, err2)); /* the same line fails the same way */
	}
	free(text);
	return 0;
}
