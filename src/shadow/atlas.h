/* The shadow atlas: named shadow-map regions packed into one RGBA8 texture.
 * GL-free. The atlas's size is fixed once, at start; regions whose shape follows the
 * view (the plane-optimal maps) are packed again every frame inside it. A guard band of
 * `guard` lixels surrounds every region and is cleared to "far" with it and never drawn,
 * so a lookup that lands just outside a region reads "lit" and never a neighbour's
 * depth. Several lights' atlases (parts) can share one texture: lx_atlas_stack places
 * them side by side, each keeping its own area, so each packs its frames as if alone. */
#ifndef LX_ATLAS_H
#define LX_ATLAS_H
#include <stdbool.h>
#include <stddef.h>

#define LX_ATLAS_MAX_REGIONS 8
#define LX_REGION_NAME_MAX 16

/* The largest texture side the atlas takes (VideoCore IV's limit), whatever the GL allows. */
#define LX_ATLAS_MAX_SIDE 2048
/* The most elongated region a variable region may take and still fit, long side : short side. */
#define LX_ATLAS_MAX_ASPECT 32
/* The most atlases (one per light) that lx_atlas_stack puts in one texture. */
#define LX_ATLAS_MAX_PARTS 4

struct lx_region {
	char name[LX_REGION_NAME_MAX];
	long budget;  /* the most lixels it may hold in a frame */
	long counted; /* what it adds to the total budget: w x h as requested, 0 when borrowed */
	bool variable; /* its shape changes per frame (else it is always its requested w x h) */
	long alone;    /* a variable region's most lixels in a frame where no other region is
			* placed (0: its budget then too): what fits in the atlas alone */
	int w, h;     /* this frame's size in the texture, in lixels; 0 x 0 when not placed */
	int x, y;     /* lower-left lixel in the texture (absolute: the atlas's origin included) */
	bool turned;  /* placed a quarter turn from its map's own axes (w, h are the placed size) */
};

struct lx_atlas {
	int width, height; /* this atlas's own area, fixed at start: its regions and guards lie inside it */
	int x0, y0;        /* the area's lower-left corner in the texture (lx_atlas_stack); 0, 0 alone */
	int texture_width, texture_height; /* the texture it lives in: width, height alone */
	int guard;
	int max_side; /* the longest side a variable region may take: width - 2 guard */
	int count;
	struct lx_region regions[LX_ATLAS_MAX_REGIONS];
};

struct lx_region_request {
	const char *name;
	int w, h;        /* its size at start; always, unless max_lixels is set */
	long max_lixels; /* 0: a fixed region; else the region's shape follows the frame and
			    it may hold up to this many lixels in one frame */
	bool borrowed;   /* its lixels come out of other regions' budgets (a map's second
			    piece, shared budgets): it adds nothing to the atlas's total */
	long alone_lixels; /* a variable region's most in a frame where it is the only region
			      placed (0: max_lixels); the layout lowers it to what fits alone */
};

/* Validates the requests and fixes the atlas's area, alone in its texture (origin 0, 0,
 * the texture its own size): for fixed regions only, the smallest shelf packing (then
 * the squarest); with variable regions, a size in which any frame's
 * shapes fit (each within its max_lixels and max_side, in any aspect), at most
 * min(max_size, LX_ATLAS_MAX_SIDE) on a side, provided a frame's regions together hold
 * no more than the total budget. The regions start at their requested
 * sizes. Returns false with a one-line reason in err when a request is invalid or the
 * regions cannot fit. */
bool lx_atlas_layout(struct lx_atlas *atlas, const struct lx_region_request *req, int count,
		     int guard, int max_size, char *err, size_t errlen);
/* One frame's placement inside the atlas's own area (from its origin x0, y0): region i
 * becomes w[i] x h[i] lixels (0 x 0: not placed this frame, left at the origin; a fixed
 * region ignores its entry and keeps its size and place; a variable region alone in the
 * frame may hold up to its `alone` lixels). Regions are turned to lie
 * landscape and packed by height in shelves (next fit decreasing height), deterministic
 * for given sizes. Should a frame's shapes not fit, the variable regions shrink by 10%
 * until they do (a map's light matrix covers its region whatever its lixel count);
 * returns how many times that happened, or -1 when even 1x1 does not fit (the variable
 * regions are then left unplaced, 0 x 0). */
int lx_atlas_pack(struct lx_atlas *atlas, const int *w, const int *h);
/* Puts n (1 to LX_ATLAS_MAX_PARTS) laid-out atlases, each keeping its width x height,
 * into one texture without overlap. Tried: shelves of the parts tallest first, every
 * shelf width from the widest part's to all in one row; then the same a quarter turned
 * (columns, widest first, up to all in one column). The smallest texture wins, then the
 * squarest, then the first tried (rows before columns, narrow shelves before wide). Its
 * sides are at most max_size, and at most LX_ATLAS_MAX_SIDE when a part has a variable
 * region (as lx_atlas_layout). Sets each part's x0, y0, texture_width and texture_height
 * and moves its regions with its origin; one part goes to the origin, alone in its
 * texture. False with a one-line reason in err, the parts unchanged, when they do not fit,
 * n is out of range or a part is missing, not laid out or given twice. */
bool lx_atlas_stack(struct lx_atlas *const *parts, int n, int max_size, char *err, size_t errlen);
const struct lx_region *lx_atlas_find(const struct lx_atlas *atlas, const char *name);
/* The total budget: the most lixels a frame's regions hold together (sum of counted). */
long lx_atlas_lixels(const struct lx_atlas *atlas);
long lx_atlas_placed(const struct lx_atlas *atlas);  /* lixels of this frame's regions */
double lx_atlas_fill(const struct lx_atlas *atlas);  /* placed lixels / texture texels */
/* Region clip space -> the texture's s, t: s = m[1] + m[0] x, t = m[3] + m[2] y for x, y
 * in [-1, 1] over the region (its place is absolute in the texture every light's atlas
 * shares). */
void lx_region_to_texture(const struct lx_atlas *atlas, int region, double m[4]);

#endif
