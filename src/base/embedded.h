/* Files built into the binary by tools/embed-files.sh (shaders, board profiles), so
 * lixel runs from any directory. Each array ends with {0, 0}. */
#ifndef LX_EMBEDDED_H
#define LX_EMBEDDED_H

struct lx_embedded_file {
	const char *name; /* the file's base name */
	const char *text;
};

extern const struct lx_embedded_file lx_shader_files[];
extern const struct lx_embedded_file lx_board_files[];

/* The text of the named file in an array, or NULL. */
const char *lx_embedded_text(const struct lx_embedded_file *files, const char *name);

#endif
