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
 * are its bounds' 8, and n is 8; of a box reaching behind the light, the part in front)
 * and inside the rays the map serves (map->bounds), in front of the light and beyond the
 * eye's near plane, and its depth in the map exceeds the caster's by `depth_gap` (in the
 * map's normalized depth, -1 to 1) or more: beyond the caster's farthest, or else ray by
 * ray, the plane's depth along each ray (linear in clip coordinates) against the points
 * the caster lies within. False, and win empty, where there is none to give: the
 * caster's points (pts) reach behind the light, or it lies too near the plane (a leg
 * standing on the floor) or beyond the map's far plane, or nothing is left of the
 * image. Where a plane map's near plane clips the caster (one next to the light, which
 * the method warns of) a lookup may call a pixel of the window lit that lies in the
 * caster's shadow all the same. */
bool lx_sure_shadow_window(const struct lx_frame *f, const struct lx_shadow_map *map, int w, int h, int id,
			   const float *pts, const unsigned short *index, int n, int plane, double inset, double depth_gap, struct lx_poly *win);

#endif
