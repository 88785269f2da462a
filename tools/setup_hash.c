/* The set-up's outputs hashed (`make setup-hash`): every method and plane-optimal
 * setting, over every built-in scene, its configurations and 40 random views each
 * (eye, target, a point light and an animation time), at three sizes, three animation
 * times on the first configuration. What is hashed is what the GL passes and the
 * measurements read: each map's matrix, region, bounds, density and screen reach, the
 * warnings, the objects' maps, the fronts and the flat boxes' faces, the atlas layout.
 * The same hash before and after a change to the set-up says it computes the same, bit
 * for bit; -v prints each set-up's own hash, to find the first that differs. The result
 * starts as garbage each time, so a set-up that reads what it did not write differs.
 * Usage: setup-hash [-v] */
#include "atlas.h"
#include "configs.h"
#include "frame.h"
#include "mesh.h"
#include "shadow_method.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static unsigned long long hash = 1469598103934665603ull; /* FNV-1a, 64 bits */

static void mix(const void *p, size_t n)
{
	const unsigned char *c = p;
	for (size_t i = 0; i < n; i++)
		hash = (hash ^ c[i]) * 1099511628211ull;
}
#define MIX(x) mix(&(x), sizeof(x))

static void mix_maps(const struct lx_shadow_result *r)
{
	MIX(r->variant), MIX(r->map_count);
	for (int i = 0; i < r->map_count; i++) {
		const struct lx_shadow_map *m = &r->maps[i];
		MIX(m->region), MIX(m->rendered), MIX(m->light_clip), MIX(m->plane), MIX(m->lixel_scale);
		MIX(m->lixel_stretch), MIX(m->w), MIX(m->h), MIX(m->pancake), MIX(m->bounds), MIX(m->has_screen);
		if (m->has_screen)
			MIX(m->screen), MIX(m->screen_served);
	}
	MIX(r->warning_count);
	for (int i = 0; i < r->warning_count; i++)
		mix(r->warnings[i], strlen(r->warnings[i]));
}

static void mix_result(const struct lx_shadow_result *r, const struct lx_atlas *a, int objects)
{
	mix_maps(r);
	mix(r->object_maps, (size_t)objects * sizeof r->object_maps[0]);
	const struct lx_plane_covers *c = &r->covers;
	MIX(c->count), MIX(c->slabs);
	for (int i = 0; i < c->count; i++) {
		MIX(c->owner[i]), MIX(c->top[i]), MIX(c->corner[i]), MIX(c->lit[i]), MIX(c->outline[i]);
		if (c->lit[i])
			MIX(c->m[i]);
	}
	for (int id = 0; id < objects; id++) {
		MIX(c->of[id]), MIX(c->paired[id]), MIX(r->slab_face_out[id]), MIX(r->slab_out[id]);
		if (r->slab_face_out[id])
			MIX(r->slab_front[id]);
	}
	MIX(a->count);
	for (int i = 0; i < a->count; i++)
		MIX(a->regions[i].w), MIX(a->regions[i].h), MIX(a->regions[i].x), MIX(a->regions[i].y);
}

/* A number in [lo, hi) from the seed (a linear congruential step: the same views on
 * every machine). */
static double uniform_in(unsigned *seed, double lo, double hi)
{
	*seed = *seed * 1103515245u + 12345u;
	return lo + (hi - lo) * ((*seed >> 8) & 0xffffff) / 16777216.0;
}

/* Scene `name` as configuration c, or for c < 0 a random view of it; its time in *t. */
static bool scene_for(const char *name, int c, int k, struct lx_scene *s, double *t)
{
	if (!lx_scene_builtin(name, s))
		return false;
	*t = 0;
	if (c >= 0) {
		lx_config_apply(&lx_configs[c], s);
		return true;
	}
	unsigned seed = (unsigned)(c * 7919 + k * 104729);
	s->camera.eye = (vec3){uniform_in(&seed, -5, 5), uniform_in(&seed, 0.3, 5), uniform_in(&seed, -1, 6)};
	s->camera.at = (vec3){uniform_in(&seed, -1.5, 1.5), uniform_in(&seed, 0, 1.2), uniform_in(&seed, -3, 1)};
	vec3 light = {uniform_in(&seed, -6, 6), uniform_in(&seed, 1, 7), uniform_in(&seed, -4, 6)};
	if (!s->light.directional && !s->light.projective)
		s->light.position = light;
	*t = uniform_in(&seed, 0, 5);
	return true;
}

static const char *const specs[] = {"none", "uniform", "psm", "lispsm", "xpsm", "tsm", "plane", "plane/square",
				    "plane/shared", "plane/lpp1", "plane/twist", "plane/onepiece", "plane/similar",
				    "plane/shared/similar"};
enum { SPECS = sizeof specs / sizeof specs[0] };

/* Every method's set-up of frame f into the hash; false on an error (printed). */
static bool hash_frame(const struct lx_frame *f, bool verbose, const char *label, long *count)
{
	static struct lx_shadow_result res;
	for (int k = 0; k < SPECS; k++) {
		char err[256];
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		const struct lx_shadow_method *m = lx_shadow_method_spec(specs[k], &o, err, sizeof err);
		struct lx_region_request req[LX_MAX_MAPS];
		struct lx_atlas a;
		if (!m || !lx_atlas_layout(&a, req, lx_shadow_method_regions(m, f->scene, &o, req), 1, 2048, err,
					   sizeof err)) {
			fprintf(stderr, "setup-hash: %s: %s\n", specs[k], err);
			return false;
		}
		memset(&res, 0xa5, sizeof res); /* garbage in: nothing of it may come out */
		unsigned long long before = hash;
		lx_shadow_method_frame(m, f, &a, &o, &res);
		mix_result(&res, &a, f->object_count);
		if (verbose)
			printf("%s %s %016llx\n", label, specs[k], hash ^ before);
		++*count;
	}
	return true;
}

int main(int argc, char **argv)
{
	bool verbose = argc > 1 && !strcmp(argv[1], "-v");
	if (argc > 2 || (argc == 2 && !verbose)) {
		fprintf(stderr, "usage: setup-hash [-v]\n");
		return 2;
	}
	static const char *const scenes[] = {"default", "table", "spotlight", "projector", "twolights"};
	static const int sizes[][2] = {{1024, 1024}, {1920, 1080}, {320, 240}};
	long count = 0;
	for (size_t sc = 0; sc < sizeof scenes / sizeof scenes[0]; sc++)
		for (int c = -40; c < lx_config_count; c++) {
			struct lx_scene s;
			double t;
			struct lx_scene_meshes me;
			if (!scene_for(scenes[sc], c, (int)sc, &s, &t) || !lx_meshes_build(&s, &me)) {
				fprintf(stderr, "setup-hash: scene %s cannot be built\n", scenes[sc]);
				return 1;
			}
			for (int z = 0; z < 3; z++)
				for (int step = 0; step < (c == 0 ? 3 : 1); step++) {
					struct lx_frame f;
					char err[256], label[96];
					snprintf(label, sizeof label, "%s %d %dx%d %d", scenes[sc], c, sizes[z][0], sizes[z][1], step);
					if (!lx_frame_setup(&f, &s, &me, t + step * 0.37, sizes[z][0], sizes[z][1], err, sizeof err)) {
						mix(err, strlen(err)); /* a view with no frame: the same refusal */
						continue;
					}
					if (!hash_frame(&f, verbose, label, &count)) {
						lx_meshes_free(&me);
						return 1;
					}
				}
			lx_meshes_free(&me);
		}
	printf("%ld set-ups, hash %016llx\n", count, hash);
	return 0;
}
