/* The shadow atlas: named shadow-map regions packed into one RGBA8 texture.
 * GL-free. The texture's size is fixed once, at start; regions whose shape follows the
 * view (the plane-optimal maps) are packed again every frame inside it. A guard band of
 * `guard` lixels surrounds every region and is cleared to "far" with it and never drawn,
 * so a lookup that lands just outside a region reads "lit" and never a neighbour's
 * depth. */
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

struct lx_region {
	char name[LX_REGION_NAME_MAX];
	long budget;  /* the most lixels it may hold in a frame */
	long counted; /* what it adds to the total budget: w x h as requested, 0 when borrowed */
	bool variable; /* its shape changes per frame (else it is always its requested w x h) */
	int w, h;     /* this frame's size in the texture, in lixels; 0 x 0 when not placed */
	int x, y;     /* lower-left lixel inside the atlas texture */
	bool turned;  /* placed a quarter turn from its map's own axes (w, h are the placed size) */
};

struct lx_atlas {
	int width, height; /* texture size, fixed at start */
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
};

/* Validates the requests and fixes the texture: for fixed regions only, the smallest
 * shelf packing (then the squarest); with variable regions, a size in which any frame's
 * shapes fit (each within its max_lixels and max_side, in any aspect), at most
 * min(max_size, LX_ATLAS_MAX_SIDE) on a side, provided a frame's regions together hold
 * no more than the total budget. The regions start at their requested
 * sizes. Returns false with a one-line reason in err when a request is invalid or the
 * regions cannot fit. */
bool lx_atlas_layout(struct lx_atlas *atlas, const struct lx_region_request *req, int count,
		     int guard, int max_size, char *err, size_t errlen);
/* One frame's placement: region i becomes w[i] x h[i] lixels (0 x 0: not placed this
 * frame; a fixed region ignores its entry and keeps its size). Regions are turned to lie
 * landscape and packed by height in shelves (next fit decreasing height), deterministic
 * for given sizes. Should a frame's shapes not fit, the variable regions shrink by 10%
 * until they do (a map's light matrix covers its region whatever its lixel count);
 * returns how many times that happened, or -1 when even 1x1 does not fit (the variable
 * regions are then left unplaced, 0 x 0). */
int lx_atlas_pack(struct lx_atlas *atlas, const int *w, const int *h);
const struct lx_region *lx_atlas_find(const struct lx_atlas *atlas, const char *name);
/* The total budget: the most lixels a frame's regions hold together (sum of counted). */
long lx_atlas_lixels(const struct lx_atlas *atlas);
long lx_atlas_placed(const struct lx_atlas *atlas);  /* lixels of this frame's regions */
double lx_atlas_fill(const struct lx_atlas *atlas);  /* placed lixels / texture texels */

#endif
