#include "embedded.h"
#include <string.h>

const char *lx_embedded_text(const struct lx_embedded_file *files, const char *name)
{
	for (const struct lx_embedded_file *f = files; f->name; f++)
		if (!strcmp(f->name, name))
			return f->text;
	return NULL;
}
