#version 100
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
#else
precision mediump float;
#endif
uniform sampler2D u_font; // one glyph cell per 6x8 texels, coverage in the red channel
varying vec2 v_uv;

void main()
{
	if (v_uv.x < 0.0)
		gl_FragColor = vec4(0.0, 0.0, 0.0, 0.65);
	else
		gl_FragColor = vec4(1.0, 1.0, 0.85, texture2D(u_font, v_uv).r);
}
