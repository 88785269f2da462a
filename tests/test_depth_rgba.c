#include "depth_rgba.h"
#include "test_util.h"
#include <stdio.h>

/* Every 24-bit code survives encode -> 8-bit conversion -> decode, whether the driver
 * rounds or truncates, and the decoded depth is within one code of the input. */
static void every_code_round_trips_with_both_conversions(void **state)
{
	(void)state;
	double worst = 0;
	for (int conv = 0; conv < 2; conv++)
		for (uint32_t n = 0; n <= LX_DEPTH_MAX_CODE; n += (n < 70000 || n > LX_DEPTH_MAX_CODE - 70000) ? 1 : 97) {
			double d = n / (double)LX_DEPTH_MAX_CODE;
			uint8_t px[4];
			lx_depth_encode_rgba8(d, (enum lx_unorm_conversion)conv, px);
			uint32_t back = lx_depth_decode_code(px);
			if (back != lx_depth_code(d))
				fail_msg("code %u (d = %.10f, %s): decoded %u", n, d, conv ? "truncating" : "rounding", back);
			double err = fabs(lx_depth_decode_rgba8(px) - d);
			if (err > worst)
				worst = err;
			assert_int_equal(px[3], 255);
		}
	/* one code is 2^-24 of the range: the error must stay within it */
	assert_true(worst <= 1.0 / LX_DEPTH_MAX_CODE + 1e-15);
	print_message("codes 0..2^24-1: worst decode error %.3g of the depth range (%.2f codes)\n", worst,
		      worst * LX_DEPTH_MAX_CODE);
}

static void random_depths_error_in_bits(void **state)
{
	(void)state;
	uint64_t s = 7;
	double worst = 0;
	for (int i = 0; i < 2000000; i++) {
		double d = test_rand(&s);
		uint8_t px[4];
		lx_depth_encode_rgba8(d, i & 1 ? LX_UNORM_TRUNCATE : LX_UNORM_ROUND, px);
		double err = fabs(lx_depth_decode_rgba8(px) - d);
		worst = err > worst ? err : worst;
	}
	double bits = -log2(worst);
	print_message("random depths: worst error %.3g, %.2f bits exact\n", worst, bits);
	assert_true(bits >= 23.0);
}

static void far_plane_encodes_as_far_never_zero(void **state)
{
	(void)state;
	uint8_t px[4];
	for (int conv = 0; conv < 2; conv++) {
		lx_depth_encode_rgba8(1.0, (enum lx_unorm_conversion)conv, px);
		assert_int_equal(lx_depth_decode_code(px), LX_DEPTH_MAX_CODE);
		assert_near(lx_depth_decode_rgba8(px), 1.0, 0);
		lx_depth_encode_rgba8(1.5, (enum lx_unorm_conversion)conv, px);
		assert_int_equal(lx_depth_decode_code(px), LX_DEPTH_MAX_CODE);
		lx_depth_encode_rgba8(NAN, (enum lx_unorm_conversion)conv, px);
		assert_int_equal(lx_depth_decode_code(px), LX_DEPTH_MAX_CODE);
		lx_depth_encode_rgba8(-0.5, (enum lx_unorm_conversion)conv, px);
		assert_int_equal(lx_depth_decode_code(px), 0);
		/* just below 1.0 stays below far, and never wraps */
		lx_depth_encode_rgba8(1.0 - 1e-7, (enum lx_unorm_conversion)conv, px);
		assert_true(lx_depth_decode_code(px) >= LX_DEPTH_MAX_CODE - 3);
	}
	/* the atlas clear colour (1, 1, 1, 1) reads as far */
	const uint8_t clear[4] = {255, 255, 255, 255};
	assert_int_equal(lx_depth_decode_code(clear), LX_DEPTH_MAX_CODE);
}

static void encoding_is_monotonic(void **state)
{
	(void)state;
	uint32_t prev = 0;
	for (int i = 0; i <= 1000000; i++) {
		uint8_t px[4];
		lx_depth_encode_rgba8(i / 1e6, LX_UNORM_TRUNCATE, px);
		uint32_t c = lx_depth_decode_code(px);
		assert_true(c >= prev);
		prev = c;
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(every_code_round_trips_with_both_conversions),
		cmocka_unit_test(random_depths_error_in_bits),
		cmocka_unit_test(far_plane_encodes_as_far_never_zero),
		cmocka_unit_test(encoding_is_monotonic),
	};
	return cmocka_run_group_tests_name("depth_rgba", tests, NULL, NULL);
}
