/* The kiosk button's logic against a fake chip: edges with times, as a GPIO line or a
 * bouncing contact would give them. */
#include "button.h"
#include "test_util.h"

#define MS 1000000LL

/* Feeds a sequence of (level, time) edges, ticking every millisecond in between, and
 * counts the events. */
struct fake_chip {
	struct lx_button b;
	int64_t now;
	int shorts, longs;
};

static void count(struct fake_chip *c, enum lx_button_event e)
{
	c->shorts += e == LX_BUTTON_SHORT;
	c->longs += e == LX_BUTTON_LONG;
}

static void run_until(struct fake_chip *c, int64_t t)
{
	for (; c->now < t; c->now += MS)
		count(c, lx_button_tick(&c->b, c->now));
	c->now = t;
}

static void edge(struct fake_chip *c, bool level, int64_t t)
{
	run_until(c, t);
	count(c, lx_button_edge(&c->b, level, t));
}

static void start(struct fake_chip *c)
{
	/* active low with pull-up: released reads high */
	lx_button_init(&c->b, 30, 1000, true, true, 0);
	c->now = 0;
	c->shorts = c->longs = 0;
}

static void clean_press(void **state)
{
	(void)state;
	struct fake_chip c;
	start(&c);
	edge(&c, false, 100 * MS); /* press */
	edge(&c, true, 300 * MS);  /* release after 200 ms */
	run_until(&c, 500 * MS);
	assert_int_equal(c.shorts, 1);
	assert_int_equal(c.longs, 0);
}

static void bouncing_press_counts_once(void **state)
{
	(void)state;
	struct fake_chip c;
	start(&c);
	/* contact bounce: 6 edges within 5 ms at the press and at the release */
	int64_t t = 100 * MS;
	for (int i = 0; i < 6; i++)
		edge(&c, i % 2 == 1 ? true : false, t + i * MS);
	edge(&c, false, t + 6 * MS);
	t = 400 * MS;
	for (int i = 0; i < 6; i++)
		edge(&c, i % 2 == 0 ? true : false, t + i * MS);
	edge(&c, true, t + 6 * MS);
	run_until(&c, 800 * MS);
	assert_int_equal(c.shorts, 1);
	assert_int_equal(c.longs, 0);
}

static void glitch_shorter_than_debounce_is_ignored(void **state)
{
	(void)state;
	struct fake_chip c;
	start(&c);
	edge(&c, false, 100 * MS);
	edge(&c, true, 110 * MS); /* 10 ms < 30 ms */
	run_until(&c, 400 * MS);
	assert_int_equal(c.shorts + c.longs, 0);
}

static void long_press_fires_once_while_held(void **state)
{
	(void)state;
	struct fake_chip c;
	start(&c);
	edge(&c, false, 100 * MS);
	run_until(&c, 1099 * MS);
	assert_int_equal(c.longs, 0);
	run_until(&c, 1200 * MS); /* 1 s after the press: long */
	assert_int_equal(c.longs, 1);
	run_until(&c, 3000 * MS);
	edge(&c, true, 3000 * MS);
	run_until(&c, 3200 * MS);
	assert_int_equal(c.longs, 1);  /* once */
	assert_int_equal(c.shorts, 0); /* and the release is not also a short press */
}

static void flood_of_edges(void **state)
{
	(void)state;
	struct fake_chip c;
	start(&c);
	/* 20000 edges a second for half a second (a broken switch or noise on the line),
	 * then a clean level: at most one press comes out of it, and quickly */
	int64_t t = 100 * MS;
	for (int i = 0; i < 10000; i++)
		count(&c, lx_button_edge(&c.b, i % 2 == 1, t + i * 50000LL)); /* every 50 us */
	c.now = t + 10000 * 50000LL;
	edge(&c, true, c.now + 1000); /* settles released */
	run_until(&c, c.now + 100 * MS);
	assert_true(c.shorts <= 1);
	assert_int_equal(c.longs, 0);
	/* and the button still works afterwards */
	int before = c.shorts;
	edge(&c, false, c.now + 100 * MS);
	edge(&c, true, c.now + 200 * MS);
	run_until(&c, c.now + 100 * MS);
	assert_int_equal(c.shorts, before + 1);
}

static void active_high_and_kernel_debounce(void **state)
{
	(void)state;
	struct lx_button b;
	/* active high, debounce 0 (the kernel's, with libgpiod v2): edges count at once */
	lx_button_init(&b, 0, 1000, false, false, 0);
	assert_int_equal(lx_button_edge(&b, true, 10 * MS), LX_BUTTON_NONE);
	assert_int_equal(lx_button_edge(&b, false, 50 * MS), LX_BUTTON_NONE);
	assert_int_equal(lx_button_tick(&b, 50 * MS), LX_BUTTON_SHORT);
}

static void held_at_start_is_not_a_press(void **state)
{
	(void)state;
	struct lx_button b;
	lx_button_init(&b, 30, 1000, true, false, 0); /* pressed when the kiosk starts */
	assert_int_equal(lx_button_tick(&b, 2000 * MS), LX_BUTTON_NONE);
	assert_int_equal(lx_button_edge(&b, true, 2500 * MS), LX_BUTTON_NONE);
	assert_int_equal(lx_button_tick(&b, 2600 * MS), LX_BUTTON_NONE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(clean_press),
		cmocka_unit_test(bouncing_press_counts_once),
		cmocka_unit_test(glitch_shorter_than_debounce_is_ignored),
		cmocka_unit_test(long_press_fires_once_while_held),
		cmocka_unit_test(flood_of_edges),
		cmocka_unit_test(active_high_and_kernel_debounce),
		cmocka_unit_test(held_at_start_is_not_a_press),
	};
	return cmocka_run_group_tests_name("button", tests, NULL, NULL);
}
