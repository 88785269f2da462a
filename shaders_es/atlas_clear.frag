#version 100
precision mediump float;
// The encoding of depth 1 (0xFFFFFF, see depth_rgba.glsl): every byte 255, as the
// atlas's clear colour.

void main()
{
	gl_FragColor = vec4(1.0);
}
