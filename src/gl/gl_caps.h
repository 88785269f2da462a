/* What the current GL context can do, probed once (after raylib's rlgl). */
#ifndef LX_GL_CAPS_H
#define LX_GL_CAPS_H
#include <stdbool.h>

struct lx_gl_caps {
	char vendor[128], renderer[128], version[128];
	int max_texture_size, max_renderbuffer_size, max_viewport[2];
	bool depth24;                /* GL_OES_depth24: 24-bit depth renderbuffers */
	bool depth_texture;          /* GL_OES_depth_texture (not used: RGBA8 is the portable path) */
	bool fragment_highp;         /* highp floats exist in fragment shaders */
	int fragment_highp_bits;     /* their mantissa precision, 0 when absent */
	int fragment_mediump_bits;
	/* A tile-based GPU (Mali, VideoCore, Vivante, Adreno, PowerVR, by GL_RENDERER): a
	 * render target is cheapest cleared whole, once per pass, which also spares loading
	 * its tiles from memory; llvmpipe and desktop GPUs clear per region. */
	bool tiler;
	/* GL_MAX_VARYING_VECTORS (a VideoCore IV has 8): main.vert's outputs must fit
	 * (lx_main_varyings). LIXEL_MAX_VARYINGS=N in the environment lowers it, so that the
	 * tests run a small GPU's variants. */
	int max_varying_vectors;
};

void lx_gl_caps_probe(struct lx_gl_caps *caps);

#endif
