/* What a plane of interest's lit front shadows (plane_cover.h). */
#include "plane_cover.h"
#include <math.h>

/* Row r of m: h_r = a . X + b. */
static void set_row(mat4 *m, int r, vec3 a, double b)
{
	m->m[r] = a.x, m->m[4 + r] = a.y, m->m[8 + r] = a.z, m->m[12 + r] = b;
}

bool lx_plane_cover_matrix(const struct lx_frame *f, int p, mat4 *out)
{
	if (p < 0 || p >= f->scene->plane_count)
		return false;
	const struct lx_plane *pl = &f->scene->planes[p];
	vec3 q[4];
	lx_frame_plane_corners(f, p, q);
	vec3 c = q[0], e1 = pl->edge1, e2 = pl->edge2, n = v3_cross(e1, e2);
	double nn = v3_dot(n, n);
	if (!(nn > 0))
		return false; /* no parallelogram (the scene parser refuses one) */
	/* the dual basis: a1 . e1 = a2 . e2 = 1, and each is 0 on the other edge and on n */
	vec3 a1 = v3_scale(v3_cross(e2, n), 1 / nn), a2 = v3_scale(v3_cross(n, e1), 1 / nn);
	double nl = sqrt(nn); /* nn > 0 */
	const struct lx_light *L = &f->light;
	if (L->directional) {
		vec3 d = L->direction;
		double nd = v3_dot(n, d);
		if (!(nd < -LX_COVER_GRAZING * nl * v3_len(d)))
			return false; /* its back is lit, or the light runs along it */
		/* s = n . (X - c) / n . d: how far X's ray runs back towards the light to the
		 * plane (> 0 beyond it), and the crossing Y = X - s d */
		vec3 s = v3_scale(n, 1 / nd); /* nd < 0 */
		double s0 = -v3_dot(n, c) / nd;
		for (int i = 0; i < 2; i++) {
			vec3 a = i ? a2 : a1;
			double ad = v3_dot(a, d);
			set_row(out, i, v3_sub(a, v3_scale(s, ad)), -v3_dot(a, c) - s0 * ad);
		}
		set_row(out, 2, v3(0, 0, 0), 1);
		/* in the parallelogram's size (> 0: nl > 0), as w - 1 below is in the light's
		 * distance: LX_COVER_TOUCH is a share of either */
		double size = v3_len(e1) + v3_len(e2);
		set_row(out, 3, v3_scale(s, 1 / size), s0 / size);
		return true;
	}
	vec3 lp = L->position, lc = v3_sub(lp, c);
	double k = v3_dot(n, lc), reach = v3_len(lc) + v3_len(e1) + v3_len(e2);
	if (!(k > LX_COVER_GRAZING * nl * reach))
		return false; /* its back is lit, or the light lies about on its plane */
	/* w = n . (L - X) / k: 1 on the plane, > 1 beyond it. The crossing of L -> X with the
	 * plane lies at 1 / w of the way (between L and X exactly where w > 1), and
	 * w (Y - c) = w (L - c) + X - L, affine in X */
	vec3 wv = v3_scale(n, -1 / k); /* k > 0 */
	double w0 = v3_dot(n, lp) / k;
	for (int i = 0; i < 2; i++) {
		vec3 a = i ? a2 : a1;
		double al = v3_dot(a, lc);
		set_row(out, i, v3_add(v3_scale(wv, al), a), w0 * al - v3_dot(a, lp));
	}
	set_row(out, 2, wv, w0);
	set_row(out, 3, wv, w0 - 1);
	return true;
}

/* Whether the part of box [lo, hi] where h.w > LX_COVER_TOUCH has rays crossing inside the
 * parallelogram's bounds: that part is the box cut by the plane, whose corners are the
 * box's corners beyond it and its edges' crossings; the light's projection of it, the
 * hull of theirs (h.z >= 1 there, or 1 for a directional light). */
static bool beyond_meets(const mat4 *m, vec3 lo, vec3 hi)
{
	vec4 h[8];
	for (int k = 0; k < 8; k++) {
		h[k] = m4_mul_point(m, v3_box_corner(lo, hi, k));
		h[k].w -= LX_COVER_TOUCH; /* a box touching the plane (the floor's edge at the wall's foot) is not beyond it */
	}
	double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
	for (int a = 0; a < 8; a++)
		for (int bit = 0; bit < 4; bit++) { /* each corner alone (bit 3), each edge once */
			int b = bit < 3 ? a | 1 << bit : a;
			if (b == a && bit < 3)
				continue;
			vec4 x = h[a];
			if (b != a) {
				if ((h[a].w > 0) == (h[b].w > 0))
					continue;
				x = v4_lin(h[b].w / (h[b].w - h[a].w), h[a], h[a].w / (h[a].w - h[b].w), h[b]);
			} else if (!(x.w > 0))
				continue;
			if (!(x.z > 0))
				continue; /* cannot happen beyond the plane: h.z = 1 + h.w or 1 */
			u0 = fmin(u0, x.x / x.z), u1 = fmax(u1, x.x / x.z);
			v0 = fmin(v0, x.y / x.z), v1 = fmax(v1, x.y / x.z);
		}
	return u0 <= 1 && u1 >= 0 && v0 <= 1 && v1 >= 0;
}

int lx_plane_cover_of(const struct lx_frame *f, int id, mat4 *m)
{
	if (id < 0 || id >= f->object_count)
		return -1;
	for (int p = 0; p < f->scene->plane_count; p++)
		if (p != id && lx_plane_cover_matrix(f, p, m) && beyond_meets(m, f->bmin[id], f->bmax[id]))
			return p;
	return -1;
}

bool lx_plane_cover_image(const struct lx_frame *f, int p, int q, struct lx_poly *win)
{
	win->n = 0;
	if (p < 0 || q < 0 || p >= f->scene->plane_count || q >= f->scene->plane_count || p == q)
		return false;
	vec3 pc[4], qc[4];
	lx_frame_plane_corners(f, p, pc);
	lx_frame_plane_corners(f, q, qc);
	vec3 nq = v3_cross(f->scene->planes[q].edge1, f->scene->planes[q].edge2);
	const struct lx_light *L = &f->light;
	vec2 pts[4];
	for (int k = 0; k < 4; k++) {
		/* the corner's shadow on q's plane: along the light's ray past the corner */
		vec3 dir = L->directional ? L->direction : v3_sub(pc[k], L->position);
		double along = v3_dot(nq, dir), t = v3_dot(nq, v3_sub(qc[0], pc[k])) / along;
		if (!(fabs(along) > 1e-12 * v3_len(nq) * v3_len(dir)) || !(t >= 0) || !isfinite(t))
			return false; /* the ray runs along q's plane, or meets it before the corner */
		vec4 c = m4_mul_point(&f->view.view_proj, v3_add(pc[k], v3_scale(dir, t)));
		if (!(c.w > 1e-9 * (fabs(c.x) + fabs(c.y) + fabs(c.z))))
			return false; /* at or behind the eye: the shadow's image is not the corners' hull */
		pts[k] = (vec2){(c.x / c.w * 0.5 + 0.5) * f->view.width, (c.y / c.w * 0.5 + 0.5) * f->view.height};
	}
	/* the corners' shadows bound the shadow (a central projection of the parallelogram,
	 * every corner in front of the light and of the eye, keeps it convex) */
	lx_poly_hull(pts, 4, win);
	return win->n >= 3;
}

bool lx_scene_may_need_cover(const struct lx_scene *s, const struct lx_scene_meshes *m)
{
	int n = lx_scene_object_count(s);
	for (int p = 0; p < s->plane_count; p++) {
		const struct lx_plane *pl = &s->planes[p];
		vec3 nrm = v3_cross(pl->edge1, pl->edge2);
		double touch = LX_COVER_TOUCH * v3_len(nrm) * (v3_len(pl->edge1) + v3_len(pl->edge2));
		for (int id = 0; id < n && id < m->count; id++) {
			vec3 lo = m->mesh[id].bmin, hi = m->mesh[id].bmax;
			if (id >= s->plane_count) { /* its box over its bounce (lx_caster_bottom) */
				const struct lx_caster *c = &s->casters[id - s->plane_count];
				lo = v3_add(lo, v3(c->x, fmin(c->low, c->high), c->z));
				hi = v3_add(hi, v3(c->x, fmax(c->low, c->high), c->z));
			}
			for (int k = 0; id != p && k < 8; k++)
				if (v3_dot(nrm, v3_sub(v3_box_corner(lo, hi, k), pl->corner)) < -touch)
					return true;
		}
	}
	return false;
}
