/* The kiosk's push button as a state machine, GL-free and hardware-free: it is fed the
 * line's edges (level and time) and the passing of time, and answers with short and long
 * presses. The GPIO backend (gpio_button.c) and the tests' fake chip both feed it.
 *
 * Debounce: a level counts only once it has held for debounce_ms with no further edge
 * (0 when the kernel debounces, as libgpiod v2 can). A press ends as a short press when
 * released before long_press_ms; held that long, it is a long press (reported once, while
 * still held). Work per edge is constant, so a flood of edges costs nothing but time. */
#ifndef LX_BUTTON_H
#define LX_BUTTON_H
#include <stdbool.h>
#include <stdint.h>

enum lx_button_event { LX_BUTTON_NONE, LX_BUTTON_SHORT, LX_BUTTON_LONG };

struct lx_button {
	int64_t debounce_ns, long_ns;
	bool active_low;
	bool raw;             /* line level after the last edge (true = high) */
	int64_t raw_since;    /* time of the last edge */
	bool pressed;         /* debounced state */
	int64_t press_start;  /* when the debounced press began (its first edge) */
	bool long_reported;
};

void lx_button_init(struct lx_button *b, int debounce_ms, int long_press_ms, bool active_low, bool level_now,
		    int64_t now_ns);
/* One edge: the line's level after it, at t_ns (non-decreasing). May complete a press
 * whose release settled before this edge. */
enum lx_button_event lx_button_edge(struct lx_button *b, bool level_high, int64_t t_ns);
/* Time passes with no edge: commits a settled level, reports a long press. Call it at
 * least every few milliseconds while the button is pressed or bouncing. */
enum lx_button_event lx_button_tick(struct lx_button *b, int64_t t_ns);

#endif
