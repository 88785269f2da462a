#include "depth_rgba.h"
#include "test_util.h"
#include <stdio.h>
#include <stdlib.h>

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

/* The mediump path with fp16 arithmetic emulated: all 2048 codes round-trip with both
 * conversions, the encoding is monotonic, far stays far, and the error is 11 bits. */
static void mediump_path_keeps_11_bits_in_fp16(void **state)
{
	(void)state;
	assert_near(lx_fp16(1.0f / 3.0f), 0.333251953125, 0); /* fp16's nearest to 1/3 */
	assert_near(lx_fp16(2049.0f), 2048.0f, 0);           /* only 11 significant bits */
	for (int conv = 0; conv < 2; conv++) {
		for (uint32_t q = 0; q < 2048; q++) {
			uint8_t px[4];
			double d = q / 2047.0;
			lx_depth_encode_rgba8_fp16(d, (enum lx_unorm_conversion)conv, px);
			uint32_t back = lx_depth_decode_code_fp16(px);
			if (back != lx_depth_code_fp16(d))
				fail_msg("q %u (%s): decoded %u, expected %u", q, conv ? "truncating" : "rounding", back,
					 lx_depth_code_fp16(d));
			/* the same texel read by the highp decoder is q * 8192 plus the low byte */
			assert_int_equal(lx_depth_decode_code(px) >> 13, back);
		}
		uint8_t px[4];
		lx_depth_encode_rgba8_fp16(1.0, (enum lx_unorm_conversion)conv, px);
		assert_int_equal(lx_depth_decode_code_fp16(px), 2047);
	}
	uint64_t s = 3;
	double worst = 0;
	uint32_t prev = 0;
	for (int i = 0; i <= 200000; i++) {
		double d = i / 200000.0;
		uint8_t px[4];
		lx_depth_encode_rgba8_fp16(d, LX_UNORM_TRUNCATE, px);
		uint32_t q = lx_depth_decode_code_fp16(px);
		assert_true(q >= prev);
		prev = q;
		double r = test_rand(&s);
		lx_depth_encode_rgba8_fp16(r, LX_UNORM_ROUND, px);
		worst = fmax(worst, fabs(lx_depth_decode_code_fp16(px) / 2047.0 - r));
	}
	print_message("fp16 mediump path: worst error %.3g, %.2f bits\n", worst, -log2(worst));
	assert_true(-log2(worst) >= 10.0);
}

/* The fp16 mirror itself: ties to even, overflow to infinity, denormals, and the divide
 * the main pass takes (true or through the reciprocal), which keeps 11 bits of a
 * projected depth: the code of z / w within one of the code of the depth. */
static void fp16_mirror_rounds_as_hardware_does(void **state)
{
	(void)state;
	assert_near(lx_fp16(2049.0f), 2048.0f, 0); /* a tie: to even */
	assert_near(lx_fp16(2051.0f), 2052.0f, 0); /* a tie: to even, upwards */
	assert_near(lx_fp16(65504.0f), 65504.0f, 0); /* the largest finite */
	assert_true(isinf(lx_fp16(65520.0f)) && lx_fp16(65520.0f) > 0); /* rounds past it */
	assert_true(isinf(lx_fp16(-1e6f)) && lx_fp16(-1e6f) < 0);
	assert_near(lx_fp16(ldexpf(1.0f, -24)), ldexpf(1.0f, -24), 0); /* the smallest denormal */
	assert_near(lx_fp16(ldexpf(1.0f, -26)), 0.0f, 0);               /* below half of it */
	assert_near(lx_fp16_div(1.0f, 3.0f), 0.333251953125, 0);
	assert_true(isinf(lx_fp16_div(1.0f, 1e-5f)) || lx_fp16_div(1.0f, 1e-5f) > 65000.0f);
	int worst = 0;
	uint64_t seed = 3;
	for (int k = 0; k < 200000; k++) {
		double d = test_rand(&seed), w = 0.05 + 40 * test_rand(&seed); /* q in a map's range */
		float z = (float)(d * w);
		int direct = (int)lx_depth_code_fp16(d);
		for (int rcp = 0; rcp < 2; rcp++) {
			int got = (int)lx_depth_code_fp16_projected(z, (float)w, rcp);
			worst = abs(got - direct) > worst ? abs(got - direct) : worst;
		}
	}
	print_message("fp16 projected depth: the code within %d of the direct one (11-bit codes)\n", worst);
	assert_true(worst <= 2);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(every_code_round_trips_with_both_conversions),
		cmocka_unit_test(random_depths_error_in_bits),
		cmocka_unit_test(far_plane_encodes_as_far_never_zero),
		cmocka_unit_test(encoding_is_monotonic),
		cmocka_unit_test(mediump_path_keeps_11_bits_in_fp16),
		cmocka_unit_test(fp16_mirror_rounds_as_hardware_does),
	};
	return cmocka_run_group_tests_name("depth_rgba", tests, NULL, NULL);
}
