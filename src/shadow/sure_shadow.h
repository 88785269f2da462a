/* Where a caster's shadow on a plane of interest is sure, GL-free.
 *
 * The main pass looks a plane's maps up only where a shadow can fall (lookup_region.h);
 * inside a caster's shadow it need not look either: every lookup there reads the
 * caster. A map holds a convex caster wherever its image covers a lixel's centre (the
 * shadow pass draws its faces turned away from the light, whose images together are the
 * whole image), so a point of the plane whose own image lies a margin inside the caster's
 * reads a lixel the caster was drawn in, at a depth no farther than the caster's
 * farthest; where the plane lies farther still, by more than the lookup's bias, the
 * compare shadows it. There the plane is drawn in the light's shadow without a lookup,
 * the same decision for less work (on the default view, a quarter of the pixels
 * plane-optimal looked up at 1024x1024). */
#ifndef LX_SURE_SHADOW_H
#define LX_SURE_SHADOW_H
#include "shadow_method.h"

/* The window polygon (pixels, GL's origin; convex, counter-clockwise) where every point
 * of plane `plane`'s plane is decided in the shadow of caster `id` by a lookup of `map`
 * alone, placed in a region of w x h lixels: its image lies `inset` lixels or more inside
 * the image of the caster's n points (object space floats, as the GL gets them: corners
 * of its convex mesh, so their image's hull lies within the image the map holds; pts[3 k]
 * onwards, or pts[3 index[k]] with an index; pts NULL: a box caster, whose mesh's corners
 * are its bounds' 8, and n is 8) and inside the rays the map serves (map->bounds), and its depth in the
 * map exceeds the caster's farthest by `depth_gap` (in the map's normalized depth, -1 to
 * 1) or more. False, and win empty, where there is none to give: the caster reaches
 * behind the light or outside the map's depth range (a map that flattens casters onto
 * its near plane, map->plane < 0, may have them nearer), or lies too near the plane (a
 * leg standing on the floor), the polygon's points lie behind the light or the eye, or
 * nothing is left of the image. */
bool lx_sure_shadow_window(const struct lx_frame *f, const struct lx_shadow_map *map, int w, int h, int id,
			   const float *pts, const unsigned short *index, int n, int plane, double inset, double depth_gap, struct lx_poly *win);

#endif
