#include "atlas.h"
#include <stdio.h>
#include <string.h>

/* Shelf packing for a given maximum shelf width; regions in order of decreasing height. */
static bool pack_shelves(struct lx_atlas *a, const int *order, int shelf_width, int guard, int max_size)
{
	int x = guard, y = guard, shelf_h = 0, width = 0;
	for (int i = 0; i < a->count; i++) {
		struct lx_region *r = &a->regions[order[i]];
		if (x + r->w + guard > shelf_width && x > guard) {
			y += shelf_h + guard;
			x = guard;
			shelf_h = 0;
		}
		r->x = x;
		r->y = y;
		x += r->w + guard;
		if (x > width)
			width = x;
		if (r->h > shelf_h)
			shelf_h = r->h;
	}
	a->width = width;
	a->height = y + shelf_h + guard;
	return a->width <= max_size && a->height <= max_size;
}

bool lx_atlas_layout(struct lx_atlas *atlas, const struct lx_region_request *req, int count,
		     int guard, int max_size, char *err, size_t errlen)
{
	memset(atlas, 0, sizeof(*atlas));
	if (count < 0 || count > LX_ATLAS_MAX_REGIONS) {
		snprintf(err, errlen, "atlas: %d regions requested, expected 0 to %d", count, LX_ATLAS_MAX_REGIONS);
		return false;
	}
	if (guard < 0 || max_size < 1) {
		snprintf(err, errlen, "atlas: guard %d and maximum size %d, expected guard >= 0 and size >= 1", guard, max_size);
		return false;
	}
	int order[LX_ATLAS_MAX_REGIONS];
	long min_width = 0;
	for (int i = 0; i < count; i++) {
		if (!req[i].name || !req[i].name[0] || strlen(req[i].name) >= LX_REGION_NAME_MAX) {
			snprintf(err, errlen, "atlas: region %d has no name or a name longer than %d characters", i, LX_REGION_NAME_MAX - 1);
			return false;
		}
		if (req[i].w < 1 || req[i].h < 1) {
			snprintf(err, errlen, "atlas: region '%s' is %dx%d lixels, expected at least 1x1", req[i].name, req[i].w, req[i].h);
			return false;
		}
		for (int j = 0; j < i; j++)
			if (!strcmp(req[i].name, req[j].name)) {
				snprintf(err, errlen, "atlas: region name '%s' appears twice", req[i].name);
				return false;
			}
		if ((long)req[i].w + 2L * guard > max_size || (long)req[i].h + 2L * guard > max_size) {
			snprintf(err, errlen, "atlas: region '%s' (%dx%d lixels plus a %d-lixel guard) exceeds the GL maximum texture size %d",
				 req[i].name, req[i].w, req[i].h, guard, max_size);
			return false;
		}
		strcpy(atlas->regions[i].name, req[i].name);
		atlas->regions[i].w = req[i].w;
		atlas->regions[i].h = req[i].h;
		order[i] = i;
		if (req[i].w + 2L * guard > min_width)
			min_width = req[i].w + 2L * guard;
	}
	atlas->count = count;
	atlas->guard = guard;
	if (count == 0) { /* a method without maps still gets a valid 1x1 texture */
		atlas->width = atlas->height = 1;
		return true;
	}
	for (int i = 1; i < count; i++) /* insertion sort, tallest first; stable */
		for (int j = i; j > 0 && atlas->regions[order[j]].h > atlas->regions[order[j - 1]].h; j--) {
			int t = order[j];
			order[j] = order[j - 1];
			order[j - 1] = t;
		}
	/* Candidate shelf widths: every prefix sum of region widths in packing order. */
	struct lx_atlas best = {0};
	long best_area = -1;
	int best_side = 0;
	long shelf = guard;
	for (int i = 0; i < count; i++) {
		shelf += atlas->regions[order[i]].w + guard;
		if (shelf < min_width || shelf > max_size)
			continue;
		struct lx_atlas trial = *atlas;
		if (!pack_shelves(&trial, order, (int)shelf, guard, max_size))
			continue;
		long area = (long)trial.width * trial.height;
		int side = trial.width > trial.height ? trial.width : trial.height;
		if (best_area < 0 || area < best_area || (area == best_area && side < best_side)) {
			best = trial;
			best_area = area;
			best_side = side;
		}
	}
	if (best_area < 0) {
		snprintf(err, errlen, "atlas: %d regions (%ld lixels) do not fit in a %dx%d texture", count,
			 lx_atlas_lixels(atlas), max_size, max_size);
		return false;
	}
	*atlas = best;
	return true;
}

const struct lx_region *lx_atlas_find(const struct lx_atlas *atlas, const char *name)
{
	for (int i = 0; i < atlas->count; i++)
		if (!strcmp(atlas->regions[i].name, name))
			return &atlas->regions[i];
	return NULL;
}

long lx_atlas_lixels(const struct lx_atlas *atlas)
{
	long s = 0;
	for (int i = 0; i < atlas->count; i++)
		s += (long)atlas->regions[i].w * atlas->regions[i].h;
	return s;
}
