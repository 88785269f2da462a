#include "frame.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

bool lx_frame_setup(struct lx_frame *f, const struct lx_scene *s, const struct lx_scene_meshes *m, double t,
		    int width, int height, char *err, size_t errlen)
{
	memset(f, 0, sizeof(*f));
	f->scene = s;
	f->meshes = m;
	f->time = t;
	f->light = s->light;
	f->object_count = m->count;
	f->scene_min = v3(INFINITY, INFINITY, INFINITY);
	f->scene_max = v3(-INFINITY, -INFINITY, -INFINITY);
	for (int id = 0; id < m->count; id++) {
		vec3 o = lx_object_offset(s, id, t);
		f->offset[id] = o;
		f->bmin[id] = v3_add(m->mesh[id].bmin, o);
		f->bmax[id] = v3_add(m->mesh[id].bmax, o);
		f->scene_min = v3(fmin(f->scene_min.x, f->bmin[id].x), fmin(f->scene_min.y, f->bmin[id].y),
				  fmin(f->scene_min.z, f->bmin[id].z));
		f->scene_max = v3(fmax(f->scene_max.x, f->bmax[id].x), fmax(f->scene_max.y, f->bmax[id].y),
				  fmax(f->scene_max.z, f->bmax[id].z));
	}
	struct lx_view *v = &f->view;
	v->width = width;
	v->height = height;
	v->eye = s->camera.eye;
	v->fovy = s->camera.fovy_deg * M_PI / 180;
	v->dir = v3(0, 0, -1);
	v3_normalize(v3_sub(s->camera.at, s->camera.eye), &v->dir); /* look_at below refuses eye == at */
	if (!m4_look_at(s->camera.eye, s->camera.at, s->camera.up, &v->view)) {
		snprintf(err, errlen, "camera: eye equals at, or up is along the view direction");
		return false;
	}
	/* far: the farthest scene corner; near: the distance to the scene box. */
	double far = 0, near2 = 0;
	for (int i = 0; i < 8; i++) {
		vec3 c = v3(i & 1 ? f->scene_max.x : f->scene_min.x, i & 2 ? f->scene_max.y : f->scene_min.y,
			    i & 4 ? f->scene_max.z : f->scene_min.z);
		far = fmax(far, v3_len(v3_sub(c, v->eye)));
	}
	for (int k = 0; k < 3; k++) {
		double e = (&v->eye.x)[k], lo = (&f->scene_min.x)[k], hi = (&f->scene_max.x)[k];
		double d = e < lo ? lo - e : e > hi ? e - hi : 0;
		near2 += d * d;
	}
	far = far * 1.01 + 1e-6; /* a scene of a single point still gets a valid range */
	v->far = far;
	v->near = fmax(sqrt(near2) * 0.9, far / 1000);
	if (!(v->near < v->far * 0.5)) /* the whole scene is a speck far away */
		v->near = v->far * 0.5;
	if (!m4_perspective(v->fovy, (double)width / height, v->near, v->far, &v->proj)) {
		snprintf(err, errlen, "camera: cannot build a projection for fov %g degrees and size %dx%d",
			 s->camera.fovy_deg, width, height);
		return false;
	}
	v->view_proj = m4_mul(&v->proj, &v->view);
	if (!m4_invert(&v->view_proj, &v->inv_view_proj)) {
		snprintf(err, errlen, "camera: the view projection is singular");
		return false;
	}
	return true;
}

void lx_view_frustum_corners(const struct lx_view *v, vec3 fc[8])
{
	static const double cx[4] = {-1, 1, 1, -1}, cy[4] = {-1, -1, 1, 1};
	for (int i = 0; i < 8; i++) {
		vec4 p = m4_mul_v4(&v->inv_view_proj, (vec4){cx[i % 4], cy[i % 4], i < 4 ? -1 : 1, 1});
		/* w > 0 for the corners of a valid perspective frustum */
		fc[i] = v3(p.x / p.w, p.y / p.w, p.z / p.w);
	}
}
