#include "atlas.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The placed regions (w, h > 0) in packing order: tallest first, ties in the regions'
 * order. Returns their count. */
static int tallest_first(const struct lx_atlas *a, int *order)
{
	int n = 0;
	for (int i = 0; i < a->count; i++)
		if (a->regions[i].w > 0 && a->regions[i].h > 0)
			order[n++] = i;
	for (int i = 1; i < n; i++) /* insertion sort: stable */
		for (int j = i; j > 0 && a->regions[order[j]].h > a->regions[order[j - 1]].h; j--) {
			int t = order[j];
			order[j] = order[j - 1];
			order[j - 1] = t;
		}
	return n;
}

/* Next-fit shelves of the n rectangles w x h in order, shelves at most shelf_width wide,
 * gap between them and around them: x[i], y[i] for each, and the extent used. The
 * regions of an atlas (gap: its guard) and the atlases of a texture (gap 0) are both
 * packed so. */
static void shelves(const int *w, const int *h, const int *order, int n, int gap, long shelf_width, int *x, int *y,
		    int *width, int *height)
{
	int cx = gap, cy = gap, shelf_h = 0;
	*width = 0;
	for (int k = 0; k < n; k++) {
		int i = order[k];
		if (cx + w[i] + gap > shelf_width && cx > gap) {
			cy += shelf_h + gap;
			cx = gap;
			shelf_h = 0;
		}
		x[i] = cx;
		y[i] = cy;
		cx += w[i] + gap;
		if (cx > *width)
			*width = cx;
		if (h[i] > shelf_h)
			shelf_h = h[i];
	}
	*height = cy + shelf_h + gap;
}

/* The n regions in order packed in shelves from the atlas's origin; gives the extent used
 * (guards included), relative to the origin. */
static void pack_shelves(struct lx_atlas *a, const int *order, int n, int shelf_width, int *width, int *height)
{
	int w[LX_ATLAS_MAX_REGIONS], h[LX_ATLAS_MAX_REGIONS], x[LX_ATLAS_MAX_REGIONS], y[LX_ATLAS_MAX_REGIONS];
	for (int i = 0; i < a->count; i++)
		w[i] = a->regions[i].w, h[i] = a->regions[i].h;
	shelves(w, h, order, n, a->guard, shelf_width, x, y, width, height);
	for (int k = 0; k < n; k++) {
		struct lx_region *r = &a->regions[order[k]];
		r->x = a->x0 + x[order[k]];
		r->y = a->y0 + y[order[k]];
	}
}

/* The fixed-size layout: every prefix sum of widths as a shelf width, smallest area wins. */
static bool layout_fixed(struct lx_atlas *atlas, int max_size)
{
	int order[LX_ATLAS_MAX_REGIONS], count = tallest_first(atlas, order), guard = atlas->guard;
	long min_width = 0;
	for (int i = 0; i < count; i++)
		if (atlas->regions[i].w + 2L * guard > min_width)
			min_width = atlas->regions[i].w + 2L * guard;
	struct lx_atlas best = {0};
	long best_area = -1;
	int best_side = 0;
	long shelf = guard;
	for (int i = 0; i < count; i++) {
		shelf += atlas->regions[order[i]].w + guard;
		if (shelf < min_width || shelf > max_size)
			continue;
		struct lx_atlas trial = *atlas;
		pack_shelves(&trial, order, count, (int)shelf, &trial.width, &trial.height);
		if (trial.width > max_size || trial.height > max_size)
			continue;
		long area = (long)trial.width * trial.height;
		int side = trial.width > trial.height ? trial.width : trial.height;
		if (best_area < 0 || area < best_area || (area == best_area && side < best_side)) {
			best = trial;
			best_area = area;
			best_side = side;
		}
	}
	if (best_area < 0)
		return false;
	*atlas = best;
	atlas->max_side = atlas->width - 2 * guard;
	return true;
}

static long isqrt_floor(long n)
{
	long r = (long)sqrt((double)n);
	while (r * r > n)
		r--;
	while ((r + 1) * (r + 1) <= n)
		r++;
	return r;
}

/* The texture for variable regions. Its width holds the most elongated shape any region
 * may take (LX_ATLAS_MAX_ASPECT : 1); its height follows the bound of next-fit
 * decreasing-height shelf packing (Coffman, Garey, Johnson and Tarjan, 1980): with items
 * no wider than the strip, height <= tallest item + 2 x items' area / strip width. Items
 * are the regions turned landscape and grown by one guard, in a strip width - guard wide. */
static bool layout_variable(struct lx_atlas *a, int max_size)
{
	int g = a->guard, cap = max_size < LX_ATLAS_MAX_SIDE ? max_size : LX_ATLAS_MAX_SIDE;
	long want = 1;
	for (int i = 0; i < a->count; i++) {
		const struct lx_region *r = &a->regions[i];
		long side = r->variable ? isqrt_floor(LX_ATLAS_MAX_ASPECT * r->budget) + 1 : (r->w > r->h ? r->w : r->h);
		if (side + 2L * g > want)
			want = side + 2L * g;
	}
	int width = (int)(want < cap ? want : cap);
	int max_side = width - 2 * g;
	double area = 0;
	long tallest = 0;
	for (int i = 0; i < a->count; i++) {
		const struct lx_region *r = &a->regions[i];
		long tall, sum; /* the item's tallest landscape height and the most its w + h can be */
		if (r->variable) {
			long root = isqrt_floor(r->budget);
			tall = root;
			double longest = max_side + (double)r->budget / max_side;
			sum = (long)ceil(fmax(2.0 * root + 2, longest + 1));
		} else {
			tall = r->w < r->h ? r->w : r->h;
			sum = r->w + r->h;
		}
		area += (double)r->counted + (double)g * sum + (double)g * g; /* a frame holds the total budget at most */
		if (tall > tallest)
			tallest = tall;
	}
	long height = g + (tallest + g) + (long)ceil(2.0 * area / (width - g)) + 1;
	if (height > cap)
		height = cap; /* a frame that cannot fit shrinks its regions (lx_atlas_pack) */
	a->width = width;
	a->height = (int)height;
	a->max_side = max_side;
	/* a region alone takes at most the square that fits the area, guards included; the
	 * area was sized without it, so it never grows the atlas */
	long fits = (long)(width < height ? width : height) - 2L * g;
	for (int i = 0; i < a->count; i++) {
		struct lx_region *r = &a->regions[i];
		if (r->alone > fits * fits)
			r->alone = fits * fits;
		if (r->alone <= r->budget)
			r->alone = 0;
	}
	return true;
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
	bool variable = false;
	for (int i = 0; i < count; i++)
		variable |= req[i].max_lixels > 0;
	/* variable regions keep to a small board's texture limit, fixed ones to the GL's */
	int side_cap = variable && max_size > LX_ATLAS_MAX_SIDE ? LX_ATLAS_MAX_SIDE : max_size;
	for (int i = 0; i < count; i++) {
		if (!req[i].name || !req[i].name[0] || strlen(req[i].name) >= LX_REGION_NAME_MAX) {
			snprintf(err, errlen, "atlas: region %d has no name or a name longer than %d characters", i, LX_REGION_NAME_MAX - 1);
			return false;
		}
		if (req[i].w < 1 || req[i].h < 1) {
			snprintf(err, errlen, "atlas: region '%s' is %dx%d lixels, expected at least 1x1", req[i].name, req[i].w, req[i].h);
			return false;
		}
		if (req[i].max_lixels < 0 || req[i].alone_lixels < 0 || (req[i].alone_lixels > 0 && req[i].max_lixels == 0)) {
			snprintf(err, errlen, "atlas: region '%s' may hold %ld lixels (%ld alone), expected 0 (fixed) or more, and "
				 "a limit alone only for a variable region", req[i].name, req[i].max_lixels, req[i].alone_lixels);
			return false;
		}
		for (int j = 0; j < i; j++)
			if (!strcmp(req[i].name, req[j].name)) {
				snprintf(err, errlen, "atlas: region name '%s' appears twice", req[i].name);
				return false;
			}
		if ((long)req[i].w + 2L * guard > side_cap || (long)req[i].h + 2L * guard > side_cap) {
			snprintf(err, errlen, "atlas: region '%s' (%dx%d lixels plus a %d-lixel guard) exceeds the maximum texture size %d",
				 req[i].name, req[i].w, req[i].h, guard, side_cap);
			return false;
		}
		struct lx_region *r = &atlas->regions[i];
		strcpy(r->name, req[i].name);
		r->w = req[i].w;
		r->h = req[i].h;
		r->variable = req[i].max_lixels > 0;
		r->budget = r->variable ? req[i].max_lixels : (long)req[i].w * req[i].h;
		if (r->variable && r->budget < (long)r->w * r->h)
			r->budget = (long)r->w * r->h;
		r->counted = req[i].borrowed ? 0 : (long)req[i].w * req[i].h;
		r->alone = req[i].alone_lixels > r->budget ? req[i].alone_lixels : 0;
	}
	atlas->count = count;
	atlas->guard = guard;
	if (count == 0) { /* a method without maps still gets a valid 1x1 texture */
		atlas->width = atlas->height = atlas->texture_width = atlas->texture_height = 1;
		return true;
	}
	if (!(variable ? layout_variable(atlas, max_size) : layout_fixed(atlas, max_size))) {
		snprintf(err, errlen, "atlas: %d regions (%ld lixels) do not fit in a %dx%d texture", count,
			 lx_atlas_lixels(atlas), max_size, max_size);
		return false;
	}
	if (variable) {
		int w[LX_ATLAS_MAX_REGIONS], h[LX_ATLAS_MAX_REGIONS];
		for (int i = 0; i < count; i++)
			w[i] = atlas->regions[i].w, h[i] = atlas->regions[i].h;
		/* the start sizes must fit as they are: nothing may shrink before the first frame */
		struct lx_atlas trial = *atlas;
		if (lx_atlas_pack(&trial, w, h) != 0) {
			snprintf(err, errlen, "atlas: %d regions (%ld lixels) do not fit in a %dx%d texture", count,
				 lx_atlas_lixels(atlas), atlas->width, atlas->height);
			return false;
		}
		*atlas = trial;
	}
	atlas->texture_width = atlas->width; /* alone in its texture until stacked */
	atlas->texture_height = atlas->height;
	return true;
}

/* Next fit decreasing height in the fixed texture; false when the shelves overflow it. */
static bool pack_nfdh(struct lx_atlas *a)
{
	int order[LX_ATLAS_MAX_REGIONS], n = tallest_first(a, order), width, height;
	for (int k = 0; k < n; k++)
		if (a->regions[order[k]].w + 2 * a->guard > a->width)
			return false;
	pack_shelves(a, order, n, a->width, &width, &height);
	return height <= a->height;
}

int lx_atlas_pack(struct lx_atlas *a, const int *w, const int *h)
{
	bool variable = false;
	for (int i = 0; i < a->count; i++)
		variable |= a->regions[i].variable;
	if (!variable)
		return 0; /* fixed regions keep the layout of the start */
	int cw[LX_ATLAS_MAX_REGIONS], ch[LX_ATLAS_MAX_REGIONS], placed = 0;
	for (int i = 0; i < a->count; i++)
		placed += !a->regions[i].variable || (w[i] > 0 && h[i] > 0);
	for (int i = 0; i < a->count; i++) {
		struct lx_region *r = &a->regions[i];
		long budget = placed == 1 && r->alone > 0 ? r->alone : r->budget;
		if (!r->variable) {
			/* a fixed region keeps its size (and its turn, if the start gave it one) */
			cw[i] = r->turned ? r->h : r->w;
			ch[i] = r->turned ? r->w : r->h;
			continue;
		}
		cw[i] = w[i] > 0 && h[i] > 0 ? w[i] : 0;
		ch[i] = w[i] > 0 && h[i] > 0 ? h[i] : 0;
		/* within the region's budget and the texture's longest side */
		if (cw[i] > a->max_side)
			cw[i] = a->max_side;
		if (ch[i] > a->max_side)
			ch[i] = a->max_side;
		while ((long)cw[i] * ch[i] > budget) {
			if (cw[i] >= ch[i])
				cw[i]--;
			else
				ch[i]--;
		}
	}
	for (int shrunk = 0;; shrunk++) {
		for (int i = 0; i < a->count; i++) {
			struct lx_region *r = &a->regions[i];
			r->turned = ch[i] > cw[i];
			r->w = r->turned ? ch[i] : cw[i];
			r->h = r->turned ? cw[i] : ch[i];
			r->x = a->x0; /* an unplaced region stays inside the atlas's own area */
			r->y = a->y0;
		}
		if (pack_nfdh(a))
			return shrunk;
		bool smaller = false;
		for (int i = 0; i < a->count; i++)
			if (a->regions[i].variable && (cw[i] > 1 || ch[i] > 1)) {
				cw[i] = cw[i] > 1 ? (int)(cw[i] * 0.9) : cw[i];
				ch[i] = ch[i] > 1 ? (int)(ch[i] * 0.9) : ch[i];
				smaller = true;
			}
		if (!smaller) { /* nothing left to shrink (the fixed regions alone overflow) */
			for (int i = 0; i < a->count; i++)
				if (a->regions[i].variable)
					a->regions[i].w = a->regions[i].h = 0;
			return -1;
		}
	}
}

/* Where the parts go in their texture, and its size. */
struct stack_plan {
	int x[LX_ATLAS_MAX_PARTS], y[LX_ATLAS_MAX_PARTS];
	int width, height;
};

/* The smallest texture (then the squarest, then the first tried) of a few arrangements:
 * shelves of the parts tallest first, every shelf width from the widest part's to all in
 * one row; then the same a quarter turned (columns, widest first, up to all in one
 * column). Four rectangles at most need no search; the choice follows the sizes alone. */
static bool best_stack(const int *pw, const int *ph, int n, int cap, struct stack_plan *best)
{
	bool found = false;
	long best_area = 0;
	int best_side = 0;
	for (int turn = 0; turn < 2; turn++) {
		const int *w = turn ? ph : pw, *h = turn ? pw : ph;
		int order[LX_ATLAS_MAX_PARTS], widest = 0;
		for (int i = 0; i < n; i++) { /* insertion sort, tallest first: stable */
			int j = i;
			for (; j > 0 && h[order[j - 1]] < h[i]; j--)
				order[j] = order[j - 1];
			order[j] = i;
			widest = w[i] > widest ? w[i] : widest;
		}
		long shelf = 0;
		for (int k = -1; k < n; k++) {
			long shelf_width = k < 0 ? widest : (shelf += w[order[k]]);
			if (shelf_width < widest)
				continue;
			struct stack_plan p;
			if (turn)
				shelves(w, h, order, n, 0, shelf_width, p.y, p.x, &p.height, &p.width);
			else
				shelves(w, h, order, n, 0, shelf_width, p.x, p.y, &p.width, &p.height);
			if (p.width > cap || p.height > cap)
				continue;
			long area = (long)p.width * p.height;
			int side = p.width > p.height ? p.width : p.height;
			if (!found || area < best_area || (area == best_area && side < best_side)) {
				*best = p;
				best_area = area;
				best_side = side;
				found = true;
			}
		}
	}
	return found;
}

bool lx_atlas_stack(struct lx_atlas *const *parts, int n, int max_size, char *err, size_t errlen)
{
	if (!parts || n < 1 || n > LX_ATLAS_MAX_PARTS || max_size < 1) {
		snprintf(err, errlen, "atlas: %d parts to stack, at most %d lixels a side; expected 1 to %d parts, size >= 1",
			 n, max_size, LX_ATLAS_MAX_PARTS);
		return false;
	}
	int w[LX_ATLAS_MAX_PARTS], h[LX_ATLAS_MAX_PARTS];
	bool variable = false;
	for (int i = 0; i < n; i++) {
		const struct lx_atlas *a = parts[i];
		if (!a || a->width < 1 || a->height < 1) {
			snprintf(err, errlen, "atlas: part %d to stack is not laid out", i);
			return false;
		}
		for (int j = 0; j < i; j++)
			if (parts[j] == a) { /* it would be moved twice */
				snprintf(err, errlen, "atlas: part %d to stack is part %d again", i, j);
				return false;
			}
		w[i] = a->width;
		h[i] = a->height;
		for (int r = 0; r < a->count; r++)
			variable |= a->regions[r].variable;
	}
	/* variable regions keep to a small board's texture limit (lx_atlas_layout) */
	int cap = variable && max_size > LX_ATLAS_MAX_SIDE ? LX_ATLAS_MAX_SIDE : max_size;
	struct stack_plan p;
	if (!best_stack(w, h, n, cap, &p)) {
		int len = snprintf(err, errlen, "atlas: %d parts (", n);
		for (int i = 0; i < n && len >= 0 && (size_t)len < errlen; i++)
			len += snprintf(err + len, errlen - len, "%s%dx%d", i ? ", " : "", w[i], h[i]);
		if (len >= 0 && (size_t)len < errlen)
			snprintf(err + len, errlen - len, ") do not fit together in a %dx%d texture", cap, cap);
		return false;
	}
	for (int i = 0; i < n; i++) {
		struct lx_atlas *a = parts[i];
		int dx = p.x[i] - a->x0, dy = p.y[i] - a->y0; /* from wherever an earlier stacking put it */
		for (int r = 0; r < a->count; r++) {
			a->regions[r].x += dx;
			a->regions[r].y += dy;
		}
		a->x0 = p.x[i];
		a->y0 = p.y[i];
		a->texture_width = p.width;
		a->texture_height = p.height;
	}
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
		s += atlas->regions[i].counted;
	return s;
}

long lx_atlas_placed(const struct lx_atlas *atlas)
{
	long s = 0;
	for (int i = 0; i < atlas->count; i++)
		s += (long)atlas->regions[i].w * atlas->regions[i].h;
	return s;
}

void lx_region_to_texture(const struct lx_atlas *atlas, int region, double m[4])
{
	const struct lx_region *g = &atlas->regions[region];
	double tw = atlas->texture_width, th = atlas->texture_height; /* >= 1 once laid out */
	m[0] = 0.5 * g->w / tw, m[1] = (g->x + 0.5 * g->w) / tw;
	m[2] = 0.5 * g->h / th, m[3] = (g->y + 0.5 * g->h) / th;
}

double lx_atlas_fill(const struct lx_atlas *atlas)
{
	/* of the atlas's own area, not the shared texture: each light's use of its part */
	return (double)lx_atlas_placed(atlas) / ((double)atlas->width * atlas->height); /* width, height >= 1 */
}
