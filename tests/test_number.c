/* The one number parser (src/base/number.c): decimal only, the whole token, ranges, and the
 * reason a value was refused. */
#include "number.h"
#include "test_util.h"
#include <float.h>

static void decimal_numbers_parse(void **state)
{
	(void)state;
	static const struct { const char *s; double v; } good[] = {
		{"1", 1}, {"-2.5", -2.5}, {".5", 0.5}, {"5.", 5}, {"1e3", 1000}, {"1E-3", 1e-3}, {"-0", 0},
		{"2.5e+2", 250}, {"0.000", 0}, {"1e308", 1e308}, {"2.2250738585072014e-308", DBL_MIN}};
	for (size_t i = 0; i < sizeof good / sizeof good[0]; i++) {
		double v = -99;
		assert_int_equal(lx_number_real(good[i].s, -DBL_MAX, DBL_MAX, &v), LX_NUMBER_OK);
		assert_true(v == good[i].v);
	}
	double z = -99;
	assert_int_equal(lx_number_real("-0", -1, 1, &z), LX_NUMBER_OK);
	assert_false(signbit(z)); /* no negative zero reaches the geometry */
}

static void anything_else_is_refused(void **state)
{
	(void)state;
	static const char *const bad[] = {"",	 " 1",	"1 ",  "\t1", "1\n", "+1",   "0x10", "0X1p3", "inf", "-inf", "nan",
					  "1e",  "1e+", ".",   "-",   "--1", "1..2", "1.2.3", "1,5",  "1e5.5", "e5",  "１",
					  "1f",  "5\nmethods none"};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		double v = 7;
		assert_int_equal(lx_number_real(bad[i], -DBL_MAX, DBL_MAX, &v), LX_NUMBER_NOT_DECIMAL);
		assert_true(v == 7); /* not written */
	}
	assert_int_equal(lx_number_real(NULL, 0, 1, &(double){0}), LX_NUMBER_NOT_DECIMAL);
}

static void overflow_underflow_and_range_say_which(void **state)
{
	(void)state;
	double v;
	assert_int_equal(lx_number_real("1e400", -DBL_MAX, DBL_MAX, &v), LX_NUMBER_OVERFLOW);
	assert_int_equal(lx_number_real("-1e309", -DBL_MAX, DBL_MAX, &v), LX_NUMBER_OVERFLOW);
	assert_int_equal(lx_number_real("1e-400", -DBL_MAX, DBL_MAX, &v), LX_NUMBER_UNDERFLOW);
	assert_int_equal(lx_number_real("4e-320", -DBL_MAX, DBL_MAX, &v), LX_NUMBER_UNDERFLOW); /* subnormal */
	assert_int_equal(lx_number_real("1e-300", -DBL_MAX, DBL_MAX, &v), LX_NUMBER_OK);
	assert_int_equal(lx_number_real("0e-400", -1, 1, &v), LX_NUMBER_OK);
	assert_int_equal(lx_number_real("180.0001", 0, 180, &v), LX_NUMBER_OUT_OF_RANGE);
	assert_int_equal(lx_number_real("180", 0, 180, &v), LX_NUMBER_OK);
	assert_string_equal(lx_number_why(LX_NUMBER_OVERFLOW), "too large to hold");
	assert_string_equal(lx_number_why(LX_NUMBER_OK), "");
}

static void whole_numbers(void **state)
{
	(void)state;
	long l;
	int i = 3;
	assert_int_equal(lx_number_whole("42", 0, 100, &l), LX_NUMBER_OK);
	assert_int_equal(l, 42);
	assert_int_equal(lx_number_whole("-7", -10, 10, &l), LX_NUMBER_OK);
	assert_int_equal(l, -7);
	assert_int_equal(lx_number_whole("4.0", 0, 100, &l), LX_NUMBER_NOT_DECIMAL);
	assert_int_equal(lx_number_whole("1e2", 0, 1000, &l), LX_NUMBER_NOT_DECIMAL);
	assert_int_equal(lx_number_whole(" 4", 0, 100, &l), LX_NUMBER_NOT_DECIMAL);
	assert_int_equal(lx_number_whole("0x4", 0, 100, &l), LX_NUMBER_NOT_DECIMAL);
	assert_int_equal(lx_number_whole("-", 0, 100, &l), LX_NUMBER_NOT_DECIMAL);
	assert_int_equal(lx_number_whole("99999999999999999999999", 0, 100, &l), LX_NUMBER_OVERFLOW);
	assert_int_equal(lx_number_whole("9223372036854775808", 0, 100, &l), LX_NUMBER_OVERFLOW); /* 2^63 */
	/* past a 32-bit long, yet a 64-bit number: out of range on every board */
	assert_int_equal(lx_number_whole("4294967296", 0, 100, &l), LX_NUMBER_OUT_OF_RANGE);
	assert_int_equal(lx_number_whole("-2147483649", -10, 10, &l), LX_NUMBER_OUT_OF_RANGE);
	assert_int_equal(lx_number_int("2147483648", 0, 2147483647, &i), LX_NUMBER_OUT_OF_RANGE);
	assert_int_equal(i, 3);
	assert_int_equal(lx_number_int("101", 0, 100, &i), LX_NUMBER_OUT_OF_RANGE);
}

static void lists_have_no_empty_items(void **state)
{
	(void)state;
	double v[3] = {0};
	int at = -1;
	assert_int_equal(lx_number_reals("1,2,-3.5", 3, -10, 10, v, &at), LX_NUMBER_OK);
	assert_true(v[0] == 1 && v[1] == 2 && v[2] == -3.5);
	static const char *const bad[] = {"1,,3", "1,2,", ",1,2", "1,2", "1,2,3,4", "1, 2,3", "", ","};
	for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++)
		assert_int_not_equal(lx_number_reals(bad[k], 3, -10, 10, v, &at), LX_NUMBER_OK);
	assert_int_equal(lx_number_reals("1,2,1e999", 3, -10, 10, v, &at), LX_NUMBER_OVERFLOW);
	assert_int_equal(at, 2);
	assert_int_equal(lx_number_reals("1,2,11", 3, -10, 10, v, &at), LX_NUMBER_OUT_OF_RANGE);

	const char *s = "plane,uniform";
	char item[16];
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), 1);
	assert_string_equal(item, "plane");
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), 1);
	assert_string_equal(item, "uniform");
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), 0);
	s = "a,";
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), -1); /* a list that ends in a comma */
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), 0);
	s = ","; /* found by fuzz_cli: it once stood still here, returning -1 for ever */
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), -1);
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), 0);
	s = "a,,b";
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), 1);
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), -1);
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), 1);
	assert_string_equal(item, "b");
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), 0);
	s = "much-too-long-for-the-item";
	assert_int_equal(lx_list_next(&s, ',', item, sizeof item), -1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(decimal_numbers_parse),
		cmocka_unit_test(anything_else_is_refused),
		cmocka_unit_test(overflow_underflow_and_range_say_which),
		cmocka_unit_test(whole_numbers),
		cmocka_unit_test(lists_have_no_empty_items),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
