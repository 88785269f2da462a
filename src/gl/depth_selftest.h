/* Which depth path the shaders can take on this GL, found by trying it: a driver's
 * precision query is not to be trusted (Mesa's lima defines GL_FRAGMENT_PRECISION_HIGH
 * and reports highp, then computes in fp16, and every cast shadow vanishes). */
#ifndef LX_DEPTH_SELFTEST_H
#define LX_DEPTH_SELFTEST_H
#include <stdbool.h>
#include <stddef.h>
#include <string.h>

/* The depth paths: 24-bit codes at highp in RGBA8 (HIGHP), 11-bit codes at mediump in
 * RGBA8 (MEDIUMP), 24-bit codes at highp in a depth texture (TEXTURE, GL_OES_depth_texture:
 * the shadow pass writes no colour); AUTO asks for the first that passes its self-test. */
enum lx_depth_precision { LX_DEPTH_AUTO, LX_DEPTH_HIGHP, LX_DEPTH_MEDIUMP, LX_DEPTH_TEXTURE };

struct lx_depth_choice {
	enum lx_depth_precision taken; /* never LX_DEPTH_AUTO */
	const char *path;              /* its name: "highp24", "mediump11" or "highp24-texture" */
	/* "passed" (auto, a 24-bit path passed), "fell-back" (auto, both failed and the
	 * 11-bit one passed), "forced" (a path given; see warning) */
	const char *selftest;
	char warning[200]; /* a forced path that failed its test; empty otherwise */
};

/* Renders a ramp of depths and a handful of neighbouring codes through the shadow pass's
 * depth-write shader into a small target, reads the codes back (not on the texture path:
 * ES 2.0 reads no depth), then reads them through the main pass's compare just in front
 * of and just behind each: true when the path keeps
 * them all. `detail` says what failed. A current GL context is needed; the result is
 * kept per path for the process (one driver). */
bool lx_depth_selftest(enum lx_depth_precision path, char *detail, size_t len);

/* The path for a request: auto takes the first whose self-test passes of the texture, the
 * 24-bit RGBA8 and the 11-bit one; false (err says why) when none does. A forced path is
 * taken even when it fails, with a warning; the texture path asked for on a GL without
 * depth textures gives auto's path, with a warning. */
bool lx_depth_choose(enum lx_depth_precision want, struct lx_depth_choice *out, char *err, size_t errlen);

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
