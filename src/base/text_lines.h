/* Line by line through a text file held in memory (scene files, board profiles). */
#ifndef LX_TEXT_LINES_H
#define LX_TEXT_LINES_H
#include <stddef.h>

/* The next line of *text into buf (at most size - 1 characters), without its newline and
 * without a comment from '#' on; *text steps past it. Returns 1 for a line, 0 at the end,
 * -1 when the line is too long for buf (*text still steps past it). */
int lx_text_line(const char **text, char *buf, size_t size);

#endif
