/* For the tests that drive the GL: a platform made current and what its GL can do.
 * Include after test_util.h. */
#ifndef LX_GL_FIXTURE_H
#define LX_GL_FIXTURE_H
#include "gl_caps.h"
#include "platform.h"

/* The named platform ("osmesa", "egl") made current, *caps probed; the test fails with the
 * platform's reason when it cannot be made. */
static inline struct lx_platform *platform_with_caps(const char *name, struct lx_gl_caps *caps)
{
	char err[512];
	struct lx_platform *plat = lx_platform_create(name, err, sizeof err);
	if (!plat)
		fail_msg("%s: %s", name, err);
	lx_gl_caps_probe(caps);
	return plat;
}

#endif
