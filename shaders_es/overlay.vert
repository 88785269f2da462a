#version 100
// The kiosk's overlay: text quads in window pixels (y down), a box behind them.
uniform vec2 u_window; // window size in pixels
attribute vec4 a_position; // x, y in pixels; u, v in the font texture (u < 0: the box)
varying vec2 v_uv;

void main()
{
	v_uv = a_position.zw;
	gl_Position = vec4(a_position.x / u_window.x * 2.0 - 1.0, 1.0 - a_position.y / u_window.y * 2.0, 0.0, 1.0);
}
