/* Shared by the libFuzzer harnesses: the input as a NUL-terminated string, and a check
 * that aborts (a crash libFuzzer reports, with its input saved) when an invariant fails. */
#ifndef LX_FUZZ_UTIL_H
#define LX_FUZZ_UTIL_H
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FUZZ_CHECK(cond)                                                                      \
	do {                                                                                  \
		if (!(cond)) {                                                                \
			fprintf(stderr, "%s:%d: invariant failed: %s\n", __FILE__, __LINE__, #cond); \
			abort();                                                              \
		}                                                                             \
	} while (0)

/* A malloc'ed copy of the input with a NUL after it (the parsers take C strings; an
 * embedded NUL simply ends the text early, as it would for a caller). */
static inline char *fuzz_text(const uint8_t *data, size_t size)
{
	char *t = malloc(size + 1);
	if (!t)
		abort();
	memcpy(t, data, size);
	t[size] = 0;
	return t;
}

/* An error message is one non-empty line that starts with "FILE:LINE: ". */
static inline void fuzz_check_error(const char *err, size_t errlen, const char *file)
{
	FUZZ_CHECK(memchr(err, 0, errlen) != NULL);
	FUZZ_CHECK(!strchr(err, '\n'));
	size_t fl = strlen(file);
	FUZZ_CHECK(!strncmp(err, file, fl) && err[fl] == ':');
	char *end;
	long line = strtol(err + fl + 1, &end, 10);
	FUZZ_CHECK(end != err + fl + 1 && line >= 1 && *end == ':');
}

#endif
