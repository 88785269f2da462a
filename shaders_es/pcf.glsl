// Percentage-closer filtering [Reeves] by hand on the RGBA8 depth (--filter; the
// reasoning and the CPU side: src/shadow/shadow_filter.h). Included by main.frag when LX_FILTER is 1
// (pcf2x2) or 2 (pcf3x3), after u_atlas and u_bias and the depth codes.
uniform vec4 u_clamp[LX_READS]; // per map read: the texel centres at its atlas region's edges (x0, y0, x1, y1)
uniform vec4 u_texel;          // the atlas's size in texels (w, h) and one texel (1 / w, 1 / h)

// 1.0 where the texel at atlas point t, clamped into the map's region, holds a depth
// nearer the light than code d by more than the bias (one NEAREST compare), and with
// LX_SELF another object's (main.frag), else 0.0
float lx_closer(vec2 t, vec4 box, float d)
{
	vec4 texel = texture2D(u_atlas, clamp(t, box.xy, box.zw));
#ifdef LX_SELF
	return float(d > lx_decode_code(texel) + u_bias) * lx_other(texel);
#else
	return float(d > lx_decode_code(texel) + u_bias);
#endif
}

#if LX_FILTER == 1
// pcf2x2: the four texels around p, weighted bilinearly by p's place between their centres
float lx_filtered_shadow(vec3 p, vec4 box)
{
	float d = lx_depth_code(p.z);
	vec2 x = p.xy * u_texel.xy - 0.5; // texel centres at whole numbers
	vec2 k = floor(x), f = x - k;
	vec2 t = (k + 0.5) * u_texel.zw, dx = vec2(u_texel.z, 0.0), dy = vec2(0.0, u_texel.w);
	float bottom = mix(lx_closer(t, box, d), lx_closer(t + dx, box, d), f.x);
	float top = mix(lx_closer(t + dy, box, d), lx_closer(t + dx + dy, box, d), f.x);
	return mix(bottom, top, f.y);
}
#else
// pcf3x3: the texel p falls in and its eight neighbours, weighted by a box two texels wide
// centred on p: per axis (1 - g, 1, g) / 2, g the place of p within its texel
float lx_row3(vec2 t, vec4 box, float d, vec3 w)
{
	vec2 dx = vec2(u_texel.z, 0.0);
	return w.x * lx_closer(t - dx, box, d) + w.y * lx_closer(t, box, d) + w.z * lx_closer(t + dx, box, d);
}

float lx_filtered_shadow(vec3 p, vec4 box)
{
	float d = lx_depth_code(p.z);
	vec2 x = p.xy * u_texel.xy; // texel edges at whole numbers
	vec2 k = floor(x), g = x - k;
	vec2 t = (k + 0.5) * u_texel.zw, dy = vec2(0.0, u_texel.w);
	vec3 wx = vec3(1.0 - g.x, 1.0, g.x) * 0.5, wy = vec3(1.0 - g.y, 1.0, g.y) * 0.5;
	return wy.x * lx_row3(t - dy, box, d, wx) + wy.y * lx_row3(t, box, d, wx) + wy.z * lx_row3(t + dy, box, d, wx);
}
#endif
