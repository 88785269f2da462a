/* Where a shadow can fall on the screen, GL-free.
 *
 * The main pass looks a receiver's maps up only inside window rectangles that hold
 * every pixel one of its maps could shadow, and draws the rest of it with the lit-only
 * program: on a fill-limited GPU the lookup is most of the frame.
 *
 * A map shadows a point only where a caster was drawn in front of it: the point's image
 * in the map lies within a few lixels of that caster's image, and its depth lies beyond
 * the caster's nearest depth, or for a box, the nearest depth of the faces the pass draws
 * of it (second-depth maps: those turned from the map). For one caster that set is a convex volume in world space,
 * half-spaces taken from the rows of the map's matrix (so it holds for every method's
 * warp): the image bounded in x, y and the diagonals, and along and across its long axis
 * where it is long and thin (a shadow cast low), beyond a depth and in front of the
 * light; of a box reaching behind the light, the image of its part inside the rays the
 * map serves. A box's volume also lies behind each of its faces the light shines on: a
 * ray enters a convex caster through one of them, and every point past that lies on the
 * inner side of all of them. Those planes are the world's, where the depth bound is the
 * map's: a plane-optimal map's depth is its light camera's, skewed across the rays, and
 * one bound from a caster's nearest corner left in its volume receivers beside it and
 * nearer the light (under the table scene's low light the slab's lit side, beside the
 * legs' tops, read two floor maps). Its part inside the receiver and in front of the eye,
 * projected, bounds the pixels.
 *
 * A receiver's own volume is left out: a plane's holds none of it where a lookup is
 * drawn (a plane turned away from the light is drawn without one), and a caster is a
 * convex closed mesh, so none of its faces turned to the light lies in its own shadow (the
 * face test shadows the others). What a lookup there would read of its own texels is the
 * map's error at its terminator: left out, those pixels are lit, as the exact reference
 * has them. For the same reason a box caster's faces turned from the light are not asked
 * whether another's shadow reaches them (under a low light the table's slab, touching the
 * legs' tops with its underside, kept them in a map it alone reads). */
#ifndef LX_LOOKUP_REGION_H
#define LX_LOOKUP_REGION_H
#include "polygon2d.h"
#include "shadow_method.h"

/* Window pixels [x0, x1) x [y0, y1), GL's origin (bottom left), as glScissor takes them. */
struct lx_rect {
	int x0, y0, x1, y1;
};

/* Lixels of margin around a caster's image. A lixel is written where the caster covers
 * its centre, and a NEAREST lookup reads the lixel it falls in: half a lixel, and a
 * float's rounding. A mediump (fp16) shader's texture coordinates are off by up to 2^-11
 * of the atlas, a lixel of a 2048-wide one: two more. */
#define LX_LOOKUP_MARGIN_HIGHP 1.0
#define LX_LOOKUP_MARGIN_MEDIUMP 3.0
/* The lookup region is cut in horizontal bands this many pixels tall, on a fixed grid. */
#define LX_LOOKUP_BAND 32
/* Spans end on columns that are multiples of this: a rasterizer shades the 4x4 blocks
 * (llvmpipe; a board's 2x2 quads) that an edge between two draws crosses once for each,
 * so a span with a lookup takes the rest of each block its edge would cut (on the
 * table's default view 0.03 ms less main pass at 1024x1024, measured frame by frame). */
#define LX_SPAN_ALIGN 4
/* Column x rounded down or up to a multiple of LX_SPAN_ALIGN (x of either sign, far from
 * INT_MAX). */
static inline int lx_align_down(int x) { return x - ((x % LX_SPAN_ALIGN) + LX_SPAN_ALIGN) % LX_SPAN_ALIGN; }
static inline int lx_align_up(int x) { return lx_align_down(x + LX_SPAN_ALIGN - 1); }

/* A window rectangle drawn with a lookup or without. */
struct lx_span {
	struct lx_rect box;
	bool lookup;
};

/* Whether the shadow pass of a map draws a world box: false when the box lies entirely
 * outside the rays the map serves or beyond its far plane (never culled for the near
 * plane: the pass flattens casters onto it). */
bool lx_shadow_map_sees_box(const struct lx_shadow_map *map, vec3 lo, vec3 hi);
/* Whether the shadow pass of a map draws anything of object id: its box is seen, and a
 * plane of interest (one quad) does not turn its front, which the pass culls, to the map. */
bool lx_shadow_map_draws(const struct lx_shadow_map *map, const struct lx_frame *f, int id);

#define LX_LOOKUP_VOLUME_PLANES 26 /* a caster's twenty-five at most, and the eye's near plane */

/* One frame's casters seen through each map, built once (lx_lookup_prepare) and asked
 * for each receiver: per map and caster the half-spaces where it can shadow a point
 * (count -1: nowhere), each map's margin in its clip units, the view's frustum, and the
 * maps each object reads as a receiver (lx_shadow_receiver_maps). */
struct lx_lookup_volumes {
	const struct lx_frame *frame;
	const struct lx_shadow_result *res;
	unsigned reads[LX_MAX_PLANES + LX_MAX_CASTERS];
	int count[LX_MAX_MAPS][LX_MAX_PLANES + LX_MAX_CASTERS];
	vec4 plane[LX_MAX_MAPS][LX_MAX_PLANES + LX_MAX_CASTERS][LX_LOOKUP_VOLUME_PLANES];
	double margin[LX_MAX_MAPS][2];
	vec3 frustum[8];
};

/* The volumes of a frame's rendered maps, each caster's image grown by margin_lixels
 * (LX_LOOKUP_MARGIN_*); none for a flat box in no map (res->slab_out), whose fronts'
 * tests alone decide its shadow. frame and res must outlive v's use. */
void lx_lookup_prepare(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
		       double margin_lixels, struct lx_lookup_volumes *v);

/* The window pixels that may read plane map `map`, into *out: its screen rectangle and a
 * pixel of margin (a pixel centre on its edge is inside it), out to whole blocks
 * (LX_SPAN_ALIGN) and within the width x height window. Where its map does not reach, a
 * pixel inside reads it as unserved, lit, as in the margin. False when the map does not
 * say where it reaches (no has_screen, or its rectangle not ordered: NaN or inverted). */
bool lx_map_screen_rect(const struct lx_shadow_map *map, int width, int height, struct lx_rect *out);
/* The window pixels plane map `map` surely serves: its screen rectangle where that is
 * what it serves (screen_served), less two pixels and two lixels for the rounding of a
 * lookup's coordinates (mediump: about a quarter of a lixel), in to whole blocks and
 * within the window; else an empty rectangle. */
struct lx_rect lx_map_sure_rect(const struct lx_shadow_map *map, int width, int height);
/* `within` cut into spans: with a lookup where one of the maps in `mask` could shadow a
 * pixel of receiver object `receiver`, without elsewhere. Per band of LX_LOOKUP_BAND rows,
 * the x-ranges of the casters' regions; bands cut alike are one. Returns the count (at
 * most max; short of room, the rest of `within` is one span with a lookup), or -1 when
 * max < 1. */
int lx_lookup_spans(const struct lx_lookup_volumes *v, int receiver, unsigned mask, struct lx_rect within,
		    struct lx_span *out, int max);
/* Whether one of the maps in `mask` can shadow some point of receiver object `receiver`
 * by another object. */
bool lx_lookup_any(const struct lx_lookup_volumes *v, int receiver, unsigned mask);

/* Whether one of the maps in `mask` may shadow a point of world box [lo, hi], a part of
 * receiver object `receiver`, by another object: the box reaches into one of their
 * volumes past each of its half-spaces (by the corner that reaches furthest). False
 * only where no such point can be shadowed; a few dot products per volume, so that a
 * caster's faces can be asked in runs, each by its box. */
bool lx_lookup_box_may_meet(const struct lx_lookup_volumes *v, int receiver, unsigned mask, vec3 lo, vec3 hi);

/* The maps of `mask` a draw of receiver object `receiver` needs, the same pixels shadowed:
 * the shader reads the first map, in order, that serves a point, so a map that serves no
 * point of the receiver's part in view is dropped, and so are the maps after one that
 * serves all of it, by the margin (the shader's rounding). */
unsigned lx_lookup_maps(const struct lx_lookup_volumes *v, int receiver, unsigned mask);

/* The maps of the frame whose shadow pass must draw object c, as a mask (v prepared with
 * the largest margin of any filter the main pass may use on them): those where c's
 * volume meets a receiver other than c that reads the map (the receiver's faces clipped
 * by the volume, as the lookup spans do; a box's faces the light shines on), and with `everywhere`
 * (--lookup-region all) those c reads itself. Leaving c out of the others changes no
 * lookup of another receiver: a caster's depth shadows a point only inside its volume.
 * Nor one of c's own (see above): c shadows none of its faces turned to the light, and
 * what it read of its own texels there was the map's error at its terminator. */
unsigned lx_lookup_caster_maps(const struct lx_lookup_volumes *v, int c, bool everywhere);

/* The most vertices lx_plane_in_window returns */
#define LX_WINDOW_POLY_MAX 12

/* The part of plane of interest `id` seen through window rectangle `box`: a convex
 * polygon in world space (returns its vertex count; 0: none), cut only by the rectangle's
 * sides and by a plane between the eye and its near plane, so that GL's own near clip is
 * what cuts there. The main pass draws a plane as such pieces, with and without a lookup,
 * in one draw each: on llvmpipe every scissored draw costs about a tenth of a millisecond. */
int lx_plane_in_window(const struct lx_frame *f, int id, struct lx_rect box, vec3 *out);
/* Plane of interest id's image in the window where it lies beyond the GL's near plane, a
 * convex polygon in window pixels (n 0: none in front). */
void lx_plane_window(const struct lx_frame *f, int id, struct lx_poly *out);
/* Whether window rectangle box lies inside that image, its corners a hundredth of a pixel
 * in or more: then lx_plane_in_window gives the rectangle itself, which the GL draws
 * uncut, its edges on whole pixels. */
bool lx_plane_window_holds(const struct lx_poly *window, struct lx_rect box);

#endif
