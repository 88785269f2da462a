#version 100
#if defined(GL_FRAGMENT_PRECISION_HIGH) && !defined(LX_FORCE_MEDIUMP)
precision highp float;
#else
precision mediump float;
#endif
// Writes the light depth of the fragment, encoded in RGBA8.
//!include depth_rgba.glsl
varying vec2 v_zw;

void main()
{
	// w > 0 for every fragment that survived clipping
	gl_FragColor = lx_encode_depth(v_zw.x / v_zw.y * 0.5 + 0.5);
}
