#include "board.h"
#include "embedded.h"
#include "number.h"
#include "text_lines.h"
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void lx_board_defaults(struct lx_board *b)
{
	memset(b, 0, sizeof(*b));
	snprintf(b->name, sizeof b->name, "custom");
	b->gpio_line = -1;
	b->active_low = true;
	b->bias = LX_BIAS_PULL_UP;
	b->debounce_ms = 30;
	b->long_press_ms = 1000;
	b->lixels = LX_METHOD_OPTIONS_DEFAULT;
	b->filter_count = 1; /* none */
	/* the kiosk's default order: the default method, the others as the registry lists
	 * them, the baseline (none) last */
	snprintf(b->methods[b->method_count++], sizeof b->methods[0], "%s", LX_DEFAULT_METHOD);
	for (int pass = 0; pass < 2; pass++)
		for (int i = 0; i < lx_shadow_method_count() && b->method_count < LX_BOARD_MAX_METHODS; i++) {
			const char *name = lx_shadow_method_at(i)->name;
			if (strcmp(name, LX_DEFAULT_METHOD) && !strcmp(name, "none") == (pass == 1))
				snprintf(b->methods[b->method_count++], sizeof b->methods[0], "%s", name);
		}
}

static bool fail(char *err, size_t errlen, const char *file, int line, const char *fmt, ...)
{
	char msg[256];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	snprintf(err, errlen, "%s:%d: %s", file, line, msg);
	return false;
}

static bool whole(const char *s, int lo, int hi, int *out)
{
	return lx_number_int(s, lo, hi, out) == LX_NUMBER_OK;
}

bool lx_parse_mode(const char *s, int *w, int *h, int *hz)
{
	char buf[64];
	if (strlen(s) >= sizeof buf)
		return false;
	strcpy(buf, s);
	char *at = strchr(buf, '@'), *x = strchr(buf, 'x');
	*hz = 0;
	if (at) {
		*at = 0;
		if (!whole(at + 1, 1, 1000, hz))
			return false;
	}
	if (!x)
		return false;
	*x = 0;
	return whole(buf, 1, 16384, w) && whole(x + 1, 1, 16384, h);
}

static bool parse_lines(const char *text, const char *file, struct lx_board *b, int *last, char *err, size_t errlen);

bool lx_board_check(const struct lx_board *b, const char *file, int line, char *err, size_t errlen)
{
	if (b->gpio_chip[0] && b->gpio_line < 0 && !b->gpio_line_name[0])
		return fail(err, errlen, file, line, "expected a gpio-line or gpio-line-name for gpio-chip %s", b->gpio_chip);
	return true;
}

bool lx_board_apply(const char *text, const char *file, struct lx_board *b, char *err, size_t errlen)
{
	int last = 0;
	return parse_lines(text, file, b, &last, err, errlen);
}

bool lx_board_parse(const char *text, const char *file, struct lx_board *b, char *err, size_t errlen)
{
	int last = 0;
	return parse_lines(text, file, b, &last, err, errlen) && lx_board_check(b, file, last + 1, err, errlen);
}

/* Where a profile line is: the file, the line, the message buffer. */
struct at {
	const char *file;
	int line;
	char *err;
	size_t errlen;
};
#define FAIL(at, ...) fail((at)->err, (at)->errlen, (at)->file, (at)->line, __VA_ARGS__)

/* A key whose value is a text of at most cap - 1 characters (value, vl long) kept in
 * dst; the word `unset` (where not NULL) keeps the empty text. 1, or 0 after the error. */
static int text_key(char *dst, size_t cap, const char *value, size_t vl, const char *unset, const char *what,
		    const struct at *at)
{
	if (vl >= cap)
		return FAIL(at, "expected %s of at most %zu characters", what, cap - 1);
	strcpy(dst, unset && !strcmp(value, unset) ? "" : value);
	return 1;
}

/* The button's keys: 1 taken, 0 after the error, -1 not one of them. */
static int button_key(struct lx_board *b, const char *key, const char *value, size_t vl, const struct at *at)
{
	enum lx_number_error e;
	if (!strcmp(key, "gpio-line")) {
		if ((e = lx_number_int(value, 0, 1023, &b->gpio_line)))
			return FAIL(at, "expected a line offset from 0 to 1023, got '%s' (%s)", value, lx_number_why(e));
		b->gpio_line_name[0] = 0; /* the last of gpio-line and gpio-line-name counts */
	} else if (!strcmp(key, "gpio-line-name")) {
		if (vl >= sizeof b->gpio_line_name || !vl)
			return FAIL(at, "expected a line name of 1 to %zu characters", sizeof b->gpio_line_name - 1);
		strcpy(b->gpio_line_name, value);
		b->gpio_line = -1;
	} else if (!strcmp(key, "gpio-active")) {
		if (strcmp(value, "low") && strcmp(value, "high"))
			return FAIL(at, "expected gpio-active low or high, got '%s'", value);
		b->active_low = !strcmp(value, "low");
	} else if (!strcmp(key, "gpio-bias")) {
		static const char *const names[] = {"as-is", "pull-up", "pull-down", "disabled"};
		int k = 0;
		while (k < 4 && strcmp(value, names[k]))
			k++;
		if (k == 4)
			return FAIL(at, "expected gpio-bias as-is, pull-up, pull-down or disabled, got '%s'", value);
		b->bias = (enum lx_bias)k;
	} else if (!strcmp(key, "debounce-ms")) {
		if ((e = lx_number_int(value, 0, 1000, &b->debounce_ms)))
			return FAIL(at, "expected debounce-ms from 0 to 1000, got '%s' (%s)", value, lx_number_why(e));
	} else if (!strcmp(key, "long-press-ms")) {
		if ((e = lx_number_int(value, 100, 10000, &b->long_press_ms)))
			return FAIL(at, "expected long-press-ms from 100 to 10000, got '%s' (%s)", value, lx_number_why(e));
	} else
		return -1;
	return 1;
}

/* The display and the maps' keys: 1 taken, 0 after the error, -1 not one of them. */
static int display_key(struct lx_board *b, const char *key, const char *value, const struct at *at)
{
	enum lx_number_error e;
	if (!strcmp(key, "mode")) {
		if (!strcmp(value, "preferred"))
			b->mode_w = b->mode_h = b->mode_hz = 0;
		else if (!lx_parse_mode(value, &b->mode_w, &b->mode_h, &b->mode_hz))
			return FAIL(at, "expected mode preferred, WxH or WxH@HZ, got '%s'", value);
	} else if (!strcmp(key, "plane-lixels") || !strcmp(key, "fallback-lixels") || !strcmp(key, "uniform-lixels")) {
		int *field = key[0] == 'p' ? &b->lixels.plane_lixels : key[0] == 'f' ? &b->lixels.fallback_lixels
										     : &b->lixels.uniform_lixels;
		if ((e = lx_number_int(value, 1, 8192, field)))
			return FAIL(at, "expected %s from 1 to 8192, got '%s' (%s)", key, value, lx_number_why(e));
	} else if (!strcmp(key, "light-budget")) {
		if (!lx_light_budget_parse(value, &b->lixels))
			return FAIL(at, "expected light-budget as %s, got '%s'", LX_LIGHT_BUDGET_EXPECTED, value);
	} else if (!strcmp(key, "depth-precision")) {
		if (!lx_depth_precision_parse(value, &b->depth_precision))
			return FAIL(at, "expected depth-precision auto, highp, mediump or texture, got '%s'", value);
	} else
		return -1;
	return 1;
}

/* methods A,B,...: known names, single commas, at least one. */
static bool methods_key(struct lx_board *b, const char *value, const struct at *at)
{
	b->method_count = 0;
	const char *rest = value;
	char t[64];
	for (int r; (r = lx_list_next(&rest, ',', t, sizeof t)) != 0;) {
		if (r < 0)
			return FAIL(at, "expected method names separated by single commas, got '%s'", value);
		const struct lx_shadow_method *m = lx_shadow_method_find(t);
		if (!m)
			return FAIL(at, "expected methods from %s, got '%s'", lx_shadow_method_names(), t);
		if (b->method_count == LX_BOARD_MAX_METHODS)
			return FAIL(at, "expected at most %d methods", LX_BOARD_MAX_METHODS);
		snprintf(b->methods[b->method_count++], sizeof b->methods[0], "%s", m->name);
	}
	if (b->method_count == 0) /* "methods ," would leave the kiosk nothing to draw */
		return FAIL(at, "expected at least one method from %s", lx_shadow_method_names());
	return true;
}

/* filters A,B,...: known filters, each once, single commas, at least one. */
static bool filters_key(struct lx_board *b, const char *value, const struct at *at)
{
	b->filter_count = 0;
	const char *rest = value;
	char t[64];
	for (int r; (r = lx_list_next(&rest, ',', t, sizeof t)) != 0;) {
		enum lx_filter f;
		if (r < 0)
			return FAIL(at, "expected filter names separated by single commas, got '%s'", value);
		if (!lx_filter_parse(t, &f))
			return FAIL(at, "expected filters from %s, got '%s'", lx_filter_names(), t);
		for (int k = 0; k < b->filter_count; k++)
			if (b->filters[k] == f)
				return FAIL(at, "expected each filter once, got '%s' twice", t);
		b->filters[b->filter_count++] = f; /* at most LX_FILTER_COUNT distinct */
	}
	if (b->filter_count == 0)
		return FAIL(at, "expected at least one filter from %s", lx_filter_names());
	return true;
}

/* One "KEY VALUE" line, the value trimmed. */
static bool apply_key(struct lx_board *b, const char *key, const char *value, size_t vl, const struct at *at)
{
	if (!strcmp(key, "name"))
		return text_key(b->name, sizeof b->name, value, vl, NULL, "a name", at);
	if (!strcmp(key, "gpio-chip"))
		return text_key(b->gpio_chip, sizeof b->gpio_chip, value, vl, "none", "a chip name or path", at);
	if (!strcmp(key, "display"))
		return text_key(b->display, sizeof b->display, value, vl, "auto", "a device path", at);
	if (!strcmp(key, "description")) {
		snprintf(b->description, sizeof b->description, "%s", value);
		return true;
	}
	int r;
	if ((r = button_key(b, key, value, vl, at)) >= 0 || (r = display_key(b, key, value, at)) >= 0)
		return r;
	if (!strcmp(key, "methods"))
		return methods_key(b, value, at);
	if (!strcmp(key, "filters"))
		return filters_key(b, value, at);
	return FAIL(at, "expected name, description, gpio-chip, gpio-line, gpio-line-name, gpio-active, gpio-bias, "
		    "debounce-ms, long-press-ms, display, mode, plane-lixels, fallback-lixels, uniform-lixels, "
		    "light-budget, depth-precision, methods or filters, got '%s'", key);
}

static bool parse_lines(const char *text, const char *file, struct lx_board *b, int *last, char *err, size_t errlen)
{
	struct at at = {file, 0, err, errlen};
	char buf[512];
	for (int r; (r = lx_text_line(&text, buf, sizeof buf)) != 0;) {
		at.line++;
		if (r < 0)
			return FAIL(&at, "expected a line shorter than %zu characters", sizeof buf);
		char *key = strtok(buf, " \t\r");
		if (!key)
			continue;
		char *value = strtok(NULL, "\r\n");
		while (value && (*value == ' ' || *value == '\t'))
			value++;
		if (!value || !*value)
			return FAIL(&at, "expected a value after '%s'", key);
		size_t vl = strlen(value);
		while (vl && (value[vl - 1] == ' ' || value[vl - 1] == '\t'))
			value[--vl] = 0;
		if (!apply_key(b, key, value, vl, &at))
			return false;
	}
	*last = at.line;
	return true;
}

bool lx_board_load(const char *name_or_path, struct lx_board *b, char *err, size_t errlen)
{
	lx_board_defaults(b);
	char file[96];
	snprintf(file, sizeof file, "%s.profile", name_or_path);
	const char *text = strchr(name_or_path, '/') ? NULL : lx_embedded_text(lx_board_files, file);
	if (text)
		return lx_board_parse(text, file, b, err, errlen);
	FILE *f = fopen(name_or_path, "rb");
	if (!f) {
		snprintf(err, errlen, "%s: no such built-in board (%s) and cannot open it as a file: %s", name_or_path,
			 lx_board_names(), strerror(errno));
		return false;
	}
	char buf[16384];
	size_t n = fread(buf, 1, sizeof buf - 1, f);
	bool too_long = !feof(f);
	fclose(f);
	if (too_long) {
		snprintf(err, errlen, "%s: expected a board profile under 16 KiB", name_or_path);
		return false;
	}
	buf[n] = 0;
	if (memchr(buf, 0, n)) {
		snprintf(err, errlen, "%s:1: expected a text file, found a NUL byte", name_or_path);
		return false;
	}
	return lx_board_parse(buf, name_or_path, b, err, errlen);
}

const char *lx_board_names(void)
{
	static char names[512];
	if (!names[0])
		for (const struct lx_embedded_file *f = lx_board_files; f->name; f++) {
			size_t l = strlen(names);
			snprintf(names + l, sizeof names - l, "%s%.*s", l ? ", " : "", (int)(strlen(f->name) - 8), f->name);
		}
	return names;
}
