/* The JSON writer (src/base/json.c): whatever bytes a name holds, the output is JSON. */
#include "json.h"
#include "test_util.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *written(const char *s)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);
	assert_non_null(f);
	struct lx_json j;
	lx_json_begin(&j, f);
	lx_json_string(&j, s);
	fclose(f);
	return buf;
}

static void strings_stay_json(void **state)
{
	(void)state;
	static const struct { const char *in, *out; } cases[] = {
		{"floor", "\"floor\""},
		{"a\"b\\c", "\"a\\\"b\\\\c\""},
		{"line\nbreak", "\"line\\u000abreak\""},
		{"caf\xc3\xa9", "\"caf\xc3\xa9\""},			  /* well-formed UTF-8 passes */
		{"\xe2\x82\xac 5", "\"\xe2\x82\xac 5\""},		  /* a three-byte sequence */
		{"fl\xffr", "\"fl\\ufffdr\""},				  /* a byte no UTF-8 has */
		{"\xc3", "\"\\ufffd\""},				  /* a sequence cut short by the end */
		{"\xc0\xaf", "\"\\ufffd\\ufffd\""},			  /* overlong */
		{"\xed\xa0\x80", "\"\\ufffd\\ufffd\\ufffd\""},		  /* a surrogate */
		{"\xf5\x80\x80\x80", "\"\\ufffd\\ufffd\\ufffd\\ufffd\""}, /* beyond U+10FFFF */
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		char *got = written(cases[i].in);
		if (strcmp(got, cases[i].out))
			fail_msg("case %zu: got %s, expected %s", i, got, cases[i].out);
		free(got);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(strings_stay_json),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
