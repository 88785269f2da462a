/* Plane-optimal shadow maps ([Chong-Gortler]): one map per plane of
 * interest (the scene's first two planes: floor and wall, or table and floor) whose
 * light image samples that plane exactly where the view's pixels do, and a small
 * conventional fallback map, focused on the receivers no plane map takes (the casters
 * in view, and planes left without a map).
 *
 * Per plane map: the plane-optimal camera (plane_optimal.c), then A_l: a mirror when the
 * eye sees the plane's unlit side, optionally the paper's twist (the line where this
 * plane meets the next one level), and per piece (one rectangle around the casters'
 * footprints, or two around two clusters of them) a scale set by the lixel budget and a
 * translation to lixel (0, 0); the map's w x h follows the pieces' aspect. Depth is
 * fitted once per plane to the casters and the plane's wanted part (unit cube clipping
 * in z). Each plane's pixels read only its own maps; a caster reads the plane maps that
 * are dense enough for it, then the fallback. */
#include "light_space.h"
#include "plane_cover.h"
#include "plane_optimal.h"
#include <math.h>
#include <string.h>

#define PLANE_MAPS 2
#define PIECES_MAX 4   /* a plane's rectangles: its own region and up to three spare pieces */
#define SPARE_PIECES 4 /* the atlas's spare regions, taken by the planes where they gain most */

/* The regions: one per plane of interest (at most two), the fallback, and with fitted
 * shapes the spare pieces that the plane maps take when their casters' footprints form
 * clusters (plane_splits). */
static int plane_regions(const struct lx_scene *s, const struct lx_method_options *o, struct lx_region_request *out)
{
	int n = 0, planes = s->plane_count < PLANE_MAPS ? s->plane_count : PLANE_MAPS;
	long budget = (long)o->plane_lixels * o->plane_lixels;
	/* fitted maps vary their shape per frame; shared budgets let one take the others' rest */
	long most = o->square_regions ? 0 : o->shared_budget ? budget * planes : budget;
	for (int i = 0; i < planes; i++)
		out[n++] = (struct lx_region_request){s->planes[i].name, o->plane_lixels, o->plane_lixels, most, false, 0};
	/* with shared budgets the fallback grows by what the plane maps leave; with fixed
	 * ones, in a frame without a plane map, it takes the planes' budgets too, as far as
	 * the atlas holds it alone, and in a frame with a plane without a map, up to a plane's
	 * budget (fallback_side) */
	long fb = (long)o->fallback_lixels * o->fallback_lixels;
	bool grows = !o->square_regions && planes > 0;
	long fb_most = grows ? (o->shared_budget ? budget * planes + fb : planes > 1 && budget > fb ? budget : fb) : 0;
	long fb_alone = grows && !o->shared_budget && !(o->plane_max_lpp > 0) ? budget * planes + fb : 0;
	out[n++] = (struct lx_region_request){"fallback", o->fallback_lixels, o->fallback_lixels, fb_most, false, fb_alone};
	if (!o->square_regions && planes > 0) {
		/* the spare pieces (plane_build), under names no plane has: the regions' names
		 * must differ */
		static const char *const piece_names[][SPARE_PIECES] = {{"piece", "piece-2", "piece-3", "piece-4"},
									 {"spare", "spare-2", "spare-3", "spare-4"},
									 {"plane-piece", "plane-piece-2", "plane-piece-3", "plane-piece-4"}};
		for (int p = 0; p < 3; p++) {
			bool taken = false;
			for (int k = 0; k < SPARE_PIECES; k++)
				for (int i = 0; i < planes; i++)
					taken |= !strcmp(s->planes[i].name, piece_names[p][k]);
			if (taken)
				continue;
			for (int k = 0; k < SPARE_PIECES; k++)
				out[n++] = (struct lx_region_request){piece_names[p][k], 1, 1, most, true, 0};
			break;
		}
	}
	return n;
}

/* The twist: a rotation of the light image that turns the line where plane `self`
 * meets plane `other` horizontal, with this plane's visible polygon below it. */
static bool twist_angle(const struct lx_view *v, const struct lx_plane *self, const struct lx_plane *other,
			const struct lx_poly *visible, double *angle)
{
	vec4 a = lx_plane_equation(self), b = lx_plane_equation(other);
	vec3 na = v3(a.x, a.y, a.z), nb = v3(b.x, b.y, b.z), dir = v3_cross(na, nb);
	if (!(v3_len(dir) > 1e-9))
		return false; /* parallel planes (table and floor) meet nowhere */
	/* a point on both planes: the least-norm solution of na.p = -a.w, nb.p = -b.w */
	double m11 = v3_dot(na, na), m12 = v3_dot(na, nb), m22 = v3_dot(nb, nb), det = m11 * m22 - m12 * m12;
	double k1 = (-a.w * m22 + b.w * m12) / det, k2 = (-b.w * m11 + a.w * m12) / det; /* det > 0: not parallel */
	vec3 p0 = v3_add(v3_scale(na, k1), v3_scale(nb, k2)), p1 = v3_add(p0, dir);
	double s[2][3];
	vec3 pts[2] = {p0, p1};
	for (int i = 0; i < 2; i++) {
		vec4 c = m4_mul_point(&v->view_proj, pts[i]);
		s[i][0] = (c.x + c.w) * 0.5 * v->width;
		s[i][1] = (c.y + c.w) * 0.5 * v->height;
		s[i][2] = c.w;
	}
	double l0 = s[0][1] * s[1][2] - s[0][2] * s[1][1], l1 = s[0][2] * s[1][0] - s[0][0] * s[1][2],
	       l2 = s[0][0] * s[1][1] - s[0][1] * s[1][0];
	double len = hypot(l0, l1);
	if (!(len > 1e-12 * (fabs(l2) + 1)))
		return false; /* the line passes through the eye: it projects to a point */
	double cx = 0, cy = 0;
	for (int i = 0; i < visible->n; i++)
		cx += visible->v[i].x / visible->n, cy += visible->v[i].y / visible->n;
	*angle = atan2(l0, l1); /* turns the line's normal (l0, l1) to +y */
	if (l0 * cx + l1 * cy + l2 > 0)
		*angle += M_PI; /* keep this plane below the line */
	return true;
}

/* The planes bounding the receiver volume (view frustum within the scene box), as
 * half-spaces: only those that carry a face of it (three of its vertices or more), so
 * that a depth fit that needs them enumerates as few plane triples as it can. */
static int receiver_faces(const struct lx_frame *f, const struct lx_light_space *ls, vec4 *out)
{
	const mat4 *vp = &f->view.view_proj;
	vec4 all[12];
	int n = 0;
	for (int r = 0; r < 3; r++) { /* the view frustum: -w <= x, y, z <= w */
		all[n++] = v4_lin(1, m4_row(vp, 3), 1, m4_row(vp, r));
		all[n++] = v4_lin(1, m4_row(vp, 3), -1, m4_row(vp, r));
	}
	vec3 lo = f->lit_min, hi = f->lit_max; /* the objects in view that the light reaches: the only receivers */
	lx_box_halfspaces(lo, hi, all + n);
	n += 6;
	const vec3 *pts = ls->receiver_pts;
	int np = ls->receiver_count;
	double size = v3_len(v3_sub(hi, lo)) + 1e-300;
	int m = 0;
	for (int k = 0; k < n; k++) {
		double len = sqrt(all[k].x * all[k].x + all[k].y * all[k].y + all[k].z * all[k].z);
		int on = 0;
		for (int i = 0; i < np && on < 3; i++)
			on += fabs(v4_dot_point(all[k], pts[i])) <= 1e-9 * size * len;
		if (on >= 3 || np == 0)
			out[m++] = all[k];
	}
	return m;
}

/* A plane's light image before A_l's scale: the plane-optimal camera, the visible
 * polygon, the wanted rays (window coordinates on the plane) turned by the twist, and
 * their bounding rectangle. */
struct plane_chart {
	struct lx_plane_camera cam;
	struct lx_poly win;
	vec3 world[32];
	int nw;
	double cs, sn;     /* the twist */
	double mx;         /* -1: the eye sees the plane from its unlit side, and the image is mirrored */
	bool on_grid;      /* the twist is a multiple of a quarter turn: pixel centres stay on a grid */
	double x0, y0, x1, y1; /* the turned wanted rays' bounds, in pixels */
	bool needs_fallback;   /* no map for the plane, yet shadows may fall on it: the fallback serves it */
	bool bounded;          /* every caster's footprint is known: the feet hold every shadow */
	struct lx_poly wanted; /* window coordinates: the visible plane where casters may shadow it */
	struct lx_poly covered; /* window coordinates: where the cover test shadows it (covered_part) */
	int plane;              /* the plane of interest charted */
	const bool *unmapped;   /* per object: no face of it in the maps, the fronts' tests decide
				 * its whole shadow (lx_shadow_result.slab_out) */
	int feet;              /* casters' own footprints on the visible plane, turned: their bounds */
	double foot[LX_MAX_PLANES + LX_MAX_CASTERS][4];
	double along_x, along_y; /* the footprint outlines' extents (chart_stretch); 0 for square lixels */
};

/* False when plane i gets no map this frame (warned where the user should know). */
/* Whether plane i can have a map this frame: lit on its front side (a light grazing
 * it, or lying in it, leaves it to the fallback), in view (seen edge-on: the fallback),
 * and with a light camera (lx_plane_camera_solve). Fills ch->win, world and cam. */
static bool chart_usable(const struct lx_frame *f, const struct lx_light_space *ls, int i, struct lx_shadow_result *out,
			 struct plane_chart *ch)
{
	const struct lx_plane *P = &f->scene->planes[i];
	const struct lx_view *v = &f->view;
	const struct lx_light *light = &f->light;
	vec4 pi = lx_plane_equation(P);
	/* the lit side faces away from the light: every point of the plane is shadowed by
	 * the facing rule, so its map would decide nothing */
	double facing = light->directional ? -v3_dot(v3(pi.x, pi.y, pi.z), light->direction) : v4_dot_point(pi, light->position);
	double near_limit = light->directional ? 1e-3 : lx_plane_near_limit(P);
	if (fabs(facing) < near_limit) {
		lx_shadow_warn(out, light->directional ? "plane %s: the light grazes the plane; its map is skipped and the fallback map serves it"
						     : "plane %s: the light is within %.3g m of the plane; its map is skipped and the fallback map serves it",
			       P->name, near_limit);
		ch->needs_fallback = true;
		return false;
	}
	if (facing < 0)
		return false;
	if (!lx_plane_visible(v, P, &ch->win, ch->world, &ch->nw)) {
		if (fabs(v4_dot_point(pi, v->eye)) < 1e-6 * ls->size && ch->nw > 0) {
			lx_shadow_warn(out, "plane %s is seen edge-on: no map for it this frame; the fallback map serves it", P->name);
			ch->needs_fallback = true;
		}
		return false; /* not in view: no pass, no fill */
	}
	vec3 c = v3(0, 0, 0);
	for (int k = 0; k < ch->nw; k++)
		c = v3_add(c, v3_scale(ch->world[k], 1.0 / ch->nw));
	enum lx_plane_camera_status st = lx_plane_camera_solve(v, lx_light_point(light), pi, (vec4){c.x, c.y, c.z, 1}, &ch->cam);
	if (st != LX_PLANE_CAMERA_OK) {
		static const char *const why[] = {"", "the light lies in the plane", "the eye lies in the plane",
						  "the five-point system is singular"};
		lx_shadow_warn(out, "plane %s: %s; its map is skipped and the fallback map serves it", P->name, why[st]);
		ch->needs_fallback = true;
		return false;
	}
	return true;
}

/* Points in the chart's light image, and whether all of them lie in front of it (from
 * the first that does not, pts holds zeros). */
static bool in_chart(const struct plane_chart *ch, const vec3 *x, int n, vec2 *pts)
{
	bool in_front = true;
	for (int k = 0; k < n; k++) {
		vec4 h = m4_mul_point(&ch->cam.m, x[k]);
		in_front &= h.w > 1e-12 * (fabs(h.x) + fabs(h.y) + fabs(h.z));
		pts[k] = in_front ? (vec2){h.x / h.w, h.y / h.w} : (vec2){0, 0};
	}
	return in_front;
}

/* Where object id's box lies against plane i, whose front the light faces (chart_usable).
 * BEHIND: wholly on the far side or in it (every corner at or behind the plane): each ray
 * from the light meets the plane before it, so it shadows nothing there, yet its image in
 * the plane's light view still covers part of the plane (the table's legs and slab under
 * its top). THROUGH: reaching beyond the plane by more than rounding (a caster standing
 * on it does not): only its part on the light's side shadows the plane, and its outline's
 * image would also hold the rest's (the cylinder beside the low table top). */
enum side { SIDE_FRONT, SIDE_THROUGH, SIDE_BEHIND };
static enum side plane_side(const struct lx_frame *f, int i, int id)
{
	vec4 pi = lx_plane_equation(&f->scene->planes[i]);
	double lo = INFINITY, hi = -INFINITY;
	int behind = 0;
	for (int k = 0; k < 8; k++) {
		double d = v4_dot_point(pi, v3_box_corner(f->bmin[id], f->bmax[id], k));
		behind += d <= 0;
		lo = d < lo ? d : lo, hi = d > hi ? d : hi;
	}
	if (behind == 8)
		return SIDE_BEHIND;
	return hi > 0 && lo < -1e-9 * (hi - lo) ? SIDE_THROUGH : SIDE_FRONT;
}

/* The casters' outlines in plane i's light image (lx_frame_object_outline's points,
 * caster c's from first[c], first[c + 1] - first[c] of them, in object order; whole[c]
 * false for one that reaches behind the light image, its points then meaningless:
 * casters_bound takes its clipped footprint instead). */
static void caster_outlines(const struct lx_frame *f, int i, const struct plane_chart *ch, vec2 *pts, bool *whole,
			    int *ids, int *first, int *nc)
{
	int np = 0;
	*nc = 0;
	for (int id = 0; id < f->object_count; id++) {
		if (!lx_object_can_cast(f, id) || ch->unmapped[id])
			continue; /* none of it in the maps: the fronts' tests decide its shadow */
		enum side sd = plane_side(f, i, id);
		if (sd == SIDE_BEHIND)
			continue;
		vec3 x[LX_OUTLINE_POINTS];
		int n = lx_frame_object_outline(f, id, true, x);
		ids[*nc] = id, first[*nc] = np;
		/* room: LX_OUTLINE_POINTS an object; one through the plane takes its box's part
		 * on the light's side (casters_bound) */
		whole[*nc] = in_chart(ch, x, n, pts + np) && sd != SIDE_THROUGH;
		(*nc)++;
		np += n;
	}
	first[*nc] = np;
}

/* Each whole caster's outline replaced by its hull, counter-clockwise (first[] moved to
 * match; a caster not charted whole keeps no points): the hull of all of them is the hull
 * of theirs (casters_bound, on about two thirds of the points), and each is its footprint's
 * polygon (chart_plane). */
static void outline_hulls(vec2 *pts, const bool *whole, int *first, int nc)
{
	int at = 0;
	for (int c = 0; c < nc; c++) {
		int from = first[c], n = first[c + 1] - from;
		first[c] = at;
		if (!whole[c])
			continue;
		struct lx_poly h;
		lx_poly_hull(pts + from, n, &h); /* at most n <= LX_OUTLINE_POINTS vertices: in place */
		memmove(pts + at, h.v, (size_t)h.n * sizeof(vec2));
		at += h.n;
	}
	first[nc] = at;
}

/* A_l's twist and mirror: a twist by a multiple of 90 degrees (a level camera facing the
 * wall) keeps the pixel grid, so it is snapped and lixel centres can fall exactly on
 * pixel centres; the map's image of the plane is the view's, mirrored when seen from the
 * side away from the light (faces turned to the light would wind clockwise in it, and
 * the shadow pass culls front faces and would store them): x is mirrored back. */
static void chart_orientation(const struct lx_frame *f, int i, int next, bool twist, struct plane_chart *ch)
{
	const struct lx_plane *P = &f->scene->planes[i];
	double angle = 0;
	if (twist && next >= 0 && !twist_angle(&f->view, P, &f->scene->planes[next], &ch->win, &angle))
		angle = 0;
	double quarter = round(angle / (M_PI / 2));
	ch->on_grid = fabs(angle - quarter * (M_PI / 2)) < 1e-6;
	ch->cs = cos(angle), ch->sn = sin(angle);
	if (ch->on_grid) {
		int k = ((int)quarter % 4 + 4) % 4;
		static const double c4[4] = {1, 0, -1, 0}, s4[4] = {0, 1, 0, -1};
		ch->cs = c4[k], ch->sn = s4[k];
	}
	ch->mx = v4_dot_point(lx_plane_equation(P), f->view.eye) < 0 ? -1 : 1;
}

/* The lixels' aspect on a plane whose budget cannot give every pixel a lixel. A shadow's
 * edges are where NEAREST lookups err, in a band as wide as a lixel across the edge; the
 * casters' footprint outlines stand for those edges (a box's shadow is the hull of its
 * corners' shadows). With lixels 1 / sx pixels wide and 1 / sy tall, an outline that runs
 * X pixels along x and Y along y (lx_poly_edges_inside) errs over about X / sy + Y / sx
 * pixels; for a given count of lixels, sx sy, that is least at sy / sx = X / Y: a
 * stretch of sqrt(X / Y), the map's y scaled up by it and its x down (then snapped:
 * fit_plane). A long shadow from a low light runs mostly one way (the table under the
 * low light at 1024x1024, shared budgets: 0.202% of the pixels wrong with square lixels,
 * 0.065% stretched and snapped to a lixel per pixel row; uniform 0.114%).
 * Kept within STRETCH_MAX either way (caps of 1.5 to 5 measured alike over 200 random
 * views), so that a thin shadow across the long side cannot fall between lixels. */
#define STRETCH_MAX 3.0
/* fit_scaled snaps an axis the stretch leaves short of a lixel per pixel only down to
 * this scale, the other axis then at s^2 >= 1/4 lixel per pixel: below it the model
 * promised more than it gave (the default scene at 1920x1080, the light facing the
 * camera, s = 0.34: 0.214% snapped against 0.158% not, uniform 0.124%) */
#define SNAP_MIN_SCALE 0.5
static double chart_stretch(double along_x, double along_y)
{
	if (!(along_x > 0 && along_y > 0))
		return along_x > 0 ? STRETCH_MAX : along_y > 0 ? 1 / STRETCH_MAX : 1;
	return lx_fmin(STRETCH_MAX, lx_fmax(1 / STRETCH_MAX, sqrt(along_x / along_y)));
}

/* A point, and a polygon, in the chart's frame: twisted and mirrored. */
static vec2 chart_point(const struct plane_chart *ch, vec2 p)
{
	return (vec2){ch->mx * (ch->cs * p.x - ch->sn * p.y), ch->sn * p.x + ch->cs * p.y};
}

static void to_chart(const struct plane_chart *ch, struct lx_poly *p)
{
	for (int k = 0; k < p->n; k++)
		p->v[k] = chart_point(ch, p->v[k]);
}

/* The footprint on plane i of object id when its corners' shadows do not all lie in front
 * of the eye (a light facing the camera throws shadows past it): the shadows' hull on the
 * plane, clipped to the near plane, in window coordinates. FOOT_LEVEL when a corner lies level with a point light or
 * beyond it (its shadow does not fall on the plane: the footprint is unbounded, or
 * nothing, caster_reach tells which), FOOT_EMPTY when nothing is left in front, FOOT_OPEN
 * when rounding leaves no bound. */
enum foot { FOOT_POLYGON, FOOT_EMPTY, FOOT_OPEN, FOOT_LEVEL };
#define FOOT_POINTS 56 /* a box's 8 corners, or a box cut by two planes: one vertex per triple of its 8 planes */
/* footprint_clipped for the hull of any points (at most FOOT_POINTS). */
static enum foot footprint_of(const struct lx_frame *f, int i, const vec3 *pts, int np, struct lx_poly *out)
{
	const struct lx_plane *P = &f->scene->planes[i];
	const struct lx_light *L = &f->light;
	vec4 pi = lx_plane_equation(P);
	vec3 n = v3(pi.x, pi.y, pi.z);
	double dl = L->directional ? 0 : v4_dot_point(pi, L->position), dn = L->directional ? v3_dot(n, L->direction) : 0;
	vec3 w[FOOT_POINTS];
	vec2 uv[FOOT_POINTS];
	for (int k = 0; k < np; k++) {
		vec3 c = pts[k];
		double dc = v4_dot_point(pi, c);
		if (L->directional ? !(dn < -1e-9) : !(dl - dc > 1e-9 * (1 + fabs(dl))))
			return FOOT_LEVEL;
		w[k] = L->directional ? v3_sub(c, v3_scale(L->direction, dc / dn))
				      : v3_add(L->position, v3_scale(v3_sub(c, L->position), dl / (dl - dc)));
		vec3 r = v3_sub(w[k], P->corner); /* coordinates on the plane: edge1, edge2 are independent */
		uv[k] = (vec2){v3_dot(r, P->edge1), v3_dot(r, P->edge2)};
	}
	struct lx_poly hull;
	lx_poly_hull(uv, np, &hull);
	vec4 h[FOOT_POINTS + 1], in[FOOT_POINTS];
	int m = 0, nin = 0;
	for (int v = 0; v < hull.n && nin < FOOT_POINTS; v++) /* the hull's vertices are points' shadows */
		for (int k = 0; k < np; k++)
			if (uv[k].x == hull.v[v].x && uv[k].y == hull.v[v].y) {
				in[nin++] = m4_mul_point(&f->view.view_proj, w[k]);
				break;
			}
	for (int v = 0; v < nin; v++) { /* in front of the near plane: w + z >= 0 */
		vec4 a = in[v], b = in[lx_loop_next(v, nin)];
		double da = a.w + a.z, db = b.w + b.z;
		if (da >= 0)
			h[m++] = a;
		if ((da >= 0) != (db >= 0)) {
			double t = da / (da - db); /* signs differ */
			h[m++] = (vec4){a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t, a.w + (b.w - a.w) * t};
		}
	}
	out->n = 0;
	for (int v = 0; v < m; v++) {
		if (!(h[v].w > 0))
			return FOOT_OPEN; /* in front of the near plane w > 0: rounding, and no bound */
		out->v[out->n++] = (vec2){(h[v].x / h[v].w + 1) * 0.5 * f->view.width, (h[v].y / h[v].w + 1) * 0.5 * f->view.height};
	}
	/* counter-clockwise in the plane's own axes, clockwise on the screen where the eye sees
	 * its other side (the table's top from under it): turned, as polygon2d.h's polygons
	 * are, else its intersection with the visible plane came out empty and its part was
	 * lost to the pieces */
	if (lx_poly_area(out) < 0)
		for (int a = 0, b = out->n - 1; a < b; a++, b--) {
			vec2 tmp = out->v[a];
			out->v[a] = out->v[b], out->v[b] = tmp;
		}
	return out->n >= 3 ? FOOT_POLYGON : FOOT_EMPTY;
}

/* footprint_of object id's box cut by the half-space `cut` (a x + b y + c z + d >= 0 kept;
 * NULL: none) and, where it reaches through plane i (plane_side), by the plane. */
static enum foot box_part_footprint(const struct lx_frame *f, int i, int id, const vec4 *cut, struct lx_poly *out)
{
	vec4 h[8];
	int nh = 6;
	lx_box_halfspaces(f->bmin[id], f->bmax[id], h);
	if (cut)
		h[nh++] = *cut;
	if (plane_side(f, i, id) == SIDE_THROUGH)
		h[nh++] = lx_plane_equation(&f->scene->planes[i]); /* >= 0 on the light's side (chart_usable) */
	vec3 pts[FOOT_POINTS];
	int np = 8;
	if (nh == 6)
		for (int k = 0; k < 8; k++)
			pts[k] = v3_box_corner(f->bmin[id], f->bmax[id], k);
	else
		np = lx_halfspace_vertices(h, nh, NULL, 0, pts, FOOT_POINTS);
	return np > 0 ? footprint_of(f, i, pts, np, out) : FOOT_EMPTY;
}

static enum foot footprint_clipped(const struct lx_frame *f, int i, int id, struct lx_poly *out)
{
	return box_part_footprint(f, i, id, NULL, out);
}

/* The distance from the origin to the convex polygon p (lx_poly_hull's winding; 0 inside
 * it). */
static double origin_distance(const struct lx_poly *p)
{
	if (lx_poly_contains(p, (vec2){0, 0}, 0))
		return 0;
	double best = INFINITY;
	for (int k = 0; k < p->n; k++) {
		vec2 a = p->v[k], b = p->v[lx_loop_next(k, p->n)], d = {b.x - a.x, b.y - a.y};
		double len2 = d.x * d.x + d.y * d.y, t = len2 > 0 ? lx_fmin(1, lx_fmax(0, -(a.x * d.x + a.y * d.y) / len2)) : 0;
		best = lx_fmin(best, hypot(a.x + t * d.x, a.y + t * d.y));
	}
	return best;
}

/* A box that straddles the point light's level as seen from plane i (corners on both
 * sides of the plane through the light parallel to i): only its part below that level
 * shadows the plane, and a point within delta of the level throws its shadow past the
 * plane's parallelogram. A point at r from the light's normal line and dc - as far
 * towards the light as it, of dl - throws its shadow r dl / (dl - dc) from the light's
 * foot F, so with r >= r_min (the box's distance from that line) and R the farthest
 * corner of the parallelogram from F, delta = r_min dl / (2 R) leaves those shadows
 * beyond 2 R. The box cut at dl - delta then bounds what falls on the plane. FOOT_OPEN
 * when the box meets the light's normal line (r_min 0). */
static enum foot straddling_reach(const struct lx_frame *f, int i, int id, struct lx_poly *out)
{
	const struct lx_plane *P = &f->scene->planes[i];
	vec4 pi = lx_plane_equation(P);
	vec3 nrm = v3(pi.x, pi.y, pi.z), L = f->light.position, e1, e2;
	double nn = v3_dot(nrm, nrm), dl = v4_dot_point(pi, L); /* nn > 0: a plane's edges are independent */
	if (!(dl > 0) || !v3_normalize(v3_cross(nrm, fabs(nrm.x) < 0.9 * sqrt(nn) ? v3(1, 0, 0) : v3(0, 1, 0)), &e1) ||
	    !v3_normalize(v3_cross(nrm, e1), &e2))
		return FOOT_OPEN;
	vec3 F = v3_sub(L, v3_scale(nrm, dl / nn)), q[4];
	lx_frame_plane_corners(f, i, q);
	double R = 0;
	for (int k = 0; k < 4; k++)
		R = lx_fmax(R, v3_len(v3_sub(q[k], F)));
	vec3 lo = f->bmin[id], hi = f->bmax[id];
	vec2 flat[8];
	for (int k = 0; k < 8; k++) {
		vec3 r = v3_sub(v3_box_corner(lo, hi, k), L);
		flat[k] = (vec2){v3_dot(r, e1), v3_dot(r, e2)};
	}
	struct lx_poly shadow_line;
	lx_poly_hull(flat, 8, &shadow_line);
	double r_min = origin_distance(&shadow_line);
	if (!(r_min > 1e-9 * (R + r_min)) || !(R > 0))
		return FOOT_OPEN;
	double level = dl - 0.5 * r_min * dl / R; /* < dl: r_min, dl, R > 0 */
	vec4 below = {-pi.x, -pi.y, -pi.z, level - pi.w}; /* pi . x <= level */
	enum foot r = box_part_footprint(f, i, id, &below, out);
	return r == FOOT_LEVEL ? FOOT_OPEN : r; /* rounding at the cut: no bound */
}

/* Where caster id can shadow the visible part of plane i, for one whose outline reaches
 * behind the chart's light image (its shadow passes the eye, or it reaches the light's
 * level): FOOT_POLYGON with its clipped footprint in *out, FOOT_EMPTY when it shadows
 * nothing there (its shadow lies wholly behind the eye, or it lies wholly level with the
 * point light or beyond it, so that no ray from the light through it meets the plane);
 * one that straddles the light's level is bounded where its shadow falls on the plane's
 * parallelogram (straddling_reach), FOOT_OPEN where that fails. */
static enum foot caster_reach(const struct lx_frame *f, int i, int id, struct lx_poly *out)
{
	enum foot r = footprint_clipped(f, i, id, out);
	if (r != FOOT_LEVEL)
		return r;
	if (f->light.directional)
		return FOOT_OPEN; /* a light not travelling towards the plane: no map asks (chart_usable) */
	vec4 pi = lx_plane_equation(&f->scene->planes[i]);
	double dl = v4_dot_point(pi, f->light.position);
	for (int k = 0; k < 8; k++)
		if (dl - v4_dot_point(pi, v3_box_corner(f->bmin[id], f->bmax[id], k)) > 1e-9 * (1 + fabs(dl)))
			return straddling_reach(f, i, id, out); /* one corner below the light, another not */
	return FOOT_EMPTY;
}

/* A caster's clipped footprint (caster_reach), window coordinates: at most the hull of
 * its box's 8 corners' shadows cut by one plane. */
struct reach {
	enum foot kind;
	int n;
	vec2 v[LX_OUTLINE_POINTS];
};

static struct lx_poly reach_poly(const struct reach *r)
{
	struct lx_poly p = {.n = r->n};
	memcpy(p.v, r->v, (size_t)r->n * sizeof(vec2));
	return p;
}

/* What the casters can shadow of plane i, in window coordinates, for its wanted rays: the
 * hull of the outlines of the casters charted whole and of the clipped footprints of the
 * others (caster_reach: a light facing the camera throws shadows past the eye; a caster
 * beyond the light's level throws none on the plane, one across it is cut where its
 * shadow leaves the plane's parallelogram); false when one cannot be bounded (the light
 * inside its box: every visible ray is wanted). reach[c]: the others' footprints. */
static bool casters_bound(const struct lx_frame *f, int i, const vec2 *pts, const bool *whole, const int *ids,
			  const int *first, int nc, struct reach *reach, struct lx_poly *cast)
{
	vec2 all[LX_OUTLINE_POINTS * (LX_MAX_PLANES + LX_MAX_CASTERS)];
	int n = 0;
	bool bounded = true;
	for (int c = 0; c < nc; c++) {
		reach[c].kind = FOOT_EMPTY, reach[c].n = 0;
		if (whole[c]) {
			memcpy(all + n, pts + first[c], (size_t)(first[c + 1] - first[c]) * sizeof(vec2));
			n += first[c + 1] - first[c];
			continue;
		}
		struct lx_poly fp;
		reach[c].kind = caster_reach(f, i, ids[c], &fp);
		if (reach[c].kind == FOOT_POLYGON && fp.n > LX_OUTLINE_POINTS)
			reach[c].kind = FOOT_OPEN; /* cannot happen: a box, cut once or not, has at most 13
						    * corners, and the near plane's cut adds one */
		bounded &= reach[c].kind != FOOT_OPEN;
		if (reach[c].kind != FOOT_POLYGON)
			continue;
		reach[c].n = fp.n;
		memcpy(reach[c].v, fp.v, (size_t)fp.n * sizeof(vec2));
		memcpy(all + n, fp.v, (size_t)fp.n * sizeof(vec2));
		n += fp.n;
	}
	if (bounded)
		lx_poly_hull(all, n, cast);
	return bounded;
}

/* Points of caster id's mesh (some of its vertices, world space) whose hull lies inside
 * it, as mesh.c builds it (32 segments around, 16 rings pole to pole): every fourth
 * vertex of a cylinder's or cone's rims (and the cone's apex); a sphere's poles, every
 * fourth vertex of its equator and every eighth of its rings at 45 and 135 degrees.
 * Returns the count (at most 18); 0 for a box, whose corners are its own. */
#define INNER_POINTS 18
static int round_inner_points(const struct lx_frame *f, int id, vec3 *x)
{
	static const double h2 = 0.70710678118654752; /* cos and sin of 45 degrees */
	static const double cs[8][2] = {{1, 0}, {h2, h2}, {0, 1}, {-h2, h2}, {-1, 0}, {-h2, -h2}, {0, -1}, {h2, -h2}};
	const struct lx_caster *c = &f->scene->casters[id - f->scene->plane_count];
	vec3 o = f->offset[id];
	double r = c->size.x, h = c->size.y;
	int n = 0;
	switch (c->shape) {
	case LX_SPHERE: /* rings at y = r (1 + cos th), radius r sin th: th = 45 and 135 degrees
			 * (every eighth vertex), 90 (every fourth) */
		x[n++] = v3_add(o, v3(0, 2 * r, 0)), x[n++] = o;
		for (int j = 0; j < 3; j++) {
			double ry = r * (j == 0 ? 1 + h2 : j == 1 ? 1 : 1 - h2), rr = r * (j == 1 ? 1 : h2);
			for (int k = 0; k < 8; k += j == 1 ? 1 : 2)
				x[n++] = v3_add(o, v3(rr * cs[k][0], ry, -rr * cs[k][1]));
		}
		return n;
	case LX_CYLINDER:
	case LX_CONE:
		for (int k = 0; k < 8; k++) {
			x[n++] = v3_add(o, v3(r * cs[k][0], 0, -r * cs[k][1]));
			if (c->shape == LX_CYLINDER)
				x[n++] = v3_add(o, v3(r * cs[k][0], h, -r * cs[k][1]));
		}
		if (c->shape == LX_CONE)
			x[n++] = v3_add(o, v3(0, h, 0));
		return n;
	default:
		return 0;
	}
}

/* The frame's casters' images in the window, shared by the planes and found as they are
 * asked for (take_hidden): first the bounds of a caster's box, then the image of its
 * mesh (the hull of points on it, a box's corners or round_inner_points) moved in by
 * HIDE_INSET pixels or more (the meshes' float vertices, and a pixel centre on the edge;
 * lx_poly_shrink). On the table most casters never get past their bounds. */
#define HIDE_INSET 1.0
enum { IMAGE_UNKNOWN, IMAGE_BOX, IMAGE_INSET, IMAGE_NONE };
struct caster_images {
	unsigned char state[LX_MAX_PLANES + LX_MAX_CASTERS];
	double bounds[LX_MAX_PLANES + LX_MAX_CASTERS][4]; /* the box's image's */
	struct lx_poly img[LX_MAX_PLANES + LX_MAX_CASTERS];
};

/* Caster id's box's image bounds (IMAGE_BOX), or IMAGE_NONE when the box reaches the near
 * plane or behind the eye (the near plane cuts it, and it hides only what it covers). */
static void caster_box_image(const struct lx_frame *f, struct caster_images *im, int id)
{
	double *b = im->bounds[id];
	b[0] = b[1] = INFINITY, b[2] = b[3] = -INFINITY;
	im->state[id] = IMAGE_BOX;
	for (int k = 0; k < 8; k++) {
		vec4 c = m4_mul_point(&f->view.view_proj, v3_box_corner(f->bmin[id], f->bmax[id], k));
		if (!(c.w > 0) || !(c.z > -c.w)) {
			im->state[id] = IMAGE_NONE;
			return;
		}
		vec2 w = lx_view_window_point(&f->view, c);
		b[0] = lx_fmin(b[0], w.x), b[1] = lx_fmin(b[1], w.y), b[2] = lx_fmax(b[2], w.x), b[3] = lx_fmax(b[3], w.y);
	}
}

/* Caster id's mesh's image, moved in (IMAGE_INSET), or IMAGE_NONE when nothing is left. */
static void caster_mesh_image(const struct lx_frame *f, struct caster_images *im, int id)
{
	vec3 x[INNER_POINTS];
	vec2 w[INNER_POINTS];
	int n = round_inner_points(f, id, x);
	if (n == 0) /* a box: its corners */
		for (; n < 8; n++)
			x[n] = v3_box_corner(f->bmin[id], f->bmax[id], n);
	for (int k = 0; k < n; k++) /* within the box: beyond the near plane */
		w[k] = lx_view_window_point(&f->view, m4_mul_point(&f->view.view_proj, x[k]));
	struct lx_poly hull;
	lx_poly_hull(w, n, &hull);
	lx_poly_shrink(&hull, HIDE_INSET, &im->img[id]);
	im->state[id] = im->img[id].n >= 3 ? IMAGE_INSET : IMAGE_NONE;
}

/* What hides one plane's footprints, found as hidden_feet asks: the frame's casters'
 * images (shared by the planes), per caster whether it hides this plane (0 not asked, 1
 * what its image covers, 2 nothing), and whether one hid some footprint. */
struct hiding {
	struct caster_images *images;
	unsigned char hides[LX_MAX_PLANES + LX_MAX_CASTERS];
	bool some;
};

/* The chart's bounds b of footprint `on` (window coordinates) narrowed to what casters do
 * not hide from the eye: a caster whose box lies wholly on the eye's side of the plane
 * (lx_frame_box_hides) meets the eye's ray to any point of the plane behind its image
 * before the plane, so a shadow there is never seen and needs no lixel. Each footprint's
 * part outside a caster's image bounds it (lx_poly_bounds_outside), so their bounds'
 * overlap holds the part outside all. False when a caster hides all of it. */
static bool take_hidden(const struct lx_frame *f, const struct plane_chart *ch, struct hiding *hd,
			const struct lx_poly *on, double *b)
{
	struct caster_images *im = hd->images;
	double x0, y0, x1, y1;
	lx_poly_bounds(on, &x0, &y0, &x1, &y1);
	vec2 ex = {ch->mx * ch->cs, -ch->mx * ch->sn}, ey = {ch->sn, ch->cs}; /* chart_point's axes */
	for (int id = f->scene->plane_count; id < f->object_count; id++) {
		if (im->state[id] == IMAGE_UNKNOWN)
			caster_box_image(f, im, id);
		const double *h = im->bounds[id];
		if (im->state[id] == IMAGE_NONE || !(h[0] < x1 && x0 < h[2] && h[1] < y1 && y0 < h[3]))
			continue; /* apart: nothing to take away */
		if (hd->hides[id] == 0) {
			vec2 corner[8];
			hd->hides[id] = lx_frame_box_hides(f, id, ch->plane, corner) ? 1 : 2;
		}
		if (hd->hides[id] != 1)
			continue;
		if (im->state[id] == IMAGE_BOX)
			caster_mesh_image(f, im, id);
		if (im->state[id] != IMAGE_INSET)
			continue;
		double r[4];
		hd->some = true;
		if (!lx_poly_bounds_outside(on, &im->img[id], ex, ey, r))
			return false;
		b[0] = lx_fmax(b[0], r[0]), b[1] = lx_fmax(b[1], r[1]), b[2] = lx_fmin(b[2], r[2]), b[3] = lx_fmin(b[3], r[3]);
	}
	return b[0] <= b[2] && b[1] <= b[3];
}

/* The footprints' parts on the visible plane in window coordinates, as add_foot keeps
 * them (the chart's feet in the same order), for hidden_feet. */
struct foot_parts {
	int n;
	struct lx_poly on[LX_MAX_PLANES + LX_MAX_CASTERS];
};

/* The bounds in the chart of polygon p (window coordinates). */
static void chart_bounds(const struct plane_chart *ch, const struct lx_poly *p, double *b)
{
	b[0] = b[1] = INFINITY, b[2] = b[3] = -INFINITY;
	for (int k = 0; k < p->n; k++) {
		vec2 c = chart_point(ch, p->v[k]);
		b[0] = c.x < b[0] ? c.x : b[0], b[1] = c.y < b[1] ? c.y : b[1], b[2] = c.x > b[2] ? c.x : b[2],
		b[3] = c.y > b[3] ? c.y : b[3];
	}
}

/* A footprint's part on the visible plane (window coordinates) among the chart's
 * footprints, which the pieces must hold (plane_pieces), less what the cover test
 * shadows (covered_part): its bounds, turned; the part itself kept in `parts`. */
static void add_foot(struct plane_chart *ch, struct lx_poly on, struct foot_parts *parts)
{
	if (ch->covered.n >= 3) { /* what lies in the cover's shadow needs no lixel */
		struct lx_poly rest;
		lx_poly_hull_of_difference(&on, &ch->covered, NULL, &rest);
		on = rest;
	}
	if (on.n < 3)
		return;
	chart_bounds(ch, &on, ch->foot[ch->feet++]);
	parts->on[parts->n++] = on;
}

/* A clipped footprint's part on the visible plane among the chart's footprints. */
static void reach_foot(struct plane_chart *ch, const struct reach *r, struct foot_parts *parts)
{
	struct lx_poly one = reach_poly(r), on;
	lx_poly_intersect(&ch->win, &one, &on);
	if (on.n < 3 || !(fabs(lx_poly_area(&on)) > 1e-9))
		return;
	add_foot(ch, on, parts);
}

/* Where the cover test (plane_cover.h) shadows plane i exactly: the image of the shadow
 * of the first lit front the renderer tests over it (a plane's where one is: the table
 * top), in window coordinates, COVER_INSET pixels in from its edges (a lixel there
 * decides nothing, the test shadows the pixel whatever it reads; the inset keeps the map
 * under the test's rounding, fp16 varyings included). Empty where no front covers the
 * plane or its shadow has no image. */
#define COVER_INSET 4.0
static void covered_part(const struct lx_frame *f, const struct lx_plane_covers *cv, int i, struct lx_poly *out)
{
	struct lx_poly img;
	out->n = 0;
	if (!lx_plane_cover_image(f, cv, cv->of[i][0], i, &img)) /* -1: no front over it */
		return;
	lx_poly_inset(&img, COVER_INSET, out); /* a hull: counter-clockwise */
	if (out->n < 3 || !(fabs(lx_poly_area(out)) > 1.0))
		out->n = 0; /* thinner than the inset: nothing to leave out */
}

/* The wanted rectangle shrunk to the footprints' bounds (with a cover, each less the
 * cover's shadow, add_foot); false when none is left. */
static bool feet_bound(struct plane_chart *ch)
{
	if (ch->feet == 0)
		return false;
	double r[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
	for (int c = 0; c < ch->feet; c++)
		for (int k = 0; k < 2; k++)
			r[k] = lx_fmin(r[k], ch->foot[c][k]), r[k + 2] = lx_fmax(r[k + 2], ch->foot[c][k + 2]);
	ch->x0 = lx_fmax(ch->x0, r[0]), ch->y0 = lx_fmax(ch->y0, r[1]);
	ch->x1 = lx_fmin(ch->x1, r[2]), ch->y1 = lx_fmin(ch->y1, r[3]);
	return true;
}

/* The chart's feet again, each less what casters hide from the eye (take_hidden), and
 * the wanted rectangle their bounds where a caster hides some (*hid_some). False when
 * they hide every footprint: no map. */
static bool hidden_feet(const struct lx_frame *f, struct plane_chart *ch, const struct foot_parts *parts,
			struct caster_images *images, bool *hid_some)
{
	struct hiding hd = {.images = images};
	int n = 0;
	for (int k = 0; k < parts->n; k++) {
		chart_bounds(ch, &parts->on[k], ch->foot[n]);
		n += take_hidden(f, ch, &hd, &parts->on[k], ch->foot[n]);
	}
	ch->feet = n;
	*hid_some = hd.some;
	return !hd.some || feet_bound(ch);
}

/* Footprints cut in slabs. A plane whose pieces still hold more pixels than it can get
 * lixels (slab_and_split) gets them thinner where a footprint fills little of its
 * bounding rectangle: a long shadow seen in perspective is a wedge, and a rectangle
 * around it holds a triangle's worth of pixels no shadow falls on. Each such footprint
 * is cut across the chart's x or y axis, whichever leaves less, in SLABS equal bands,
 * where the bands' own bounds hold a fifth less area (or more) than the footprint's; the
 * slabs are feet of their own, which the pieces' choices may take apart or merge again
 * (plane_splits). */
#define SLABS 3
static double slab_area(const struct plane_chart *ch, const struct lx_poly *on, vec2 e, double lo, double hi,
			struct lx_poly *slab)
{
	double area = 0;
	for (int j = 0; j < SLABS; j++) {
		double a = lo + (hi - lo) * j / SLABS, b = lo + (hi - lo) * (j + 1) / SLABS, r[4];
		lx_poly_clip_halfplane(on, e.x, e.y, -a, &slab[j]);
		lx_poly_clip_halfplane(&slab[j], -e.x, -e.y, b, &slab[j]);
		if (slab[j].n < 3)
			continue;
		chart_bounds(ch, &slab[j], r);
		area += (r[2] - r[0]) * (r[3] - r[1]);
	}
	return area;
}

static bool slab_feet(const struct plane_chart *ch, struct foot_parts *parts)
{
	vec2 axis[2] = {{ch->mx * ch->cs, -ch->mx * ch->sn}, {ch->sn, ch->cs}}; /* chart_point's */
	bool cut = false;
	for (int k = 0, n = parts->n; k < n; k++) {
		double r[4];
		chart_bounds(ch, &parts->on[k], r);
		double whole = (r[2] - r[0]) * (r[3] - r[1]), least = 0.8 * whole;
		struct lx_poly slab[2][SLABS];
		int best = -1;
		for (int a = 0; a < 2; a++) {
			double area = slab_area(ch, &parts->on[k], axis[a], r[a], r[a + 2], slab[a]);
			if (area < least)
				least = area, best = a;
		}
		if (best < 0 || parts->n + SLABS - 1 > LX_MAX_PLANES + LX_MAX_CASTERS)
			continue;
		bool first = true;
		for (int j = 0; j < SLABS; j++) {
			if (slab[best][j].n < 3)
				continue;
			parts->on[first ? k : parts->n++] = slab[best][j];
			first = false;
		}
		cut = true;
	}
	return cut;
}

static bool chart_plane(const struct lx_frame *f, const struct lx_light_space *ls, int i, int next,
			const struct lx_method_options *o, struct lx_shadow_result *out, struct plane_chart *ch,
			struct foot_parts *parts)
{
	bool twist = o->plane_twist || o->square_regions, similar = o->plane_similar;
	ch->needs_fallback = false;
	if (!chart_usable(f, ls, i, out, ch))
		return false;
	/* Wanted rays in this light image (window coordinates on the plane): the visible
	 * plane, within what the casters can cover. */
	struct lx_poly wanted = ch->win, cast;
	vec2 pts[LX_OUTLINE_POINTS * (LX_MAX_PLANES + LX_MAX_CASTERS)];
	bool whole[LX_MAX_PLANES + LX_MAX_CASTERS];
	int nc, ids[LX_MAX_PLANES + LX_MAX_CASTERS], first[LX_MAX_PLANES + LX_MAX_CASTERS + 1];
	struct reach reach[LX_MAX_PLANES + LX_MAX_CASTERS];
	caster_outlines(f, i, ch, pts, whole, ids, first, &nc);
	outline_hulls(pts, whole, first, nc);
	bool bounded = casters_bound(f, i, pts, whole, ids, first, nc, reach, &cast);
	ch->bounded = bounded;
	if (bounded)
		lx_poly_intersect(&ch->win, &cast, &wanted);
	if (wanted.n < 3 || !(fabs(lx_poly_area(&wanted)) > 1e-9))
		return false; /* no caster over the visible plane: nothing to shadow there */
	ch->wanted = wanted;
	chart_orientation(f, i, next, twist, ch);
	struct lx_poly rot = wanted;
	to_chart(ch, &rot);
	lx_poly_bounds(&rot, &ch->x0, &ch->y0, &ch->x1, &ch->y1);
	/* each caster's own footprint: where its shadow can fall, for pieces (plane_pieces,
	 * when every caster has one); its outline, or its clipped footprint where its shadow
	 * passes the eye, inside the visible plane, for the lixels' aspect (chart_stretch) */
	ch->feet = 0, ch->plane = i, parts->n = 0;
	double along_x = 0, along_y = 0;
	struct lx_poly win = ch->win;
	to_chart(ch, &win);
	for (int c = 0; c < nc; c++) {
		struct lx_poly one, on;
		if (!whole[c]) { /* a clipped footprint's edges run along its shadow's too */
			if (reach[c].kind != FOOT_POLYGON)
				continue;
			if (bounded)
				reach_foot(ch, &reach[c], parts);
			one = reach_poly(&reach[c]);
		} else {
			one.n = first[c + 1] - first[c]; /* its outline's hull (outline_hulls) */
			memcpy(one.v, pts + first[c], (size_t)one.n * sizeof(vec2));
			lx_poly_intersect(&ch->win, &one, &on);
			if (on.n < 3 || !(fabs(lx_poly_area(&on)) > 1e-9))
				continue;
			if (bounded)
				add_foot(ch, on, parts);
		}
		if (similar)
			continue; /* square lixels: no outlines wanted */
		double dx, dy;
		to_chart(ch, &one);
		lx_poly_edges_inside(&one, &win, &dx, &dy);
		along_x += dx, along_y += dy;
	}
	ch->along_x = along_x, ch->along_y = along_y;
	/* no caster's own footprint on the visible plane, or (with a cover) every shadow falls
	 * in the cover's and the test serves it: the hull of the outlines only spans between */
	if (bounded && !(ch->covered.n >= 3 ? feet_bound(ch) : ch->feet > 0))
		return false;
	return ch->x1 - ch->x0 > 1e-9 && ch->y1 - ch->y0 > 1e-9;
}

/* The rectangles a plane's map is cut into: one around all the casters' footprints, or,
 * where that holds more pixels than the plane's budget has lixels, up to PIECES_MAX
 * around clusters of them that cover much less (one similarity for all, each rectangle
 * its own region of the atlas: the plane's own and spare pieces, plane_build).
 * Clusters: the footprints sorted along x or along y and split in two where the two
 * bounding rectangles' areas add up least; and the footprints merged pair by pair, the
 * pair whose bounding rectangle adds least first, down to one. Pieces may overlap: the
 * density they buy is worth drawing their overlap with each map, of which a pixel reads
 * the first that serves it (each holds every caster over its rectangle, so any decides
 * it right). */
struct plane_pieces {
	int n;
	double r[PIECES_MAX][4]; /* x0, y0, x1, y1 */
};

/* A plane's choices: by[k] the best k rectangles found (n 0: none), each choice covering
 * a fifth less area than the best with fewer pieces (a piece costs a region's pass). */
struct plane_splits {
	struct plane_pieces by[PIECES_MAX + 1];
};

static double rect_area(const double *r) { return (r[2] - r[0] + 1) * (r[3] - r[1] + 1); }

static double pieces_area(const struct plane_pieces *pc)
{
	double a = 0;
	for (int k = 0; k < pc->n; k++)
		a += rect_area(pc->r[k]);
	return a;
}

static void rect_union(const double *a, const double *b, double *out)
{
	out[0] = lx_fmin(a[0], b[0]), out[1] = lx_fmin(a[1], b[1]), out[2] = lx_fmax(a[2], b[2]), out[3] = lx_fmax(a[3], b[3]);
}

static void offer_pieces(struct plane_splits *sp, const double (*r)[4], int n)
{
	if (n < 2 || n > PIECES_MAX)
		return;
	struct plane_pieces pc = {.n = n};
	memcpy(pc.r, r, (size_t)n * sizeof r[0]);
	if (sp->by[n].n == 0 || pieces_area(&pc) < pieces_area(&sp->by[n]))
		sp->by[n] = pc;
}

/* Two clusters along x or y: the footprints sorted by their centres, cut where the two
 * rectangles' areas add up least. */
static void split_along_axes(const struct plane_chart *ch, struct plane_splits *sp)
{
	int order[LX_MAX_PLANES + LX_MAX_CASTERS];
	for (int axis = 0; axis < 2; axis++) {
		for (int i = 0; i < ch->feet; i++)
			order[i] = i;
		for (int i = 1; i < ch->feet; i++) /* by the footprints' centres along the axis */
			for (int j = i; j > 0 && ch->foot[order[j]][axis] + ch->foot[order[j]][axis + 2] <
							 ch->foot[order[j - 1]][axis] + ch->foot[order[j - 1]][axis + 2]; j--) {
				int t = order[j];
				order[j] = order[j - 1];
				order[j - 1] = t;
			}
		for (int cut = 1; cut < ch->feet; cut++) {
			double g[2][4] = {{INFINITY, INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, -INFINITY, -INFINITY}};
			for (int i = 0; i < ch->feet; i++)
				rect_union(g[i >= cut], ch->foot[order[i]], g[i >= cut]);
			offer_pieces(sp, g, 2);
		}
	}
}

/* Of the n >= 2 rectangles g, the two whose bounding rectangle adds the least area to
 * theirs made one (the last moved into the freed place): n - 1 left. */
static void merge_closest(double (*g)[4], int *n)
{
	int bi = 0, bj = 1;
	double least = INFINITY;
	for (int i = 0; i < *n; i++)
		for (int j = i + 1; j < *n; j++) {
			double u[4];
			rect_union(g[i], g[j], u);
			double added = rect_area(u) - rect_area(g[i]) - rect_area(g[j]);
			if (added < least)
				least = added, bi = i, bj = j;
		}
	rect_union(g[bi], g[bj], g[bi]);
	memcpy(g[bj], g[*n - 1], sizeof g[bj]);
	(*n)--;
}

/* The footprints merged pair by pair, least added area first; each stage of PIECES_MAX
 * rectangles or fewer is a choice. */
static void merge_feet(const struct plane_chart *ch, struct plane_splits *sp)
{
	double g[LX_MAX_PLANES + LX_MAX_CASTERS][4];
	int n = ch->feet;
	memcpy(g, ch->foot, (size_t)n * sizeof g[0]);
	while (n > 1) {
		offer_pieces(sp, (const double(*)[4])g, n);
		merge_closest(g, &n);
	}
}

/* A plane's choices of rectangles (plane_splits); none but the one rectangle without
 * spare pieces to take. */
static void plane_splits(const struct plane_chart *ch, bool spare, long own_budget, struct plane_splits *sp)
{
	memset(sp, 0, sizeof *sp);
	sp->by[1].n = 1;
	sp->by[1].r[0][0] = ch->x0, sp->by[1].r[0][1] = ch->y0, sp->by[1].r[0][2] = ch->x1, sp->by[1].r[0][3] = ch->y1;
	/* within the budget at a lixel per pixel, no split gains (piece_gain) */
	if (!spare || ch->feet < 2 || !(rect_area(sp->by[1].r[0]) > (double)own_budget))
		return;
	split_along_axes(ch, sp);
	merge_feet(ch, sp);
	double kept = pieces_area(&sp->by[1]);
	for (int k = 2; k <= PIECES_MAX; k++) {
		if (sp->by[k].n == 0 || !(pieces_area(&sp->by[k]) < 0.8 * kept))
			sp->by[k].n = 0; /* a fifth less area than the best with fewer, or not at all */
		else
			kept = pieces_area(&sp->by[k]);
	}
}

/* The least area of a plane's choices of rectangles (plane_splits), in pixels (without
 * spare pieces to take, plane_splits offers only the one rectangle). */
static double least_area(const struct plane_splits *sp)
{
	double least = pieces_area(&sp->by[1]);
	for (int k = 2; k <= PIECES_MAX; k++)
		if (sp->by[k].n > 0)
			least = lx_fmin(least, pieces_area(&sp->by[k]));
	return least;
}

/* A plane served by one rectangle over its budget: the rectangle shrinks to its feet's
 * bounds where they hold every shadow (ch->bounded). The wanted rays are the visible
 * plane within the hull of all the casters' outlines, which also holds the space between
 * footprints: one caster's shadow off the plane drew the rectangle across it (on a view of
 * the table, the top's map at 0.40 lixels per pixel around the ball's shadow alone). The
 * pieces' choices keep the hull's rectangle as the one to beat; within the budget a
 * smaller one would only raise the map past a lixel per pixel, for its fill. */
static void one_piece_to_feet(struct plane_chart *ch, struct plane_pieces *pc, long budget)
{
	if (pc->n != 1 || !ch->bounded || !(rect_area(pc->r[0]) > (double)budget) || !feet_bound(ch))
		return;
	pc->r[0][0] = ch->x0, pc->r[0][1] = ch->y0, pc->r[0][2] = ch->x1, pc->r[0][3] = ch->y1;
}

/* What more pieces gain: the lixels per pixel the budget gives, up to one (past one,
 * lixels no longer decide more pixels), as a share of what it gave before, and
 * PIECE_GAIN_AT_ONE more for reaching one, where the scale snaps to whole pixels and
 * lixel centres fall on pixel centres (on the default view at 1024x1024 the floor at
 * 0.98 lixels per pixel in one rectangle: 0.0160% mismatch; at 1 in two: 0.0051%). A
 * share, not a difference: under the light facing the camera at 1920x1080 two rectangles
 * take the floor from 0.13 to 0.17 lixels per pixel, and its mismatch from 0.1520% to
 * 0.1096%. A piece costs a region's pass and more spans in the main pass, so it is
 * taken for PIECE_GAIN_MIN or more, never to save area alone. */
#define PIECE_GAIN_AT_ONE 0.1
#define PIECE_GAIN_MIN 0.05
static double piece_gain(const struct plane_pieces *from, const struct plane_pieces *to, long budget)
{
	/* areas >= 1: each rectangle counts its last row and column (rect_area) */
	double one = pieces_area(from), two = pieces_area(to);
	double before = lx_fmin(1, (double)budget / one), after = lx_fmin(1, (double)budget / two);
	return after / before - 1 + (two <= budget && one > budget ? PIECE_GAIN_AT_ONE : 0);
}

/* The spare pieces handed out one choice at a time to the plane whose next choice gains
 * most per piece it takes (PIECE_GAIN_MIN or more); take[i] the count plane i ends with. */
static void share_pieces(const struct plane_splits *sp, const bool *ok, int np, int spare, long budget, int *take)
{
	for (int i = 0; i < np; i++)
		take[i] = 1;
	while (spare > 0) {
		int best = -1, best_k = 0;
		double most = -1;
		for (int i = 0; i < np; i++)
			for (int k = take[i] + 1; ok[i] && k <= PIECES_MAX && k - take[i] <= spare; k++) {
				if (sp[i].by[k].n == 0)
					continue;
				double g = piece_gain(&sp[i].by[take[i]], &sp[i].by[k], budget) / (k - take[i]);
				if (g >= PIECE_GAIN_MIN && g > most)
					most = g, best = i, best_k = k;
			}
		if (best < 0)
			return;
		spare -= best_k - take[best];
		take[best] = best_k;
	}
}

/* A_l's scales and translation for one piece: u = (sx, sy) * (R p - (x0, y0)) + (ox, oy),
 * in a map of w x h lixels whose used part is [ox, uw] x [oy, vh]; sx = sy but for a
 * stretched map (chart_stretch). */
struct plane_fit {
	double sx, sy, x0, y0, ox, oy, uw, vh;
	int w, h;
};

/* fit_plane below a whole-number scale: scale s, stretched by a, shrunk until the pieces
 * hold no more than the budget and fit within the texture's side. */
static void fit_scaled(const struct plane_chart *ch, const struct plane_pieces *pc, long budget, int side, double s,
		       double a, struct plane_fit *fit)
{
	/* Snapping. Where the stretch gives the finer axis a lixel per pixel or more, that
	 * axis takes exactly one (the other the rest of the lixels) and whole pixels of
	 * translation, so that along it lixel centres fall on pixel centres, as at lpp 1: a
	 * shadow edge along the pixel rows (columns) is then decided exactly, instead of a
	 * whole row of pixels reading a lixel whose centre lies across it. Over 200 random
	 * views at 640x480 (tools/random-views.py) the mean mismatch fell from 0.0359% to
	 * 0.0286% (default scene) and 0.0901% to 0.0756% (table) with fixed budgets, 0.0130%
	 * to 0.0109% and 0.0617% to 0.0560% with shared ones. Short of that, an axis is
	 * snapped to one lixel per pixel where the edges' model says it errs less so: 0.0276%,
	 * 0.0716%, 0.0103% and 0.0549% on those views; the table's back edge seen straight
	 * on under the light near the wall, shared budgets at 1024x1024, 0.152% to 0.127%; the
	 * default scene's median at 1024x1024, fixed budgets, 0.0244% to 0.0193%. One lixel
	 * per pixel rather than two or more, as the model says: the default scene's horizon
	 * at 1920x1080, 0.0283% with two, 0.0188% with one. */
	bool rows = false, cols = false; /* snapped: the map's y (x) at one lixel per pixel */
	if (ch->on_grid && a != 1 && (s * a >= 1 || s / a >= 1))
		rows = s * a >= 1, cols = !rows;
	else if (ch->on_grid && s < 1 && s >= SNAP_MIN_SCALE) {
		/* Snapped, the rows' (columns') edges err no more: what is left is Y / s_x
		 * (X / s_y), against X / s_y + Y / s_x stretched alone (chart_stretch); with the
		 * snapped axis at 1, the other at s^2 */
		double X = ch->along_x, Y = ch->along_y, alone = X / (s * a) + Y * a / s;
		rows = Y <= X && Y / (s * s) < alone;
		cols = X < Y && X / (s * s) < alone;
	}
	for (int tries = 0; tries < 64; tries++) { /* ceil() may overshoot the budget by a row */
		long total = 0;
		int worst = 0;
		double sx = cols ? 1 : rows ? s * s : s / a, sy = rows ? 1 : cols ? s * s : s * a;
		for (int p = 0; p < pc->n; p++) {
			double x0 = cols ? floor(pc->r[p][0]) : pc->r[p][0], y0 = rows ? floor(pc->r[p][1]) : pc->r[p][1];
			double uw = sx * (pc->r[p][2] - x0), vh = sy * (pc->r[p][3] - y0);
			int w = (int)ceil(uw), h = (int)ceil(vh);
			w = w < 1 ? 1 : w, h = h < 1 ? 1 : h;
			fit[p] = (struct plane_fit){sx, sy, x0, y0, 0, 0, lx_fmin(w, uw), lx_fmin(h, vh), w, h};
			total += (long)w * h;
			worst = w > worst ? w : h > worst ? h : worst;
		}
		if ((total <= budget && worst <= side) || tries == 63)
			return;
		if (worst > side && (rows || cols)) { /* a snapped axis cannot shrink: unsnapped */
			rows = cols = false;
			continue;
		}
		s *= 0.999 * lx_fmin(sqrt((double)budget / (double)total), (double)side / worst);
	}
}

/* Sizes the pieces' maps, one scale for all. A fixed (square) region: the paper's
 * uniform scale down when the budget cannot give a lixel per pixel. A fitted region: the
 * scale is set by area, so the budget's lixels all cover wanted pixels, in shapes that
 * follow the rectangles; where the budget gives a pixel one lixel or more on an unturned
 * pixel grid the scale is a whole number and lixel centres fall on pixel centres. */
static void fit_plane(const struct plane_chart *ch, const struct plane_pieces *pc, const struct lx_region *g,
		      const struct lx_atlas *atlas, long budget, double max_lpp, struct plane_fit *fit)
{
	if (!g->variable) { /* one piece (plane_build) */
		double rw = ch->x1 - ch->x0, rh = ch->y1 - ch->y0; /* > 1e-9 (chart_plane) */
		double k = lx_fmin(1.0, lx_fmin(g->w / rw, g->h / rh));
		*fit = (struct plane_fit){.sx = k, .sy = k, .x0 = ch->x0, .y0 = ch->y0, .w = g->w, .h = g->h};
		if (k == 1.0 && ch->on_grid && ceil(ch->x1) - floor(ch->x0) <= g->w &&
		    ceil(ch->y1) - floor(ch->y0) <= g->h) {
			/* pixel centres, turned by quarter turns, stay at half-integers: a
			 * whole-lixel translation puts each on a lixel centre */
			fit->x0 = floor(ch->x0);
			fit->y0 = floor(ch->y0);
		}
		fit->uw = lx_fmin(g->w, k * (ch->x1 - fit->x0));
		fit->vh = lx_fmin(g->h, k * (ch->y1 - fit->y0));
		return;
	}
	int side = atlas->max_side > 1 ? atlas->max_side : 1;
	double area = 0, wide = 0, tall = 0;
	for (int k = 0; k < pc->n; k++) {
		area += (pc->r[k][2] - pc->r[k][0]) * (pc->r[k][3] - pc->r[k][1]); /* > 0: inside the chart's bounds */
		wide = lx_fmax(wide, pc->r[k][2] - pc->r[k][0]), tall = lx_fmax(tall, pc->r[k][3] - pc->r[k][1]);
	}
	double s = sqrt((double)budget / lx_fmax(area, 1e-300));
	if (max_lpp > 0)
		s = lx_fmin(s, sqrt(max_lpp));
	/* stretched only short of a lixel per pixel (chart_stretch): from there on a
	 * similarity keeps lixel centres on pixel centres */
	double a = s < 1 ? chart_stretch(ch->along_x, ch->along_y) : 1; /* in [1/3, 3] */
	/* the long sides within the texture (both > 0: inside the chart's bounds) */
	s = lx_fmin(s, lx_fmin((side - 1) * a / lx_fmax(wide, 1e-9), (side - 1) / (a * lx_fmax(tall, 1e-9))));
	if (ch->on_grid && s >= 1 && a == 1) {
		/* whole lixels per pixel, the translation in whole pixels: pixel centres land on
		 * lixel centres (an even scale puts them on corners, half a lixel off) */
		for (double k = floor(s); k >= 1; k--) {
			long total = 0;
			bool fits = true;
			for (int p = 0; p < pc->n; p++) {
				double x0 = floor(pc->r[p][0]), y0 = floor(pc->r[p][1]), off = fmod(k, 2) == 0 ? 0.5 : 0;
				double uw = k * (pc->r[p][2] - x0) + off, vh = k * (pc->r[p][3] - y0) + off;
				int w = (int)ceil(uw), h = (int)ceil(vh);
				fit[p] = (struct plane_fit){k, k, x0, y0, off, off, uw, vh, w, h};
				total += (long)w * h;
				fits &= w <= side && h <= side;
			}
			if (fits && total <= budget)
				return;
		}
		/* No whole number fits: the pieces' rows and columns rounded out take lixels
		 * their area does not count, and the map falls short of a lixel per pixel after
		 * all. So it is fitted as such, stretched and snapped; an unsnapped similarity
		 * just under one puts lixel centres up to half a lixel off pixel centres along
		 * every edge (random view 19 of the table, tools/random-views.py --seed 13, the
		 * floor at 0.995 lixels per pixel: 0.2223% against 0.0027% at one). */
		s = lx_fmin(s, 1);
		a = chart_stretch(ch->along_x, ch->along_y);
		s = lx_fmin(s, lx_fmin((side - 1) * a / lx_fmax(wide, 1e-9), (side - 1) / (a * lx_fmax(tall, 1e-9))));
	}
	fit_scaled(ch, pc, budget, side, s, a, fit);
}

/* The farthest depth (z / w of m) of the plane's wanted part: z / w is a ratio of linear
 * functions on the plane, so over a convex polygon in front of the light its largest
 * value is at a vertex. The vertices, in window coordinates, go back to the plane along
 * their eye rays. False when one does not meet the plane in front of the light. */
static bool plane_zfar(const struct lx_frame *f, const struct lx_plane *P, const struct lx_poly *wanted, const mat4 *m,
		       double *zfar)
{
	vec4 e = lx_plane_equation(P);
	*zfar = -INFINITY;
	for (int k = 0; k < wanted->n; k++) {
		vec3 q;
		double t;
		if (!lx_window_on_plane(&f->view, e, wanted->v[k].x, wanted->v[k].y, &q, &t))
			return false;
		double w = v4_dot_point(m4_row(m, 3), q);
		if (!(w > 0))
			return false;
		*zfar = lx_fmax(*zfar, v4_dot_point(m4_row(m, 2), q) / w);
	}
	return isfinite(*zfar);
}

/* Depth: unit cube clipping inside the map's frustum. Receivers: the plane's wanted
 * part (only the plane's pixels, and casters whose depth lies within, read the map), or
 * where that cannot be charted the view frustum within the scene box and the map's
 * cone; casters: their boxes within the cone. Writes the fitted z row into *m; false
 * when no caster lies in front of a receiver. */
static bool fit_depth(const struct lx_frame *f, const struct lx_light_space *ls, const struct plane_chart *ch,
		      const double *b, mat4 *m, struct lx_shadow_result *out, const struct lx_plane *P)
{
	const char *name = P->name;
	vec4 wrow = m4_row(m, 3), zrow = m4_row(m, 2);
	double wplane = INFINITY;
	for (int k = 0; k < ch->nw; k++)
		wplane = lx_fmin(wplane, v4_dot_point(wrow, ch->world[k]));
	vec4 hs[20];
	int nh = 0;
	hs[nh++] = v4_lin(1, m4_row(m, 0), -b[0], wrow);
	hs[nh++] = v4_lin(-1, m4_row(m, 0), b[2], wrow);
	hs[nh++] = v4_lin(1, m4_row(m, 1), -b[1], wrow);
	hs[nh++] = v4_lin(-1, m4_row(m, 1), b[3], wrow);
	double wmin = 1e-4 * wplane; /* a hair in front of the light: depth is finite there */
	hs[nh++] = v4_lin(1, wrow, -wmin, (vec4){0, 0, 0, 1});
	int ncone = nh;
	double zfar = -INFINITY, znear = INFINITY;
	if (!plane_zfar(f, P, &ch->wanted, m, &zfar)) { /* rare: the receiver volume in the cone */
		nh += receiver_faces(f, ls, hs + nh);
		vec3 vert[2048];
		int nv = lx_halfspace_vertices(hs, nh, NULL, 0, vert, 2048);
		for (int k = 0; k < nv; k++)
			zfar = lx_fmax(zfar, v4_dot_point(zrow, vert[k]) / v4_dot_point(wrow, vert[k])); /* w >= wmin > 0 there */
	}
	bool clipped = false;
	for (int id = 0; id < f->object_count; id++) {
		if (!lx_object_can_cast(f, id))
			continue;
		/* the box's corners against the cone: all outside one side gives none; all in
		 * front of the near plane (the usual case) gives the corners, a superset of the
		 * box within the cone (a nearer znear is still correct); only a box reaching the
		 * near plane needs the half-space enumeration */
		vec3 cv[512];
		int nc = 0, all_in = 1, out_one = 0;
		vec3 corner[8];
		for (int k = 0; k < 8; k++)
			corner[k] = v3_box_corner(f->bmin[id], f->bmax[id], k);
		for (int q = 0; q < ncone; q++) {
			int outside = 0;
			for (int k = 0; k < 8; k++)
				outside += v4_dot_point(hs[q], corner[k]) < 0;
			all_in &= q < ncone - 1 || outside == 0; /* the last cone plane is the near plane */
			out_one |= outside == 8;
		}
		if (out_one)
			continue;
		if (all_in) {
			memcpy(cv, corner, sizeof corner);
			nc = 8;
		} else {
			vec4 cb[11];
			memcpy(cb, hs, (size_t)ncone * sizeof(vec4));
			lx_box_halfspaces(f->bmin[id], f->bmax[id], cb + ncone);
			nc = lx_halfspace_vertices(cb, ncone + 6, NULL, 0, cv, 512);
		}
		for (int k = 0; k < nc; k++) {
			double w = v4_dot_point(wrow, cv[k]);
			znear = lx_fmin(znear, v4_dot_point(zrow, cv[k]) / w);
			clipped |= w <= wmin * (1 + 1e-9);
		}
	}
	if (clipped)
		lx_shadow_warn(out, "plane %s: a caster next to the light is clipped by the map's near plane", name);
	if (!(znear < zfar) || !isfinite(znear) || !isfinite(zfar))
		return false; /* no caster in front of any receiver in this map */
	double pad = (zfar - znear) * 1e-4;
	znear -= pad, zfar += pad;
	vec4 z2 = v4_lin(2 / (zfar - znear), zrow, -(zfar + znear) / (zfar - znear), wrow);
	m->m[2] = z2.x, m->m[6] = z2.y, m->m[10] = z2.z, m->m[14] = z2.w;
	return m4_finite(m);
}

/* A_l for one piece: window (x q, y q, z q, q) -> region clip, x_clip = 2 u / w - 1. */
static mat4 piece_matrix(const struct plane_chart *ch, const struct plane_fit *ft)
{
	mat4 a = m4_identity();
	double kx = 2.0 / ft->w, ky = 2.0 / ft->h, sx = ft->sx, sy = ft->sy;
	a.m[0] = kx * sx * ch->cs * ch->mx, a.m[4] = -kx * sx * ch->sn * ch->mx, a.m[12] = kx * (ft->ox - sx * ft->x0) - 1;
	a.m[1] = ky * sy * ch->sn, a.m[5] = ky * sy * ch->cs, a.m[13] = ky * (ft->oy - sy * ft->y0) - 1;
	return a;
}

/* The plane map's depth row, shared by its pieces: A_l leaves z alone and the cone of
 * rays is the same at any scale, so it is fitted once, with a lixel per pixel over the
 * rectangle around all pieces, before the budgets are known. False when no caster lies
 * in front of a receiver there (no map). */
static bool plane_depth(const struct lx_frame *f, const struct lx_light_space *ls, const struct plane_chart *ch,
			const struct plane_pieces *pc, struct lx_shadow_result *out, const struct lx_plane *P, mat4 *depth)
{
	double r[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
	for (int k = 0; k < pc->n; k++)
		r[0] = lx_fmin(r[0], pc->r[k][0]), r[1] = lx_fmin(r[1], pc->r[k][1]), r[2] = lx_fmax(r[2], pc->r[k][2]),
		r[3] = lx_fmax(r[3], pc->r[k][3]);
	struct plane_fit ft = {1, 1, r[0], r[1], 0, 0, r[2] - r[0], r[3] - r[1], (int)ceil(r[2] - r[0]), (int)ceil(r[3] - r[1])};
	ft.w = ft.w < 1 ? 1 : ft.w, ft.h = ft.h < 1 ? 1 : ft.h;
	mat4 a = piece_matrix(ch, &ft);
	*depth = m4_mul(&a, &ch->cam.m);
	double b[4] = {-1, -1, 2.0 * ft.uw / ft.w - 1, 2.0 * ft.vh / ft.h - 1};
	return fit_depth(f, ls, ch, b, depth, out, P);
}

/* Builds plane i's map (and its spare pieces', more[0..]) from its chart, pieces, depth
 * row and lixel budget, with each piece's reach on the screen. */
static void build_plane_map(const struct lx_atlas *atlas, const struct plane_chart *ch, const struct plane_pieces *pc,
			    const mat4 *depth, int i, long budget, double max_lpp, struct lx_shadow_map *map,
			    struct lx_shadow_map *const *more)
{
	struct plane_fit fit[PIECES_MAX];
	fit_plane(ch, pc, &atlas->regions[map->region], atlas, budget, max_lpp, fit);
	for (int k = 0; k < pc->n; k++) {
		struct lx_shadow_map *mp = k == 0 ? map : more[k - 1];
		const struct plane_fit *ft = &fit[k];
		mat4 ak = piece_matrix(ch, ft), mk = m4_mul(&ak, &ch->cam.m);
		for (int c = 0; c < 4; c++) /* the shared depth row */
			mk.m[c * 4 + 2] = depth->m[c * 4 + 2];
		if (!m4_finite(&mk))
			continue;
		double b[4] = {2.0 * ft->ox / ft->w - 1, 2.0 * ft->oy / ft->h - 1, 2.0 * ft->uw / ft->w - 1,
			       2.0 * ft->vh / ft->h - 1};
		mp->light_clip = mk;
		memcpy(mp->bounds, b, sizeof b);
		mp->lixel_scale = ft->sx == ft->sy ? ft->sx : sqrt(ft->sx * ft->sy);
		mp->lixel_stretch = ft->sx == ft->sy ? 1 : sqrt(ft->sy / ft->sx);
		mp->w = ft->w, mp->h = ft->h;
		mp->plane = i;
		mp->rendered = true;
		/* the piece's rectangle back in window coordinates (undo mirror and twist): its
		 * bounding box is where the plane's shadows in this piece can fall */
		mp->has_screen = true;
		mp->screen_served = ch->on_grid; /* a twisted piece's bounding box holds more than it */
		mp->screen[0] = mp->screen[1] = INFINITY, mp->screen[2] = mp->screen[3] = -INFINITY;
		for (int c = 0; c < 4; c++) {
			double u = (c & 1 ? pc->r[k][2] : pc->r[k][0]) * ch->mx, v = c & 2 ? pc->r[k][3] : pc->r[k][1];
			double x = ch->cs * u + ch->sn * v, y = -ch->sn * u + ch->cs * v;
			mp->screen[0] = lx_fmin(mp->screen[0], x), mp->screen[1] = lx_fmin(mp->screen[1], y);
			mp->screen[2] = lx_fmax(mp->screen[2], x), mp->screen[3] = lx_fmax(mp->screen[3], y);
		}
	}
}

/* A piece's lixels at a lixel per pixel, as fit_plane counts them (whole pixels from a
 * floored corner, rounded up), a row and a column more for the margin: short of that the
 * fit takes a scale just off 1, whose lixel centres sit off the pixel centres. */
static double scale_one_width(const double *r) { return ceil(r[2] - floor(r[0])) + 1; }
static double scale_one_height(const double *r) { return ceil(r[3] - floor(r[1])) + 1; }

static double scale_one_lixels(const struct plane_pieces *pc)
{
	double a = 0;
	for (int k = 0; k < pc->n; k++)
		a += scale_one_width(pc->r[k]) * scale_one_height(pc->r[k]);
	return a;
}

/* Each plane map's lixels this frame: its own budget, and what the others leave: the
 * budgets of the maps that serve nothing this frame (their plane out of view, facing
 * away from the light, or with no shadow in view), and with shared budgets also the
 * rest of each map whose whole-number scale (or the cap, or the texture's side) stops
 * it short of its budget. */
static void plane_budgets(const struct lx_atlas *atlas, const struct lx_method_options *o,
			  const struct plane_chart *ch, const struct plane_pieces *pc, const bool *ok, int np,
			  long *budget)
{
	long own = (long)o->plane_lixels * o->plane_lixels, need[PLANE_MAPS];
	for (int i = 0; i < np; i++)
		budget[i] = atlas->regions[i].variable ? own : (long)atlas->regions[i].w * atlas->regions[i].h;
	if (o->square_regions)
		return;
	double density = o->plane_max_lpp > 0 ? o->plane_max_lpp : 1;
	for (int i = 0; i < np; i++)
		need[i] = ok[i] ? (long)ceil(density * scale_one_lixels(&pc[i])) : 0;
	/* The budget of a map with nothing to serve this frame, and with shared budgets the
	 * lixels a map's fit leaves unused, go to the maps that need more than their own
	 * (for lpp 1, or the cap), in proportion to their shortfall. A map that needs less
	 * keeps the scale its own budget gives: beyond lpp 1 its lixels still serve the
	 * casters that read it (measured: handing those over cost accuracy on every view);
	 * only its rest moves. With fixed budgets a map that serves keeps its own: a plane
	 * without a map would leave its lixels idle (random views where the floor alone has
	 * shadows, short of a lixel per pixel, and the wall none: plane_keeps_every_shadow). */
	long spare = 0, short_by = 0;
	for (int i = 0; i < np; i++) {
		if (!ok[i]) {
			spare += budget[i], budget[i] = 0;
		} else if (need[i] > budget[i]) {
			short_by += need[i] - budget[i];
		} else if (o->shared_budget) {
			struct plane_fit fit[PIECES_MAX];
			long used = 0;
			fit_plane(&ch[i], &pc[i], &atlas->regions[i], atlas, budget[i], o->plane_max_lpp, fit);
			for (int k = 0; k < pc[i].n; k++)
				used += (long)fit[k].w * fit[k].h;
			if (used < budget[i])
				spare += budget[i] - used, budget[i] = used;
		}
	}
	if (short_by <= 0 || spare <= 0)
		return;
	for (int i = 0; i < np; i++)
		if (ok[i] && need[i] > budget[i])
			budget[i] += (long)lx_fmin((double)spare * (need[i] - budget[i]) / short_by, need[i] - budget[i]);
}

/* Piece k cut in two across its long side into a new last piece. */
static void cut_piece(struct plane_pieces *pc, int k)
{
	double *r = pc->r[k], *cut = pc->r[pc->n++];
	memcpy(cut, r, 4 * sizeof *r);
	bool wide = r[2] - r[0] >= r[3] - r[1];
	double mid = floor(0.5 * (r[wide ? 0 : 1] + r[wide ? 2 : 3]));
	r[wide ? 2 : 3] = mid, cut[wide ? 0 : 1] = mid;
}

/* Whether each of plane i's pieces, as fit_plane makes them for `budget`, holds at most
 * `room` lixels; *big: the piece that holds the most (fit: the fit). */
static bool pieces_in_room(const struct lx_atlas *atlas, const struct plane_chart *ch, const struct plane_pieces *pc,
			   int i, long budget, double max_lpp, long room, int *big, struct plane_fit *fit)
{
	fit_plane(ch, pc, &atlas->regions[i], atlas, budget, max_lpp, fit);
	*big = 0;
	for (int k = 1; k < pc->n; k++)
		if ((long)fit[k].w * fit[k].h > (long)fit[*big].w * fit[*big].h)
			*big = k;
	return (long)fit[*big].w * fit[*big].h <= room;
}

/* The most lixels up to `asked` at which each of plane i's pieces as fit_plane makes them
 * holds at most `room`, found to 256 lixels by halving (one lixel always fits); *lpp: the
 * density the fit then gives. Not a bound on a piece's lixels under any stretch, as
 * before 7fb3acd: held back by one, maps took 1-3% fewer lixels than their fit allows
 * (24 random views at 1920x1080 of tools/random-views.py; its view 147 of --seed 2026,
 * the floor at 0.977 lixels per pixel by the bound, at 1 by the fit). */
static long room_budget(const struct lx_atlas *atlas, const struct plane_chart *ch, const struct plane_pieces *pc,
			int i, double max_lpp, long room, long asked, double *lpp)
{
	struct plane_fit fit[PIECES_MAX];
	int big;
	long lo = 1, hi = asked + 1; /* lo fits; hi is past what may be taken */
	while (hi - lo > 256) {
		long mid = lo + (hi - lo) / 2;
		*(pieces_in_room(atlas, ch, pc, i, mid, max_lpp, room, &big, fit) ? &lo : &hi) = mid;
	}
	pieces_in_room(atlas, ch, pc, i, lo, max_lpp, room, &big, fit);
	*lpp = fit[0].sx * fit[0].sy;
	return lo;
}

/* A map that took another's budget (plane_budgets) may hold more lixels than its
 * region: with fixed budgets each region holds its own plane's budget alone. Where a
 * piece as fit_plane makes it would overflow its region, the largest is cut in two across
 * its long side into one of the `free` spare pieces; with none left (or PIECES_MAX), the
 * map's budget shrinks until its largest piece fits, and where two pieces made one free a
 * piece to cut the largest in, at a higher density than the shrunk budget gives, they
 * are. (Until d715bd3 a bound on a piece's lixels under any stretch decided the cuts: on
 * random view 14 of --seed 909 at 1920x1080 the floor took four pieces where two hold it.)
 * The pieces' lixels together never pass the plane budgets' total, so the frame still
 * packs (lx_atlas_layout's bound). */
static void cut_to_regions(const struct lx_atlas *atlas, const struct plane_chart *ch, const double *max_lpp, int np,
			   const bool *ok, int free, struct plane_pieces *pc, long *budget)
{
	for (int i = 0; i < np; i++) {
		long room = atlas->regions[i].budget, asked = budget[i]; /* the spare pieces' rooms are the same */
		struct plane_fit fit[PIECES_MAX];
		int big;
		if (!ok[i] || asked <= room) /* a fit's pieces hold at most its budget */
			continue;
		bool in_room;
		while (!(in_room = pieces_in_room(atlas, &ch[i], &pc[i], i, asked, max_lpp[i], room, &big, fit)) &&
		       free > 0 && pc[i].n < PIECES_MAX)
			cut_piece(&pc[i], big), free--;
		if (in_room)
			continue;
		double lpp, lpp_merged;
		budget[i] = room_budget(atlas, &ch[i], &pc[i], i, max_lpp[i], room, asked, &lpp);
		if (pc[i].n < 2)
			continue;
		struct plane_pieces merged = pc[i];
		merge_closest(merged.r, &merged.n);
		pieces_in_room(atlas, &ch[i], &merged, i, asked, max_lpp[i], room, &big, fit);
		cut_piece(&merged, big);
		long b = room_budget(atlas, &ch[i], &merged, i, max_lpp[i], room, asked, &lpp_merged);
		if (lpp_merged > lpp)
			pc[i] = merged, budget[i] = b;
	}
}

/* The side of a one-map frame's fallback (every budget, a square over C_tot: as uniform
 * maps it) scaled to the fallback's rectangle fb (x0, y0, x1, y1 on G): the side at which
 * the fallback is as dense as that map along both axes. 0 where either rectangle is not
 * charted or has no extent. */
static double one_map_side(const struct lx_light_space *ls, const double *fb, long total)
{
	struct lx_poly want;
	double u[4], r[4] = {fb[0], fb[1], fb[2], fb[3]};
	if (!lx_light_space_wanted(ls, &want) || want.n < 3)
		return 0;
	lx_poly_bounds(&want, &u[0], &u[1], &u[2], &u[3]);
	lx_light_space_clamp(ls, u);
	lx_light_space_clamp(ls, r);
	double uw = u[2] - u[0], uh = u[3] - u[1], ratio = lx_fmax((r[2] - r[0]) / uw, (r[3] - r[1]) / uh);
	if (!(uw > 0 && uh > 0 && isfinite(ratio))) /* no extent, or a side unbounded */
		return 0;
	return floor(sqrt((double)total)) * ratio;
}

/* The fallback's side, square: its own lixels, and with shared budgets what the plane
 * maps leave unused this frame (a map at a whole-number scale, or none). With fixed
 * budgets a frame without any plane map is a one-map frame: the fallback serves every
 * receiver, and takes the planes' budgets too (as uniform does all of them), as far as
 * the atlas holds it alone; a plane without a map this frame hands it what the other
 * maps do not take (plane_budgets), as far as makes it as dense as that one map would be
 * (one_map_side), no more than a plane's budget (its region's limit) and no more than the
 * casters it serves need (`need`, fallback_need): on random views where the wall had no
 * map and the fallback at 128x128 served a box near the eye, plane lost to uniform by up
 * to 0.05 points. Under a density cap it keeps its own: the cap is there to spend less
 * fill. fb: the fallback's rectangle on G. */
static int fallback_side(const struct lx_atlas *atlas, const struct lx_method_options *o, const struct lx_shadow_result *out,
			 int np, const struct lx_light_space *ls, const double *fb, double need)
{
	if (o->plane_max_lpp > 0)
		return o->fallback_lixels;
	long own = (long)o->fallback_lixels * o->fallback_lixels, plane = (long)o->plane_lixels * o->plane_lixels;
	long used = 0;
	int mapless = np;
	for (int m = 0; m < out->map_count; m++)
		if (out->maps[m].rendered && out->maps[m].plane >= 0) /* the fallback's plane is -1 */
			used += (long)out->maps[m].w * out->maps[m].h;
	for (int i = 0; i < np; i++)
		mapless -= out->maps[i].rendered;
	long side = o->fallback_lixels;
	if (o->shared_budget || (mapless == np && atlas->regions[np].alone > 0)) {
		long left = (long)np * plane - used;
		side = (long)floor(sqrt((double)own + (double)(left > 0 ? left : 0)));
	} else {
		/* fixed budgets: the mapless planes' lixels that the others did not borrow (none
		 * where every plane has a map) */
		long borrowed = used - (long)(np - mapless) * plane, idle = (long)mapless * plane - (borrowed > 0 ? borrowed : 0);
		double most = lx_fmin(lx_fmin(sqrt((double)own + (double)idle), sqrt((double)atlas->regions[np].budget)), need);
		if (idle > 0 && most > side) /* one_map_side intersects two hulls: only where it may bind */
			side = (long)floor(lx_fmin(most, one_map_side(ls, fb, own + (long)np * plane)));
	}
	side = side < o->fallback_lixels ? o->fallback_lixels : side;
	return (int)(side < atlas->max_side ? side : atlas->max_side);
}

/* Whether a world box is outside the view frustum (all corners beyond one clip plane). */
static bool box_out_of_view(const struct lx_view *v, vec3 lo, vec3 hi)
{
	int out[6] = {0};
	for (int k = 0; k < 8; k++) {
		vec4 c = m4_mul_point(&v->view_proj, v3_box_corner(lo, hi, k));
		out[0] += c.x < -c.w, out[1] += c.x > c.w, out[2] += c.y < -c.w;
		out[3] += c.y > c.w, out[4] += c.z < -c.w, out[5] += c.z > c.w;
	}
	for (int i = 0; i < 6; i++)
		if (out[i] == 8)
			return true;
	return false;
}

/* The box's faces turned to both the eye and the light, as corner index triples: a face's
 * corner and its two edges' far ends. slack > 0 keeps too the faces within that share of
 * their distance of edge-on (to the eye or the light), whose side rounding may flip.
 * Returns the count. */
static int box_faces(const struct lx_frame *f, const vec3 *c, double slack, int (*faces)[3])
{
	static const int face[6][3] = {{0, 2, 4}, {1, 5, 3}, {0, 4, 1}, {2, 3, 6}, {0, 1, 2}, {4, 6, 5}};
	static const double normal[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
	const struct lx_light *L = &f->light;
	int n = 0;
	for (int i = 0; i < 6; i++) {
		vec3 nrm = v3(normal[i][0], normal[i][1], normal[i][2]);
		vec3 mid = v3_scale(v3_add(c[face[i][1]], c[face[i][2]]), 0.5);
		vec3 to_light = L->directional ? v3_scale(L->direction, -1) : v3_sub(L->position, mid);
		vec3 to_eye = v3_sub(f->view.eye, mid);
		if (v3_dot(nrm, to_eye) > -slack * v3_len(to_eye) && v3_dot(nrm, to_light) > -slack * v3_len(to_light))
			memcpy(faces[n++], face[i], sizeof face[i]);
	}
	return n;
}

/* The points whose hull holds what of caster id reads the fallback: of a box wholly beyond
 * the near plane, the corners of its faces turned to both the eye and the light (a face
 * turned away from the light is in its own shadow and reads no map, main.frag; one turned
 * away from the eye is hidden); else its outline (a round caster's curved side, or a box
 * the near plane cuts, whose inner faces show through the cut). A table's slab seen from
 * below gives its lit sides only, not its underside's whole shadow. */
static int fallback_points(const struct lx_frame *f, int id, vec3 *x)
{
	if (f->scene->casters[id - f->scene->plane_count].shape != LX_BOX || !lx_view_box_beyond_near(&f->view, f->bmin[id], f->bmax[id]))
		return lx_frame_object_outline(f, id, true, x);
	vec3 c[8];
	int faces[6][3], n = 0;
	for (int k = 0; k < 8; k++)
		c[k] = v3_box_corner(f->bmin[id], f->bmax[id], k);
	unsigned used = 0;
	for (int i = 0, nf = box_faces(f, c, 1e-9, faces); i < nf; i++) /* a face's fourth corner: o ^ u ^ v */
		used |= 1u << faces[i][0] | 1u << faces[i][1] | 1u << faces[i][2] | 1u << (faces[i][0] ^ faces[i][1] ^ faces[i][2]);
	for (int k = 0; k < 8; k++)
		if (used >> k & 1)
			x[n++] = c[k];
	return n;
}

/* The fallback's rays on G ([Kapoulkine]'s unit cube clipping, on its own receivers): the
 * casters in view that another object's shadow can reach, by the corners of their faces
 * the fallback serves (fallback_points; their surfaces are receivers no plane map serves),
 * and the visible part of each plane that needs it, within what the casters cover
 * (reached: those casters, as far as it got). False when a point cannot be charted on G
 * (a receiver behind the point light). */
static bool fallback_wanted(const struct lx_frame *f, const struct lx_light_space *ls, const bool *in_view,
			    const bool *needs, bool *reached, struct lx_poly *want)
{
	vec2 pts[LX_OUTLINE_POINTS * (LX_MAX_PLANES + LX_MAX_CASTERS) + 32 * LX_MAX_PLANES];
	int n = 0;
	for (int id = f->scene->plane_count; id < f->object_count; id++) {
		vec3 x[LX_OUTLINE_POINTS];
		int m = in_view[id] ? fallback_points(f, id, x) : 0;
		double own[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
		for (int k = 0; k < m; k++) {
			vec2 *g = &pts[n + k];
			if (!lx_light_space_chart(ls, f, (vec4){x[k].x, x[k].y, x[k].z, 1}, g))
				return false;
			own[0] = lx_fmin(own[0], g->x), own[1] = lx_fmin(own[1], g->y), own[2] = lx_fmax(own[2], g->x), own[3] = lx_fmax(own[3], g->y);
		}
		/* a convex caster never shadows its own lit faces: with no other shadow reaching
		 * it, it needs no lixel */
		reached[id] = m > 0 && lx_light_space_shadowed_by_other(ls, f, id, own);
		if (reached[id])
			n += m;
	}
	for (int p = 0; p < f->scene->plane_count; p++) {
		struct lx_poly win;
		vec3 world[32];
		int nw = 0;
		/* an edge-on plane is not "visible" but still gives its polygon in the view */
		if (!needs[p] || (!lx_plane_visible(&f->view, &f->scene->planes[p], &win, world, &nw) && nw == 0))
			continue;
		for (int k = 0; k < nw && k < 32; k++)
			if (!lx_light_space_chart(ls, f, (vec4){world[k].x, world[k].y, world[k].z, 1}, &pts[n++]))
				return false;
	}
	struct lx_poly rec;
	lx_poly_hull(pts, n, &rec);
	if (!ls->receivers_behind && ls->receivers.n >= 3) /* the view's receivers: what is seen */
		lx_poly_intersect(&rec, &ls->receivers, &rec);
	if (ls->casters_unbounded || ls->receivers_behind || ls->casters.n < 3)
		*want = rec;
	else
		lx_poly_intersect(&rec, &ls->casters, want);
	return true;
}

/* A box's corners through a projective matrix, in 2D units (sx, sy scale clip x, y);
 * false where a corner lies behind the matrix's centre or (depth_limited) beyond its far
 * plane. */
static bool box_image(const mat4 *m, const vec3 *c, double sx, double sy, bool depth_limited, vec2 *out)
{
	for (int k = 0; k < 8; k++) {
		vec4 d = m4_mul_point(m, c[k]);
		if (!(d.w > 0) || (depth_limited && d.z > d.w))
			return false;
		out[k] = (vec2){d.x / d.w * sx, d.y / d.w * sy};
	}
	return true;
}

/* The smaller singular value of the 2x2 matrix (a b; c d). */
static double sigma_min(double a, double b, double c, double d)
{
	double p = a * a + b * b + c * c + d * d, q = a * d - b * c; /* sum of squares, determinant */
	double disc = sqrt(lx_fmax(0, p * p - 4 * q * q));
	return sqrt(lx_fmax(0, 0.5 * (p - disc)));
}

/* Lixels per pixel a map gives a box's surfaces along their worst direction: over the
 * given faces, the least singular value of the map from the face's screen image to its
 * lixel image (taken affine per face, from its two edges; pix: the corners in pixels).
 * -1 where a corner is behind the map's light or beyond its depth range; 0 without a
 * face seen larger than a pixel. */
static double box_density(const struct lx_shadow_map *m, int w, int h, const vec3 *c, const vec2 *pix,
			  int (*faces)[3], int nf)
{
	vec2 lix[8];
	if (!box_image(&m->light_clip, c, 0.5 * w, 0.5 * h, true, lix))
		return -1;
	double worst = INFINITY;
	for (int i = 0; i < nf; i++) {
		int o = faces[i][0], u = faces[i][1], v = faces[i][2];
		/* P: the face's edges on the screen, L: in lixels; J = L P^-1 */
		double p11 = pix[u].x - pix[o].x, p12 = pix[v].x - pix[o].x, p21 = pix[u].y - pix[o].y, p22 = pix[v].y - pix[o].y;
		double l11 = lix[u].x - lix[o].x, l12 = lix[v].x - lix[o].x, l21 = lix[u].y - lix[o].y, l22 = lix[v].y - lix[o].y;
		double det = p11 * p22 - p12 * p21;
		if (!(fabs(det) > 1)) /* seen edge-on, or under a pixel: no pixels to serve */
			continue;
		double i11 = p22 / det, i12 = -p12 / det, i21 = -p21 / det, i22 = p11 / det;
		worst = lx_fmin(worst, sigma_min(l11 * i11 + l12 * i21, l11 * i12 + l12 * i22, l21 * i11 + l22 * i21,
					      l21 * i12 + l22 * i22));
	}
	return isfinite(worst) ? worst : 0;
}

/* A caster's densities (box_density) in the fallback and in each plane map (-1 for a map
 * it cannot read). */
struct caster_density {
	bool known; /* in view and taking maps (caster_densities) */
	double fallback, map[LX_MAX_MAPS];
};

/* The densities of caster id, the fallback's as if `side` lixels square: false where it
 * takes none of the maps (reaching behind the eye, the rule of lx_shadow_receiver_maps,
 * or no face seen larger than a pixel). */
static bool caster_densities(const struct lx_frame *f, const struct lx_shadow_result *out, int fbm, int side, int id,
			     struct caster_density *d)
{
	const struct lx_shadow_map *fb = &out->maps[fbm];
	vec3 c[8];
	vec2 pix[8];
	int faces[6][3];
	for (int k = 0; k < 8; k++)
		c[k] = v3_box_corner(f->bmin[id], f->bmax[id], k);
	if (!box_image(&f->view.view_proj, c, 0.5 * f->view.width, 0.5 * f->view.height, false, pix))
		return false;
	int nf = box_faces(f, c, 0, faces);
	d->fallback = box_density(fb, side, side, c, pix, faces, nf);
	if (!(d->fallback > 0))
		return false;
	for (int m = 0; m < out->map_count && m < LX_MAX_MAPS; m++) {
		const struct lx_shadow_map *pm = &out->maps[m];
		d->map[m] = pm->rendered && pm->plane >= 0 ? box_density(pm, pm->w, pm->h, c, pix, faces, nf) : -1;
	}
	return true;
}

/* The maps a caster of densities d reads: the densest LX_MAX_READS - 1 plane maps that
 * give it at least the fallback's (a draw reads at most LX_MAX_READS), then the fallback. */
static unsigned densest_maps(const struct lx_shadow_result *out, int fbm, const struct caster_density *d)
{
	unsigned mask = 1u << fbm;
	for (int k = 0; k < LX_MAX_READS - 1; k++) {
		int best = -1;
		for (int m = 0; m < out->map_count && m < LX_MAX_MAPS; m++)
			if (!(mask & 1u << m) && d->map[m] >= d->fallback && (best < 0 || d->map[m] > d->map[best]))
				best = m;
		if (best >= 0)
			mask |= 1u << best;
	}
	return mask;
}

/* Which maps a caster's own surfaces read. A plane map holds every caster in front of
 * its plane, so it can serve a caster's rays too, and often more densely than the small
 * fallback; but seen from the eye a caster may be squeezed in it along some direction (a
 * sphere over a floor seen from a millimetre above it: the floor map is three lixels
 * tall), or lie beyond its depth range. A caster reads, in order, the plane maps that give
 * its faces at least the fallback's lixels per pixel in their worst direction (the
 * densest three of them), then the fallback (which covers every caster in view another's
 * shadow can reach). Each one's densities in cd[id]. Each plane map a caster reads then
 * draws it as its faces near its silhouette, not as a fan (renderer.c): the facing
 * view's ball, under the cone's shadow, is 234 triangles in each of the floor's two
 * pieces, where its fan is 52. --caster-maps fallback (caster_fallback_only) leaves
 * this out: each caster reads the fallback alone, for less shadow-pass work and coarser
 * shadows of casters on casters (docs/plane-optimal.md, "Casters' maps"). cd: the
 * densities (casters_densities), the fallback's with fixed budgets at its own 128,
 * whatever a plane without a map hands it this frame, which then serves what reads the
 * fallback and takes no caster off the plane maps (taken at its grown size, the casters left the
 * floor's maps on the default view and on horizon at 1024x1024, 0.0051% -> 0.0070% and
 * 0.0094% -> 0.0125%, and the main pass on horizon took 0.14 ms more). */
static void choose_caster_maps(const struct lx_frame *f, int fbm, struct lx_shadow_result *out,
			       const struct caster_density *cd)
{
	for (int id = f->scene->plane_count; id < f->object_count; id++)
		if (cd[id].known)
			out->object_maps[id] = densest_maps(out, fbm, &cd[id]);
}

/* Each caster's densities in cd (caster_densities, the fallback's as if `side` lixels
 * square; known: in view and taking maps). */
static void casters_densities(const struct lx_frame *f, const struct lx_shadow_result *out, int fbm, int side,
			      const bool *in_view, struct caster_density *cd)
{
	for (int id = f->scene->plane_count; id < f->object_count; id++)
		cd[id].known = in_view[id] && caster_densities(f, out, fbm, side, id, &cd[id]);
}

/* The fallback's side past which it gives no caster it serves more than a lixel per pixel
 * in its worst direction (box_density; cd: their densities at `side`): as with the plane
 * maps past one (readers_scale), more would change no decision on the caster's own pixels
 * and cost fill (at 160x120 the default view's fallback took 350x350 where 128x128 gives
 * each caster several). Only the casters another's shadow reaches look it up; INFINITY
 * where a plane reads it (needs), whose density is not known here. */
static double fallback_need(const struct lx_frame *f, const struct lx_shadow_result *out, const bool *needs,
			    const struct caster_density *cd, int side)
{
	double need = 0;
	for (int i = 0; i < f->scene->plane_count; i++)
		if (needs[i])
			return INFINITY;
	for (int id = f->scene->plane_count; id < f->object_count; id++)
		if (cd[id].known && out->shadow_reaches[id]) /* known: its density > 0 */
			need = lx_fmax(need, side / cd[id].fallback);
	return need;
}

/* The whole-number scale plane i's maps need, at most their scale k now (k > 1, a
 * similarity). Past a lixel per pixel the extra lixels change no decision on the plane's
 * own pixels, whose centres already fall on lixel centres: they serve only the casters
 * that read the maps (choose_caster_maps), and they cost fill, a caster's image growing
 * with the map (close to the default scene's floor at 1024x1024, 0.10 ms of shadow pass
 * at 3x3 lixels a pixel against one). So each caster reading one of them asks for a
 * lixel per pixel in its worst direction, and no less than the fallback's (else it would
 * read the fallback instead), as far as k gives it; a map no caster reads takes one
 * lixel a pixel. */
static double readers_scale(const struct lx_frame *f, const struct lx_shadow_result *out,
			    const struct caster_density *cd, int fbm, int plane, double k)
{
	double need = 1;
	for (int id = f->scene->plane_count; id < f->object_count; id++) {
		unsigned reads = out->object_maps[id];
		if (!out->shadow_reaches[id] || !(reads & 1u << fbm))
			continue; /* no lookup on it (no other's shadow reaches it), or no maps chosen */
		for (int m = 0; m < out->map_count && m < LX_MAX_MAPS; m++) {
			if (!(reads & 1u << m) || out->maps[m].plane != plane)
				continue;
			/* read: its density d >= the fallback's > 0. The slack keeps an exact whole
			 * number from rounding up; the check redoes lower_to_readers' scaling, in its
			 * operations, so that the caster still finds the map as dense as the fallback */
			double d = cd[id].map[m], kn = ceil(k * lx_fmax(cd[id].fallback, 1) / d - 1e-9);
			if (d * (1 / k * kn) < cd[id].fallback)
				kn++;
			need = lx_fmax(need, kn);
		}
	}
	return lx_fmin(need, k);
}

/* The fallback map (map fbm, region np): the receivers no plane map takes, and the maps
 * each caster reads (in_view: the objects in view, for choose_caster_maps; cd: their
 * densities), and which casters another's shadow may reach (out->shadow_reaches). */
static void build_fallback(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_method_options *o,
			   const struct lx_light_space *ls, const struct plane_chart *ch, int np, int fbm,
			   bool *in_view, struct caster_density *cd, struct lx_shadow_result *out)
{
	struct lx_shadow_map *fb = &out->maps[fbm];
	bool needs[LX_MAX_PLANES] = {false};
	for (int i = 0; i < f->scene->plane_count; i++)
		needs[i] = i >= np || (ch[i].needs_fallback && !out->maps[i].rendered);
	for (int id = f->scene->plane_count; id < f->object_count; id++) {
		in_view[id] = !box_out_of_view(&f->view, f->bmin[id], f->bmax[id]);
		out->shadow_reaches[id] = in_view[id]; /* unless fallback_wanted finds none reaches it */
	}
	struct lx_poly want;
	double x0 = -INFINITY, x1 = INFINITY, y0 = -INFINITY, y1 = INFINITY;
	if (fallback_wanted(f, ls, in_view, needs, out->shadow_reaches, &want)) {
		if (want.n < 3)
			return; /* no receiver off the planes in view */
		lx_poly_bounds(&want, &x0, &y0, &x1, &y1);
	} else if (lx_light_space_wanted(ls, &want)) { /* not charted on G: all of C_tot */
		if (want.n < 3)
			return;
		lx_poly_bounds(&want, &x0, &y0, &x1, &y1);
	}
	fb->rendered = lx_light_space_map(ls, x0, x1, y0, y1, &fb->light_clip, out, "fallback");
	if (!fb->rendered)
		return;
	/* the casters' densities at its own side; its size this frame, before the atlas is
	 * packed (whose region still has the last frame's): a fixed region's, or its own, with
	 * more where a plane has no map or with shared budgets what the planes leave
	 * (fallback_side). With shared budgets the casters choose against that size (a density
	 * scales with the side), with fixed ones against its own (choose_caster_maps) */
	int side = o->fallback_lixels;
	casters_densities(f, out, fbm, side, in_view, cd);
	fb->w = atlas->regions[np].w, fb->h = atlas->regions[np].h;
	if (atlas->regions[np].variable)
		fb->w = fb->h = fallback_side(atlas, o, out, np, ls, (double[4]){x0, y0, x1, y1},
					      o->shared_budget ? INFINITY : fallback_need(f, out, needs, cd, side));
	if (o->shared_budget) /* the casters choose against the grown side: a density scales with it */
		for (int id = f->scene->plane_count; id < f->object_count; id++)
			if (cd[id].known)
				cd[id].fallback *= (double)fb->w / side;
	if (!o->caster_fallback_only)
		choose_caster_maps(f, fbm, out, cd);
}

/* What plane_build settles for each plane map before building it. */
struct plane_plan {
	int np;
	bool ok[PLANE_MAPS]; /* the plane has a map */
	struct plane_chart ch[PLANE_MAPS];
	struct plane_pieces pc[PLANE_MAPS];
	mat4 depth[PLANE_MAPS];
	long budget[PLANE_MAPS];
	double max_lpp[PLANE_MAPS]; /* its density cap (0 or less: none) */
};

/* The plane maps of the plan, of the planes in the mask `planes`: plane i's in map i, its
 * spare pieces' in the maps after the planes', in the planes' order. */
static void build_plane_maps(const struct lx_atlas *atlas, const struct plane_plan *pl, unsigned planes,
			     struct lx_shadow_result *out)
{
	for (int i = 0, next = pl->np; i < pl->np; i++) {
		struct lx_shadow_map *more[PIECES_MAX - 1];
		for (int k = 1; pl->ok[i] && k < pl->pc[i].n; k++)
			more[k - 1] = &out->maps[next++];
		if (pl->ok[i] && planes & 1u << i)
			build_plane_map(atlas, &pl->ch[i], &pl->pc[i], &pl->depth[i], i, pl->budget[i], pl->max_lpp[i],
					&out->maps[i], more);
	}
}

/* Caps the density of each plane map past a lixel per pixel at what the casters reading
 * it need (readers_scale) and builds the lowered ones again. Their densities for each
 * caster shrink with their scale (a caster's image in a piece is the chart's, scaled), and
 * the casters choose their maps again among them. */
static void lower_to_readers(const struct lx_frame *f, const struct lx_atlas *atlas, int fbm, struct plane_plan *pl,
			     struct caster_density *cd, struct lx_shadow_result *out)
{
	double ratio[PLANE_MAPS];
	unsigned lowered = 0;
	for (int i = 0; i < pl->np; i++) {
		const struct lx_shadow_map *m = &out->maps[i];
		ratio[i] = 1;
		if (!pl->ok[i] || !m->rendered || m->lixel_stretch != 1 || !(m->lixel_scale > 1))
			continue; /* short of a lixel per pixel, or at one */
		double k = readers_scale(f, out, cd, fbm, i, m->lixel_scale);
		if (k < m->lixel_scale) {
			pl->max_lpp[i] = pl->max_lpp[i] > 0 ? lx_fmin(pl->max_lpp[i], k * k) : k * k;
			ratio[i] = 1 / m->lixel_scale; /* > 0: past 1 */
			lowered |= 1u << i;
		}
	}
	if (!lowered)
		return;
	build_plane_maps(atlas, pl, lowered, out);
	for (int i = 0; i < pl->np; i++)
		ratio[i] *= lowered & 1u << i ? out->maps[i].lixel_scale : 1;
	for (int id = f->scene->plane_count; id < f->object_count; id++) {
		if (!(out->object_maps[id] & 1u << fbm))
			continue; /* no maps chosen */
		for (int m = 0; m < out->map_count && m < LX_MAX_MAPS; m++)
			if (out->maps[m].plane >= 0 && lowered & 1u << out->maps[m].plane && cd[id].map[m] > 0)
				cd[id].map[m] *= ratio[out->maps[m].plane];
		out->object_maps[id] = densest_maps(out, fbm, &cd[id]);
	}
}

/* The feet made again from the parts, less what casters hide from the eye (hidden_feet),
 * and the choices made again where the feet changed (the parts, or what is hidden);
 * false when casters hide every foot. */
static bool split_again(const struct lx_frame *f, struct caster_images *images, bool changed, int spare, long budget,
			struct plane_chart *ch, struct plane_splits *sp, const struct foot_parts *parts)
{
	bool hid_some = false;
	if (!hidden_feet(f, ch, parts, images, &hid_some))
		return false;
	if (changed || hid_some)
		plane_splits(ch, spare > 0, budget, sp);
	return true;
}

/* Plane i charted (chart_plane) and its choices of rectangles made (plane_splits), with
 * `spare` pieces to take and its own budget of lixels; false when it gets no map. */
static bool chart_and_split(const struct lx_frame *f, const struct lx_light_space *ls, int i, int np,
			    const struct lx_method_options *o, struct lx_shadow_result *out, struct caster_images *images,
			    int spare, struct plane_chart *ch, struct plane_splits *sp, struct foot_parts *parts)
{
	long own = (long)o->plane_lixels * o->plane_lixels;
	covered_part(f, &out->covers, i, &ch->covered);
	if (!chart_plane(f, ls, i, i + 1 < np ? i + 1 : -1, o, out, ch, parts))
		return false;
	plane_splits(ch, spare > 0, own, sp); /* share_pieces keeps within the spare ones */
	/* Where its pieces still hold more pixels than the budget has lixels, the feet leave
	 * out what casters hide from the eye (take_hidden): a shadow there is never seen. Not
	 * before: within the budget it buys no density, and a smaller rectangle would only
	 * take the pieces' place with more area (on the default view at 1024x1024 one 586x205
	 * against two of 76,000 lixels together, 0.13 ms more shadow pass in interleaved
	 * runs). */
	return !(least_area(sp) > (double)own) || split_again(f, images, false, spare, own, ch, sp, parts);
}

/* A plane whose pieces hold more pixels than the most lixels it can get this frame (its
 * own budget and those of the planes without a map: plane_budgets) gets its footprints cut
 * in slabs (slab_feet) and its choices made again; false when then no foot is left. Not
 * against its own budget alone: under the table's low light at 1920x1080 the floor, with
 * the top's idle budget, is at a lixel per pixel in three pieces, and slabs cut it in
 * four for nothing. */
static bool slab_and_split(const struct lx_frame *f, int spare, long most, struct caster_images *images,
			   struct plane_chart *ch, struct plane_splits *sp, struct foot_parts *parts)
{
	if (!(least_area(sp) > (double)most) || !slab_feet(ch, parts))
		return true;
	return split_again(f, images, true, spare, most, ch, sp, parts);
}

static void plane_build(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_method_options *o,
			struct lx_shadow_result *out)
{
	int np = f->scene->plane_count < PLANE_MAPS ? f->scene->plane_count : PLANE_MAPS;
	/* The maps in the order a receiver reads them, the first that serves a point deciding
	 * it: the planes' own, their spare pieces, and last the fallback, which serves what
	 * no plane map does (a caster reading a piece denser than the fallback must reach it
	 * first: choose_caster_maps). Each in its region of plane_regions, the fallback's np. */
	int fbm = atlas->count - 1;
	out->map_count = atlas->count;
	for (int i = 0; i < atlas->count; i++) {
		out->maps[i] = (struct lx_shadow_map){.region = i < np ? i : i == fbm ? np : i + 1, .rendered = false,
						      .light_clip = m4_identity()};
		lx_shadow_map_full(&out->maps[i]);
		out->maps[i].plane = i < np ? i : -1;
	}
	struct lx_light_space ls;
	lx_light_space_build(f, &ls);
	if (ls.empty)
		return; /* no shadow can fall in the view: no pass at all */
	struct plane_plan pl; /* not zeroed: every field of planes 0..np-1 is set below */
	pl.np = np;
	struct caster_images images;
	memset(images.state, 0, sizeof images.state);
	/* the atlas's spare pieces (plane_regions), for planes whose footprints cluster */
	int spare = atlas->count > np + 1 && atlas->regions[0].variable && !o->plane_one_piece ? atlas->count - np - 1 : 0;
	long own = (long)o->plane_lixels * o->plane_lixels;
	struct plane_splits sp[PLANE_MAPS];
	struct foot_parts parts[PLANE_MAPS];
	long most = own;
	for (int i = 0; i < np; i++) {
		pl.ch[i].unmapped = out->slab_out;
		pl.ok[i] = chart_and_split(f, &ls, i, np, o, out, &images, spare, &pl.ch[i], &sp[i], &parts[i]);
		most += pl.ok[i] ? 0 : own;
	}
	for (int i = 0; i < np && !o->plane_unslabbed; i++)
		if (pl.ok[i])
			pl.ok[i] = slab_and_split(f, spare, most, &images, &pl.ch[i], &sp[i], &parts[i]);
	int take[PLANE_MAPS];
	share_pieces(sp, pl.ok, np, spare, own, take);
	for (int i = 0; i < np; i++) {
		if (!pl.ok[i])
			continue;
		pl.pc[i] = sp[i].by[take[i]];
		one_piece_to_feet(&pl.ch[i], &pl.pc[i], own);
		/* no caster in front of a receiver there: no map (its pieces stay unused) */
		pl.ok[i] = plane_depth(f, &ls, &pl.ch[i], &pl.pc[i], out, &f->scene->planes[i], &pl.depth[i]);
	}
	plane_budgets(atlas, o, pl.ch, pl.pc, pl.ok, np, pl.budget);
	/* where no caster reads a plane map (--caster-maps fallback), the readers' density is
	 * a lixel per pixel from the first fit, which lower_to_readers would build again */
	bool unread = o->caster_fallback_only && !o->plane_dense_budget && !o->filtered;
	for (int i = 0; i < np; i++)
		pl.max_lpp[i] = unread ? (o->plane_max_lpp > 0 ? lx_fmin(o->plane_max_lpp, 1) : 1) : o->plane_max_lpp;
	if (!o->shared_budget) { /* the regions hold their own budgets: shared ones hold all */
		int free = spare;
		for (int i = 0; i < np; i++)
			free -= pl.ok[i] ? pl.pc[i].n - 1 : 0;
		cut_to_regions(atlas, pl.ch, pl.max_lpp, np, pl.ok, free, pl.pc, pl.budget);
	}
	build_plane_maps(atlas, &pl, ~0u, out);
	bool in_view[LX_MAX_PLANES + LX_MAX_CASTERS];
	struct caster_density cd[LX_MAX_PLANES + LX_MAX_CASTERS];
	build_fallback(f, atlas, o, &ls, pl.ch, np, fbm, in_view, cd, out);
	/* past a lixel per pixel, only as dense as the casters reading a map need it; the
	 * fallback keeps its size (with shared budgets what the first fit left it), and the
	 * casters choose again among the smaller maps. Not under a filter: it reads a box of
	 * lixels, narrower on the screen the denser the map, so there the extra lixels shape
	 * the plane's own edges (directional at 320x240, pcf3x3: a soft-edge error of 0.047%
	 * at the budget's 25 lixels a pixel, 0.253% at one) */
	if (!o->plane_dense_budget && !o->filtered)
		lower_to_readers(f, atlas, fbm, &pl, cd, out);
}

const struct lx_shadow_method lx_method_plane = {.name = "plane",
	.summary = "plane-optimal maps for the first two planes (350^2 lixels each, shaped per frame) and a 128x128 fallback",
	.regions = plane_regions,
	.build = plane_build};
