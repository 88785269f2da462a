/* Shared helpers for the cmocka tests. */
#ifndef LX_TEST_UTIL_H
#define LX_TEST_UTIL_H
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>
#include "scene.h"

/* The tests' data files, from the repository's top (where make runs them). */
#ifndef LX_TEST_DATA
#define LX_TEST_DATA "tests/data"
#endif

#define assert_near(a, b, eps)                                                                          \
	do {                                                                                            \
		double a_ = (a), b_ = (b), e_ = (eps);                                                  \
		if (!(fabs(a_ - b_) <= e_))                                                             \
			fail_msg("%s = %.17g, expected %s = %.17g within %g", #a, a_, #b, b_, e_);       \
	} while (0)

/* xorshift: reproducible random numbers for sweeps */
static inline double test_rand(uint64_t *s)
{
	*s ^= *s << 13;
	*s ^= *s >> 7;
	*s ^= *s << 17;
	return (double)(*s >> 11) / 9007199254740992.0;
}

/* A random view of the built-in scenes' room for the sweeps, drawn from *seed in a fixed
 * order: the eye, the target, then a point light above the room, or when directional a
 * light travelling down by at least min_down (and sideways at most 0.5 each way). */
static inline void test_random_view(struct lx_scene *s, uint64_t *seed, bool directional, double min_down)
{
	s->camera.eye = v3(test_rand(seed) * 10 - 5, 0.3 + test_rand(seed) * 5, test_rand(seed) * 10 - 3);
	s->camera.at = v3(test_rand(seed) * 4 - 2, test_rand(seed) * 1.5, test_rand(seed) * 4 - 3);
	if (directional) {
		s->light.directional = true;
		assert_true(v3_normalize(v3(test_rand(seed) - 0.5, -min_down - test_rand(seed), test_rand(seed) - 0.5),
					 &s->light.direction));
	} else
		s->light.position = v3(test_rand(seed) * 12 - 6, 3.5 + test_rand(seed) * 5, test_rand(seed) * 12 - 4);
}

/* 64-bit FNV-1a over n bytes, continued from h (TEST_FNV_BASIS to begin): the golden
 * images' hashes, the shader texts' identities. */
#define TEST_FNV_BASIS 0xcbf29ce484222325ull
static inline uint64_t test_fnv1a(uint64_t h, const void *bytes, size_t n)
{
	const unsigned char *p = bytes;
	for (size_t i = 0; i < n; i++)
		h = (h ^ p[i]) * 0x100000001b3ull;
	return h;
}

/* Scene file `name` of LX_TEST_DATA into *s; the test fails with the parser's line. */
static inline void test_scene_load(const char *name, struct lx_scene *s)
{
	char path[512], err[256];
	snprintf(path, sizeof path, "%s/%s", LX_TEST_DATA, name);
	if (!lx_scene_load(path, s, err, sizeof err))
		fail_msg("%s", err);
}

#endif
