/* Board profiles: what the kiosk needs to know of a board (the GPIO button, the display,
 * the lixel budgets, the order of methods the button cycles through, and the shadow
 * filters it cycles through within each method), as small text
 * files in board/ built into the binary; --board NAME|FILE. GL-free. */
#ifndef LX_BOARD_H
#define LX_BOARD_H
#include "depth_selftest.h"
#include "shadow_method.h"
#include "shadow_filter.h"
#include <stdbool.h>
#include <stddef.h>

#define LX_BOARD_MAX_METHODS 8

enum lx_bias { LX_BIAS_AS_IS, LX_BIAS_PULL_UP, LX_BIAS_PULL_DOWN, LX_BIAS_DISABLED };

struct lx_board {
	char name[32];
	char description[96];
	char gpio_chip[64]; /* a name (gpiochip0), a path (/dev/gpiochip0), a label (pinctrl-rp1) or
			     * auto (any chip: with gpio_line_name); empty: no button */
	int gpio_line;      /* the line's offset, or -1 when named */
	char gpio_line_name[32]; /* the line's name (GPIO17), or empty: by offset */
	bool active_low;
	enum lx_bias bias;
	int debounce_ms, long_press_ms;
	char display[128]; /* a DRM device path, or empty for the first that can mode-set */
	int mode_w, mode_h, mode_hz; /* 0: the connector's preferred mode / any refresh */
	struct lx_method_options lixels;
	enum lx_depth_precision depth_precision; /* auto: the start-up self-test decides */
	int method_count;
	char methods[LX_BOARD_MAX_METHODS][16];
	/* the filters the button steps through within each method, the first to start
	 * with (default none alone: a press goes to the next method) */
	int filter_count;
	enum lx_filter filters[LX_FILTER_COUNT];
};

void lx_board_defaults(struct lx_board *b);
/* Parses a profile over the defaults; on error false with "FILE:LINE: what was expected". */
bool lx_board_parse(const char *text, const char *file, struct lx_board *b, char *err, size_t errlen);
/* The same line by line without the check that the lines agree (a gpio-chip needs a
 * line): for overrides given one at a time, checked together with lx_board_check. */
bool lx_board_apply(const char *text, const char *file, struct lx_board *b, char *err, size_t errlen);
bool lx_board_check(const struct lx_board *b, const char *file, int line, char *err, size_t errlen);
/* A built-in profile by name (board/NAME.profile), else a file. */
bool lx_board_load(const char *name_or_path, struct lx_board *b, char *err, size_t errlen);
/* The built-in profiles' names, separated by ", ". */
const char *lx_board_names(void);
/* Parses WxH or WxH@HZ; false when malformed. */
bool lx_parse_mode(const char *s, int *w, int *h, int *hz);

#endif
