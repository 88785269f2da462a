#include "json.h"
#include <math.h>

static void sep(struct lx_json *j)
{
	if (j->after_key) {
		j->after_key = false;
		return;
	}
	if (j->depth > 0) {
		if (!j->first[j->depth])
			fputs(", ", j->f);
		j->first[j->depth] = false;
	}
}

void lx_json_begin(struct lx_json *j, FILE *f)
{
	j->f = f;
	j->depth = 0;
	j->after_key = false;
}

static void open_(struct lx_json *j, char c, char close)
{
	sep(j);
	fputc(c, j->f);
	if (j->depth < 31) {
		j->depth++;
		j->first[j->depth] = true;
		j->closer[j->depth] = close;
	}
}

void lx_json_object(struct lx_json *j) { open_(j, '{', '}'); }
void lx_json_array(struct lx_json *j) { open_(j, '[', ']'); }

void lx_json_end(struct lx_json *j)
{
	if (j->depth > 0) {
		fputc(j->closer[j->depth], j->f);
		j->depth--;
	}
	if (j->depth == 0)
		fputc('\n', j->f);
}

/* The length of the well-formed UTF-8 sequence at p (1 to 4), 0 when it is not one. */
static int utf8_length(const unsigned char *p)
{
	int n = p[0] >= 0xf0 && p[0] <= 0xf4 ? 4 : p[0] >= 0xe0 && p[0] < 0xf0 ? 3 : p[0] >= 0xc2 && p[0] < 0xe0 ? 2 : 0;
	if (p[0] < 0x80)
		return 1;
	for (int k = 1; k < n; k++)
		if ((p[k] & 0xc0) != 0x80)
			return 0;
	if ((n == 3 && ((p[0] == 0xe0 && p[1] < 0xa0) || (p[0] == 0xed && p[1] >= 0xa0))) ||
	    (n == 4 && ((p[0] == 0xf0 && p[1] < 0x90) || (p[0] == 0xf4 && p[1] >= 0x90))))
		return 0; /* overlong, a surrogate, or beyond U+10FFFF */
	return n;
}

/* A JSON string: escapes as the grammar needs, and any byte that is not well-formed
 * UTF-8 (a name from a file in another encoding) as U+FFFD, so the output stays JSON. */
static void str(FILE *f, const char *s)
{
	fputc('"', f);
	for (const unsigned char *p = (const unsigned char *)s; *p;) {
		int n = utf8_length(p);
		if (n == 0) {
			fputs("\\ufffd", f);
			p++;
		} else if (n > 1) {
			fwrite(p, 1, (size_t)n, f);
			p += n;
		} else {
			if (*p == '"' || *p == '\\')
				fprintf(f, "\\%c", *p);
			else if (*p < 0x20 || *p == 0x7f)
				fprintf(f, "\\u%04x", *p);
			else
				fputc(*p, f);
			p++;
		}
	}
	fputc('"', f);
}

void lx_json_key(struct lx_json *j, const char *key)
{
	sep(j);
	str(j->f, key);
	fputs(": ", j->f);
	j->after_key = true;
}

void lx_json_string(struct lx_json *j, const char *s)
{
	sep(j);
	str(j->f, s);
}

void lx_json_number(struct lx_json *j, double v)
{
	sep(j);
	if (isfinite(v))
		fprintf(j->f, "%.6g", v);
	else
		fputs("null", j->f);
}

void lx_json_int(struct lx_json *j, long v)
{
	sep(j);
	fprintf(j->f, "%ld", v);
}

void lx_json_bool(struct lx_json *j, bool v)
{
	sep(j);
	fputs(v ? "true" : "false", j->f);
}
