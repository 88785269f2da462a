/* A small JSON writer. Non-finite numbers are written as null, never NaN or Infinity. */
#ifndef LX_JSON_H
#define LX_JSON_H
#include <stdbool.h>
#include <stdio.h>

struct lx_json {
	FILE *f;
	int depth;
	bool first[32];
	char closer[32];
	bool after_key;
};

void lx_json_begin(struct lx_json *j, FILE *f);
void lx_json_object(struct lx_json *j);
void lx_json_array(struct lx_json *j);
void lx_json_end(struct lx_json *j); /* closes the innermost object or array */
void lx_json_key(struct lx_json *j, const char *key);
void lx_json_string(struct lx_json *j, const char *s);
void lx_json_number(struct lx_json *j, double v);
void lx_json_int(struct lx_json *j, long v);
void lx_json_bool(struct lx_json *j, bool v);

#endif
