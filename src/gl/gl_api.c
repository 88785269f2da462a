#include "gl_api.h"

struct lx_gl_api lx_gl;
static unsigned context_serial;

unsigned lx_gl_context_serial(void) { return context_serial; }

bool lx_gl_load(void *(*get_proc)(const char *name), const char **missing)
{
	struct lx_gl_api api;
#define X(ret, name, args)                                                  \
	api.name = (ret(GL_APIENTRY *) args)get_proc("gl" #name);           \
	if (!api.name) {                                                    \
		*missing = "gl" #name;                                      \
		return false;                                               \
	}
	LX_GL_FUNCTIONS(X)
#undef X
	lx_gl = api;
	context_serial++;
	return true;
}
