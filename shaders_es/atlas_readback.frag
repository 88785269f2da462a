#version 100
#if defined(GL_FRAGMENT_PRECISION_HIGH) && !defined(LX_FORCE_MEDIUMP)
precision highp float;
#else
precision mediump float;
#endif
// The depth-texture path's atlas read back (ES 2.0 reads no depth buffer): each texel's
// code as the main pass decodes it, written as the RGBA8 path writes codes, so that
// --atlas-out and the tests read both paths alike. Drawn over the whole atlas by
// atlas_clear.vert's quad.
#define LX_DEPTH_TEXTURE 1
//!include depth_rgba.glsl
#ifdef GL_FRAGMENT_PRECISION_HIGH
uniform highp sampler2D u_atlas; // a depth: samplers default to lowp, which may be fp16
#else
uniform sampler2D u_atlas;
#endif
uniform vec2 u_inverse_size; // 1 / the atlas's width and height

void main()
{
	gl_FragColor = lx_encode_code(lx_decode_code(texture2D(u_atlas, gl_FragCoord.xy * u_inverse_size)));
}
