#include "text_lines.h"
#include <string.h>

int lx_text_line(const char **text, char *buf, size_t size)
{
	const char *t = *text;
	if (!*t)
		return 0;
	const char *eol = strchr(t, '\n');
	size_t len = eol ? (size_t)(eol - t) : strlen(t);
	*text = eol ? eol + 1 : t + len;
	if (len >= size)
		return -1;
	memcpy(buf, t, len);
	buf[len] = 0;
	char *hash = strchr(buf, '#');
	if (hash)
		*hash = 0;
	return 1;
}
