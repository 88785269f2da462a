#version 100
#if defined(GL_FRAGMENT_PRECISION_HIGH) && !defined(LX_FORCE_MEDIUMP)
precision highp float;
#else
precision mediump float;
#endif
// Writes the light depth of the fragment, encoded in RGBA8, and in the alpha byte which
// object drew it (u_caster: (id + 0.25) / 255), so that a convex caster's lit faces can
// pass over their own texels (main.frag, LX_SELF); on the depth-texture path
// (LX_DEPTH_TEXTURE) the rasterizer's depth is the map and there is no colour to write.
//!include depth_rgba.glsl
varying vec2 v_zw;
#ifndef LX_DEPTH_TEXTURE
uniform float u_caster;
#endif

void main()
{
#ifdef LX_DEPTH_TEXTURE
	gl_FragColor = vec4(1.0); // no colour attachment: nothing of it is kept
#else
	// w > 0 for every fragment that survived clipping
	gl_FragColor = vec4(lx_encode_depth(v_zw.x / v_zw.y * 0.5 + 0.5).rgb, u_caster);
#endif
}
