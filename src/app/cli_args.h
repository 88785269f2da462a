/* What the commands (render, bench, kiosk) share in reading their arguments: the one
 * line for bad input (exit status 2), options that take a value, the scene argument. */
#ifndef LX_CLI_ARGS_H
#define LX_CLI_ARGS_H
#include "number.h"
#include "scene.h"
#include <stdbool.h>
#include <stddef.h>

/* "lixel CMD: OPT: expected EXPECTED, got 'GOT'" on stderr; returns 2. */
int lx_arg_bad(const char *cmd, const char *opt, const char *expected, const char *got);
/* The same line for a number that did not parse, with the reason ("too large to hold")
 * unless it is only out of the range that expected states. */
int lx_arg_bad_number(const char *cmd, const char *opt, const char *expected, const char *got, enum lx_number_error e);
/* X,Y,Z: three numbers within +-LX_SCENE_NUMBER_MAX separated by single commas. */
enum lx_number_error lx_arg_triple(const char *s, vec3 *out);
/* argv[*i] must be one of the n option names that take a value: on success *value is the
 * next argument, *i steps over it, and 0 is returned; else one line and 2. */
int lx_arg_value(const char *cmd, int argc, char **argv, int *i, const char *const *names, size_t n,
		 const char **value);
/* Options whose value is kept as given (an output path, a name looked up later): the
 * value goes to *to of the entry named opt. Returns whether opt was one of the n. */
struct lx_arg_text {
	const char *name;
	const char **to;
};
bool lx_arg_text(const char *opt, const char *value, const struct lx_arg_text *t, size_t n);
/* The scene of --scene: NULL for the default, a built-in name, or a file. Prints the
 * file's FILE:LINE error and returns false when it does not load. */
bool lx_arg_scene(const char *arg, struct lx_scene *s);

/* The maps' options shared by render and bench: --region-shape square|fitted,
 * --budget-split fixed|shared, --plane-density readers|budget, --plane-max-lpp X, --lookup-region footprint|all, --depth-slots N,
 * --light-budget S,...
 * Returns 0 when opt is one of them and
 * its value is good, 2 (after the one line) when the value is bad, -1 for another option. */
struct lx_method_options;
/* --depth-precision auto|highp|mediump|texture (render, bench, kiosk): 0 when opt is it and its
 * value is good, 2 (after the one line) when the value is bad, -1 for another option. */
#include "depth_selftest.h"
int lx_arg_depth_precision(const char *cmd, const char *opt, const char *value, enum lx_depth_precision *out);
#define LX_DEPTH_OPTION_HELP \
	"  --depth-precision P  the shaders' depth path: auto (default: the first whose start-up\n" \
	"                       self-test passes of texture, highp and mediump), or one forced\n" \
	"                       (a warning when its self-test fails): texture, the 24-bit codes\n" \
	"                       in a depth texture (GL_OES_depth_texture; the shadow pass writes\n" \
	"                       no colour; without it auto's path), highp, the 24-bit codes in\n" \
	"                       RGBA8, or mediump, 11-bit codes in RGBA8\n" \
	"  --mediump            the same as --depth-precision mediump\n"
int lx_arg_plane_option(const char *cmd, const char *opt, const char *value, struct lx_method_options *o);
/* A method spec (lx_shadow_method_spec, from options o): 0 when it reads, else one line
 * saying which part is wrong and what it may be (or, for a spec with a line break or tab,
 * the usual line with it escaped and expected) and 2. */
int lx_arg_method_spec(const char *cmd, const char *opt, const char *spec, const struct lx_method_options *o,
		       const char *expected);
/* --filter none|pcf2x2|pcf3x3 and --light-size DEG (render; bench takes --light-size):
 * 0 when opt is one of them and its value is good, 2 (after the one line) when the value
 * is bad, -1 for another option. */
#include "shadow_filter.h"
int lx_arg_filter(const char *cmd, const char *opt, const char *value, enum lx_filter *filter, double *light_size_deg);
#define LX_FILTER_OPTION_HELP \
	"  --filter F           the shadow lookup: none (default: one NEAREST texel), pcf2x2 (the\n" \
	"                       4 nearest texels' compares weighted bilinearly) or pcf3x3 (9\n" \
	"                       texels' compares under a box two texels wide): softer edges for\n" \
	"                       4 or 9 fetches a lookup\n" \
	"  --light-size DEG     the area light the soft-edge error is measured against: a sphere\n" \
	"                       (or, for a directional light, a disc of directions) of this\n" \
	"                       angular diameter, 0 to 20 degrees (default 0.5, about the sun's); render\n" \
	"                       --measure computes it when a filter is on or this is given\n"
#define LX_PLANE_OPTION_NAMES \
	"--region-shape", "--budget-split", "--plane-density", "--caster-maps", "--plane-max-lpp", "--lookup-region", "--caster-depth", "--depth-slots", \
		"--light-budget"
#define LX_PLANE_OPTION_HELP \
	"  --region-shape S     plane maps: fitted (default: each map's shape follows its\n" \
	"                       wanted region, the scale set by area) or square (the paper's)\n" \
	"  --budget-split S     plane maps: fixed (default: 350^2 lixels each; a plane without\n" \
	"                       a map this frame hands its budget to a map short of a lixel\n" \
	"                       per pixel, and with no plane map the fallback takes them all)\n" \
	"                       or shared (a map also hands on the rest its whole-number\n" \
	"                       scale leaves, and what is left goes to the fallback unless\n" \
	"                       --plane-max-lpp caps them)\n" \
	"  --caster-maps M      what a caster's own surfaces read: dense (default: first the\n" \
	"                       plane maps denser on it than the fallback, each of which then\n" \
	"                       holds the caster's far side as its faces) or fallback (the\n" \
	"                       fallback alone: less shadow-pass work, coarser shadows of\n" \
	"                       casters on casters)\n" \
	"  --plane-density D    plane maps past a lixel per pixel: readers (default: only as\n" \
	"                       dense as the casters that read a map need, a lixel per pixel\n" \
	"                       on their surfaces; a map none reads takes one lixel a pixel)\n" \
	"                       or budget (as dense as the budget allows: more fill)\n" \
	"  --plane-max-lpp X    plane maps: at most X lixels per pixel (less shadow-pass fill;\n" \
	"                       default none)\n" \
	"  --lookup-region R    footprint (default: a receiver pixel looks its maps up only\n" \
	"                       where a caster's shadow can fall on it) or all (everywhere: the\n" \
	"                       same shadows, more fill)\n" \
	"  --caster-depth D     face (default: a caster's pixel compared along its face's plane\n" \
	"                       at the centre of the lixel read, never further from the light:\n" \
	"                       no acne where a coarse map meets the caster's silhouette, for\n" \
	"                       more work per lookup; on the mediump path the face's nearest\n" \
	"                       depth over half a lixel each way; unfiltered, else point) or\n" \
	"                       point (at its own depth)\n" \
	"  --depth-slots N      the atlas cleared once every N frames, 1 to 64 (default 8):\n" \
	"                       each frame's maps written into their own Nth of the depth range,\n" \
	"                       below the earlier frames' (24 - log2 N bits a frame); taken on\n" \
	"                       the depth-texture path of a GPU that is not a tiler, else 1\n" \
	"  --light-budget S,... a scene of several lights: each light's share of the lixels\n" \
	"                       above, from 0.01 to 1 (default 1 each; lights past the list take\n" \
	"                       its last share), e.g. 1,0.5 for half a budget for the second\n"

#endif
