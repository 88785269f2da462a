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

static void str(FILE *f, const char *s)
{
	fputc('"', f);
	for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
		if (*p == '"' || *p == '\\')
			fprintf(f, "\\%c", *p);
		else if (*p < 0x20)
			fprintf(f, "\\u%04x", *p);
		else
			fputc(*p, f);
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
