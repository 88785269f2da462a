#include "shader_text.h"
#include "plane_cover.h"
#include "embedded.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct text {
	char *s;
	size_t len, cap;
	bool oom;
};

static void append(struct text *t, const char *s, size_t n)
{
	if (t->oom)
		return;
	if (t->len + n + 1 > t->cap) {
		size_t cap = (t->len + n + 1) * 2;
		char *p = realloc(t->s, cap);
		if (!p) {
			t->oom = true;
			return;
		}
		t->s = p;
		t->cap = cap;
	}
	memcpy(t->s + t->len, s, n);
	t->len += n;
	t->s[t->len] = 0;
}

static char *assemble(const char *name, const char *src, const char *defines, char *err, size_t errlen)
{
	struct text t = {0};
	const char *line = src;
	int n = 0;
	while (*line) {
		const char *eol = strchr(line, '\n');
		size_t len = eol ? (size_t)(eol - line + 1) : strlen(line);
		static const char tag[] = "//!include ";
		if (!strncmp(line, tag, sizeof tag - 1)) {
			char inc[64];
			size_t m = len - (sizeof tag - 1);
			while (m && (line[sizeof tag - 2 + m] == '\n' || line[sizeof tag - 2 + m] == '\r'))
				m--;
			snprintf(inc, sizeof inc, "%.*s", (int)m, line + sizeof tag - 1);
			const char *body = lx_embedded_text(lx_shader_files, inc);
			if (!body) {
				snprintf(err, errlen, "%s:%d: included file '%s' is not built in", name, n + 1, inc);
				free(t.s);
				return NULL;
			}
			append(&t, body, strlen(body));
		} else
			append(&t, line, len);
		if (n++ == 0 && defines)
			append(&t, defines, strlen(defines));
		line += len;
	}
	if (t.oom) {
		free(t.s);
		snprintf(err, errlen, "%s: out of memory", name);
		return NULL;
	}
	return t.s;
}

static bool ident_char(char c)
{
	return c == '_' || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
}

/* LIXEL_SIMULATE_LIMA=1: what Mesa's lima does to a fragment shader, on a driver that
 * computes mediump in fp16 (llvmpipe does): every highp made mediump, while
 * GL_FRAGMENT_PRECISION_HIGH stays defined and highp is still reported. Returns the new
 * text (the old one freed), or NULL when out of memory. */
static char *simulate_lima(char *src)
{
	struct text t = {0};
	const char *p = src, *q;
	while ((q = strstr(p, "highp"))) {
		bool word = (q == src || !ident_char(q[-1])) && !ident_char(q[5]);
		append(&t, p, (size_t)(q - p));
		append(&t, word ? "mediump" : "highp", word ? 7 : 5);
		p = q + 5;
	}
	append(&t, p, strlen(p));
	free(src);
	if (t.oom) {
		free(t.s);
		return NULL;
	}
	return t.s;
}

bool lx_simulating_lima(void)
{
	const char *v = getenv("LIXEL_SIMULATE_LIMA");
	return v && !strcmp(v, "1");
}

char *lx_shader_text(const char *name, const char *text, const char *defines, bool simulate_lima_fragment, char *err,
		     size_t errlen)
{
	char *src = assemble(name, text, defines, err, errlen);
	if (src && simulate_lima_fragment && !(src = simulate_lima(src)))
		snprintf(err, errlen, "%s: out of memory", name);
	return src;
}

const char *lx_shadow_defines(enum lx_depth_precision path)
{
	return path == LX_DEPTH_MEDIUMP ? "#define LX_FORCE_MEDIUMP 1\n"
	       : path == LX_DEPTH_TEXTURE ? "#define LX_DEPTH_TEXTURE 1\n"
					  : NULL;
}

int lx_main_varyings(int reads, bool edges, bool face_plane, bool projective, int covers)
{
	return 2 + reads * (1 + edges) + (face_plane ? (reads + 1) / 2 : 0) + projective + covers;
}

static bool varyings_fit(const struct lx_main_variant *v, int n) { return v->max_varyings <= 0 || n <= v->max_varyings; }

/* The rows n covers take: a vec4 each, their floats beside the light's direction and
 * the normal (two vec3s), and one more row when a face test's float makes three. */
static int cover_rows(const struct lx_main_variant *v, int n) { return n + (n > 1 && v->faces == LX_FACES_TESTED); }

int lx_main_covers(const struct lx_main_variant *v)
{
	if (v->maps <= 0 || v->faces == LX_FACES_AWAY || v->covers <= 0)
		return 0;
	int n = v->covers < LX_MAX_COVERS ? v->covers : LX_MAX_COVERS;
	return n > 1 && !varyings_fit(v, lx_main_varyings(v->reads, false, false, v->projective, cover_rows(v, n))) ? 1 : n;
}

bool lx_main_face_plane(const struct lx_main_variant *v)
{
	return v->maps > 0 && v->reads > 0 && v->faces == LX_FACES_CASTER && !v->filtered &&
	       varyings_fit(v, lx_main_varyings(v->reads, false, true, v->projective, cover_rows(v, lx_main_covers(v))));
}

bool lx_main_self(const struct lx_main_variant *v)
{
	return v->self_id && v->maps > 0 && v->reads > 0 && v->faces == LX_FACES_CASTER && v->path != LX_DEPTH_TEXTURE;
}

void lx_main_defines(const struct lx_main_variant *v, char *out, size_t len)
{
	const char *p = lx_shadow_defines(v->path);
	bool away = v->maps > 0 && v->faces == LX_FACES_AWAY;
	int reads = away ? 0 : v->reads; /* in its own shadow: nothing to read */
	bool plane = !away && lx_main_face_plane(v);
	/* the served test on edge functions (main.vert), for both shaders alike; not on the
	 * mediump path, whose fp16 test stays as it was */
	int covers = lx_main_covers(v);
	bool edges = reads > 0 && v->path != LX_DEPTH_MEDIUMP &&
		     varyings_fit(v, lx_main_varyings(reads, true, plane, v->projective, cover_rows(v, covers)));
	snprintf(out, len, "#define LX_SHADOWED %d\n#define LX_READS %d\n#define LX_FACE_TEST %d\n%s%s%s%s%s%s%s%s",
		 v->maps > 0, reads, v->maps > 0 && v->faces == LX_FACES_TESTED, away ? "#define LX_FACE_AWAY 1\n" : "",
		 v->decision ? "#define LX_DECISION 1\n" : "", p ? p : "", edges ? "#define LX_EDGES 1\n" : "",
		 plane ? "#define LX_FACE_PLANE 1\n" : "", lx_main_self(v) ? "#define LX_SELF 1\n" : "",
		 covers > 0 ? "#define LX_COVER 1\n" : "", covers > 1 ? "#define LX_COVER2 1\n" : "");
}
