/* lx_run_order: the bench's schedule of runs, round after round. */
#include "test_util.h"
#include "run_order.h"
#include <string.h>

/* The names of `rounds` rounds of the runs names[0, n), listed in that order, into out
 * (rounds x n). */
static void schedule(const char *const *names, int n, int rounds, const char **out)
{
	unsigned long long seq = LX_RUN_ORDER_SEED;
	for (int r = 0; r < rounds; r++) {
		int order[LX_RUN_ORDER_MAX];
		lx_run_order(names, n, &seq, order);
		for (int k = 0; k < n; k++)
			out[r * n + k] = names[order[k]];
	}
}

/* The runs of results.md's bench, by their labels. */
static const char *const twelve[12] = {"none", "uniform", "psm", "lispsm", "tsm", "plane", "plane/square",
				       "plane/shared", "plane/lpp1", "plane/twist", "plane/onepiece", "plane/similar"};

/* Every round is a permutation of the runs. */
static void each_round_runs_each_once(void **state)
{
	(void)state;
	unsigned long long seq = LX_RUN_ORDER_SEED;
	for (int r = 0; r < 20; r++) {
		int order[LX_RUN_ORDER_MAX], seen[12] = {0};
		lx_run_order(twelve, 12, &seq, order);
		for (int k = 0; k < 12; k++) {
			assert_in_range(order[k], 0, 11);
			seen[order[k]]++;
		}
		for (int k = 0; k < 12; k++)
			assert_int_equal(seen[k], 1);
	}
}

/* The order of --methods changes nothing: every listing of the same runs gives the same
 * names in the same places, round after round (all six listings of three runs, and
 * reversed and rotated listings of twelve). */
static void listing_order_changes_nothing(void **state)
{
	(void)state;
	const char *three[6][3] = {{"none", "uniform", "plane"}, {"none", "plane", "uniform"},
				   {"uniform", "none", "plane"}, {"uniform", "plane", "none"},
				   {"plane", "none", "uniform"}, {"plane", "uniform", "none"}};
	const char *first[5 * 3], *other[5 * 3];
	schedule(three[0], 3, 5, first);
	for (int l = 1; l < 6; l++) {
		schedule(three[l], 3, 5, other);
		for (int k = 0; k < 15; k++)
			assert_string_equal(first[k], other[k]);
	}
	const char *listed[12], *a[5 * 12], *b[5 * 12];
	schedule(twelve, 12, 5, a);
	for (int shift = 1; shift < 12; shift++) {
		for (int k = 0; k < 12; k++) /* reversed, then rotated */
			listed[k] = twelve[(11 - k + shift) % 12];
		schedule(listed, 12, 5, b);
		for (int k = 0; k < 60; k++)
			assert_string_equal(a[k], b[k]);
	}
}

/* A fresh order each round: over five rounds of three runs, more than one run goes
 * first, and no run always follows the same one. */
static void rounds_take_fresh_orders(void **state)
{
	(void)state;
	const char *names[3] = {"none", "uniform", "plane"}, *s[5 * 3];
	schedule(names, 3, 5, s);
	int firsts = 0;
	for (int r = 1; r < 5; r++)
		firsts += strcmp(s[r * 3], s[0]) != 0;
	assert_true(firsts > 0);
	for (int m = 0; m < 3; m++) { /* run m's predecessors within rounds */
		const char *pred = NULL;
		bool same = true;
		int seen = 0;
		for (int r = 0; r < 5; r++)
			for (int k = 1; k < 3; k++)
				if (!strcmp(s[r * 3 + k], names[m])) {
					same &= !pred || !strcmp(pred, s[r * 3 + k - 1]);
					pred = s[r * 3 + k - 1], seen++;
				}
		assert_true(seen < 2 || !same);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(each_round_runs_each_once),
		cmocka_unit_test(listing_order_changes_nothing),
		cmocka_unit_test(rounds_take_fresh_orders),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
