/* lixel's one number parser, for options, scene files and board profiles alike: decimal
 * only (no hex, no inf or nan, no leading '+' space or tab), the whole token, range-checked,
 * and a reason that says what was wrong. GL-free. */
#ifndef LX_NUMBER_H
#define LX_NUMBER_H
#include <stddef.h>

enum lx_number_error {
	LX_NUMBER_OK = 0,
	LX_NUMBER_NOT_DECIMAL, /* not [-]digits[.digits][e[+-]digits] as a whole */
	LX_NUMBER_OVERFLOW,    /* more than a double (or a 64-bit whole number) can hold */
	LX_NUMBER_UNDERFLOW,   /* not zero, yet below the smallest normal double */
	LX_NUMBER_OUT_OF_RANGE /* a number, outside [lo, hi] */
};

/* s as a real number in [lo, hi]. *out is written only on LX_NUMBER_OK. */
enum lx_number_error lx_number_real(const char *s, double lo, double hi, double *out);
/* s as a whole number (decimal digits, an optional '-') in [lo, hi]. */
enum lx_number_error lx_number_whole(const char *s, long lo, long hi, long *out);
enum lx_number_error lx_number_int(const char *s, int lo, int hi, int *out);
/* Exactly n real numbers in [lo, hi] separated by single commas, no item empty. On an
 * error *bad_item (when not NULL) is the 0-based item at fault, n when the count is wrong. */
enum lx_number_error lx_number_reals(const char *s, int n, double lo, double hi, double *out, int *bad_item);
/* A few words for an error message: "" for LX_NUMBER_OK, else e.g. "not a decimal number". */
const char *lx_number_why(enum lx_number_error e);

/* The next item of a list separated by sep: copies it (at most n-1 characters) to item and
 * steps *s past it and its separator. Returns 0 at the end of the list, 1 for an item, -1
 * for an empty item (",," or a separator at either end: the item before a final
 * separator counts as the empty one) or one too long for item. */
int lx_list_next(const char **s, char sep, char *item, size_t n);

#endif
