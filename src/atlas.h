/* The shadow atlas: named shadow-map regions packed into one RGBA8 texture.
 * GL-free. Each region gets exactly its budget of w x h lixels; a guard band of
 * `guard` lixels surrounds every region inside the texture and is never written by
 * a shadow pass (it keeps the clear value, "far"), so a lookup that lands just
 * outside a region reads "lit" and never a neighbour's depth. */
#ifndef LX_ATLAS_H
#define LX_ATLAS_H
#include <stdbool.h>
#include <stddef.h>

#define LX_ATLAS_MAX_REGIONS 8
#define LX_REGION_NAME_MAX 16

struct lx_region {
	char name[LX_REGION_NAME_MAX];
	int w, h; /* the budget, in lixels */
	int x, y; /* lower-left lixel inside the atlas texture */
};

struct lx_atlas {
	int width, height; /* texture size */
	int guard;
	int count;
	struct lx_region regions[LX_ATLAS_MAX_REGIONS];
};

struct lx_region_request {
	const char *name;
	int w, h;
};

/* Packs the requests in shelves, trying every shelf width and keeping the smallest
 * texture area (then the squarest), within max_size on a side. Returns false with a
 * one-line reason in err when a request is invalid or the regions cannot fit. */
bool lx_atlas_layout(struct lx_atlas *atlas, const struct lx_region_request *req, int count,
		     int guard, int max_size, char *err, size_t errlen);
const struct lx_region *lx_atlas_find(const struct lx_atlas *atlas, const char *name);
long lx_atlas_lixels(const struct lx_atlas *atlas); /* sum of the budgets */

#endif
