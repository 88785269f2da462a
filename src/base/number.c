#include "number.h"
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

static const char *digits(const char *p)
{
	while (*p >= '0' && *p <= '9')
		p++;
	return p;
}

/* [-]digits[.digits]|[-].digits, then [e|E[+|-]digits]; true when that is all of s */
static bool is_decimal(const char *s)
{
	const char *p = s + (*s == '-');
	const char *a = digits(p);
	bool whole = a > p, frac = false;
	if (*a == '.') {
		const char *b = digits(a + 1);
		frac = b > a + 1;
		a = b;
	}
	if (!whole && !frac)
		return false;
	if (*a == 'e' || *a == 'E') {
		const char *e = a + 1;
		e += *e == '+' || *e == '-';
		const char *b = digits(e);
		if (b == e)
			return false;
		a = b;
	}
	return *a == 0;
}

enum lx_number_error lx_number_real(const char *s, double lo, double hi, double *out)
{
	if (!s || !is_decimal(s))
		return LX_NUMBER_NOT_DECIMAL;
	errno = 0;
	double v = strtod(s, NULL);
	/* strtod reports ERANGE for both ends; the value tells which */
	if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1))
		return LX_NUMBER_OVERFLOW;
	if (v != 0 ? fabs(v) < DBL_MIN : errno == ERANGE)
		return LX_NUMBER_UNDERFLOW;
	if (!(v >= lo && v <= hi))
		return LX_NUMBER_OUT_OF_RANGE;
	*out = v == 0 ? 0 : v; /* no -0 */
	return LX_NUMBER_OK;
}

enum lx_number_error lx_number_whole(const char *s, long lo, long hi, long *out)
{
	if (!s)
		return LX_NUMBER_NOT_DECIMAL;
	const char *p = s + (*s == '-');
	if (p == digits(p) || *digits(p))
		return LX_NUMBER_NOT_DECIMAL;
	/* in 64 bits whatever a long holds, so that a value past the range is out of range on
	 * a 32-bit board too (armhf: 2147483648 for an int option), as on the desktop */
	errno = 0;
	long long v = strtoll(s, NULL, 10);
	if (errno == ERANGE)
		return LX_NUMBER_OVERFLOW;
	if (v < lo || v > hi)
		return LX_NUMBER_OUT_OF_RANGE;
	*out = (long)v; /* within [lo, hi], longs both */
	return LX_NUMBER_OK;
}

enum lx_number_error lx_number_int(const char *s, int lo, int hi, int *out)
{
	long v;
	enum lx_number_error e = lx_number_whole(s, lo, hi, &v);
	if (e == LX_NUMBER_OK)
		*out = (int)v;
	return e;
}

enum lx_number_error lx_number_reals(const char *s, int n, double lo, double hi, double *out, int *bad_item)
{
	char item[128];
	int k = 0, r;
	double tmp[16];
	if (n < 1 || n > 16)
		return LX_NUMBER_OUT_OF_RANGE;
	while (s && (r = lx_list_next(&s, ',', item, sizeof item)) != 0) {
		if (r < 0 || k == n) {
			if (bad_item)
				*bad_item = r < 0 ? k : n;
			return LX_NUMBER_NOT_DECIMAL;
		}
		enum lx_number_error e = lx_number_real(item, lo, hi, &tmp[k]);
		if (e) {
			if (bad_item)
				*bad_item = k;
			return e;
		}
		k++;
	}
	if (k != n) {
		if (bad_item)
			*bad_item = n;
		return LX_NUMBER_NOT_DECIMAL;
	}
	memcpy(out, tmp, (size_t)n * sizeof *out);
	return LX_NUMBER_OK;
}

const char *lx_number_why(enum lx_number_error e)
{
	switch (e) {
	case LX_NUMBER_OK: return "";
	case LX_NUMBER_NOT_DECIMAL: return "not a decimal number";
	case LX_NUMBER_OVERFLOW: return "too large to hold";
	case LX_NUMBER_UNDERFLOW: return "too small to hold (below 2.2e-308)";
	case LX_NUMBER_OUT_OF_RANGE: return "out of range";
	}
	return "";
}

int lx_list_next(const char **s, char sep, char *item, size_t n)
{
	const char *p = *s;
	if (!p || !*p)
		return 0;
	const char *end = strchr(p, sep);
	size_t len = end ? (size_t)(end - p) : strlen(p);
	*s = end ? end + 1 : p + len; /* always forward: a list of k characters ends in k calls */
	/* an empty item: here, or after a separator that ends the list */
	if (len == 0 || len >= n || (end && !end[1]))
		return -1;
	memcpy(item, p, len);
	item[len] = 0;
	return 1;
}
