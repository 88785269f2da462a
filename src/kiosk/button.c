#include "button.h"

void lx_button_init(struct lx_button *b, int debounce_ms, int long_press_ms, bool active_low, bool level_now,
		    int64_t now_ns)
{
	*b = (struct lx_button){.debounce_ns = (int64_t)(debounce_ms < 0 ? 0 : debounce_ms) * 1000000,
				.long_ns = (int64_t)(long_press_ms < 1 ? 1 : long_press_ms) * 1000000,
				.active_low = active_low, .raw = level_now, .raw_since = now_ns};
	b->pressed = level_now != active_low;
	b->press_start = now_ns;
	b->long_reported = b->pressed; /* a button held at start is not a new press */
}

/* Commits the raw level if it has settled by t; reports a short press on release. */
static enum lx_button_event settle(struct lx_button *b, int64_t t)
{
	bool down = b->raw != b->active_low;
	if (down == b->pressed || t - b->raw_since < b->debounce_ns)
		return LX_BUTTON_NONE;
	b->pressed = down;
	if (down) {
		b->press_start = b->raw_since;
		b->long_reported = false;
		return LX_BUTTON_NONE;
	}
	return b->long_reported ? LX_BUTTON_NONE : LX_BUTTON_SHORT;
}

static enum lx_button_event held(struct lx_button *b, int64_t t)
{
	if (b->pressed && !b->long_reported && t - b->press_start >= b->long_ns) {
		b->long_reported = true;
		return LX_BUTTON_LONG;
	}
	return LX_BUTTON_NONE;
}

enum lx_button_event lx_button_edge(struct lx_button *b, bool level_high, int64_t t_ns)
{
	/* the level before this edge may have settled in the meantime */
	enum lx_button_event e = settle(b, t_ns);
	if (e == LX_BUTTON_NONE)
		e = held(b, t_ns);
	b->raw = level_high;
	b->raw_since = t_ns;
	return e;
}

enum lx_button_event lx_button_tick(struct lx_button *b, int64_t t_ns)
{
	enum lx_button_event e = settle(b, t_ns);
	return e != LX_BUTTON_NONE ? e : held(b, t_ns);
}
