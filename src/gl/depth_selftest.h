/* Which depth path the shaders can take on this GL, found by trying it: a driver's
 * precision query is not to be trusted (Mesa's lima defines GL_FRAGMENT_PRECISION_HIGH
 * and reports highp, then computes in fp16, and every cast shadow vanishes). */
#ifndef LX_DEPTH_SELFTEST_H
#define LX_DEPTH_SELFTEST_H
#include <stdbool.h>
#include <stddef.h>
#include <string.h>

/* LX_DEPTH_TEXTURE: the 24-bit highp codes kept in a depth texture (GL_OES_depth_texture)
 * instead of RGBA8: the shadow pass writes no colour. Taken only when asked for. */
enum lx_depth_precision { LX_DEPTH_AUTO, LX_DEPTH_HIGHP, LX_DEPTH_MEDIUMP, LX_DEPTH_TEXTURE };

struct lx_depth_choice {
	bool mediump;     /* the path taken: 11-bit codes at mediump, else 24-bit at highp */
	bool texture;     /* the maps' depth in a depth texture (24-bit highp codes), else RGBA8 */
	const char *path; /* "highp24", "mediump11" or "highp24-texture" */
	/* "passed" (auto, the 24-bit path passed), "fell-back" (auto, it failed and the
	 * 11-bit one passed), "forced" (a path given; see warning) */
	const char *selftest;
	char warning[200]; /* a forced path that failed its test; empty otherwise */
};

/* Renders a ramp of depths and a handful of neighbouring codes through the shadow pass's
 * depth-write shader into a small target, reads the codes back, then reads them through
 * the main pass's compare just in front of and just behind each: true when the path keeps
 * them all. `detail` says what failed. A current GL context is needed; the result is
 * kept per path for the process (one driver). */
bool lx_depth_selftest(enum lx_depth_precision path, char *detail, size_t len);

/* The path for a request: auto takes the 24-bit path where it passes, else the 11-bit
 * one; false (err says why) when auto finds neither. A forced path is taken even when it
 * fails, with a warning; the texture path asked for on a GL without depth textures gives
 * auto's path, with a warning. */
bool lx_depth_choose(enum lx_depth_precision want, struct lx_depth_choice *out, char *err, size_t errlen);

/* The request that takes the path a choice took (to make another run on it). */
static inline enum lx_depth_precision lx_depth_choice_path(const struct lx_depth_choice *c)
{
	return c->texture ? LX_DEPTH_TEXTURE : c->mediump ? LX_DEPTH_MEDIUMP : LX_DEPTH_HIGHP;
}

/* "auto", "highp", "mediump" or "texture"; false for anything else. (Inline: board
 * profiles, which are GL-free, parse it too.) */
static inline bool lx_depth_precision_parse(const char *s, enum lx_depth_precision *out)
{
	static const char *const names[] = {"auto", "highp", "mediump", "texture"};
	for (int i = 0; i < 4; i++)
		if (!strcmp(s, names[i])) {
			*out = (enum lx_depth_precision)i;
			return true;
		}
	return false;
}

#endif
