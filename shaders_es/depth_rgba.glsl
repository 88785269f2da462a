// RGBA8 depth encoding (the CPU mirror and its reasoning: src/depth_rgba.h).
// Depth d in [0, 1] becomes a 24-bit integer code n split into bytes R, G, B.
// Each byte b is written as (b + 0.25) / 255 so that a driver which rounds and one
// which truncates both store b. 1.0 encodes as 0xFFFFFF, the clear colour: no wrap.
#if defined(GL_FRAGMENT_PRECISION_HIGH) && !defined(LX_FORCE_MEDIUMP)
// highp: every step below is exact in single precision (integers below 2^24).
float lx_depth_code(float d)
{
	return min(floor(clamp(d, 0.0, 1.0) * 16777215.0), 16777215.0);
}

vec4 lx_encode_code(float n)
{
	float hi = floor(n / 65536.0);
	float rem = n - hi * 65536.0;
	float mid = floor(rem / 256.0);
	float lo = rem - mid * 256.0;
	return vec4((vec3(hi, mid, lo) + 0.25) / 255.0, 1.0);
}

vec4 lx_encode_depth(float d)
{
	return lx_encode_code(lx_depth_code(d));
}

#ifdef LX_DEPTH_TEXTURE
// The maps in a depth texture (GL_OES_depth_texture): the rasterizer's depth d in R, the
// code its nearest 24-bit step (within a step or two: d comes as a float, and near 1 the
// steps are as fine as its mantissa), far (1.0) kept at the last code. The self-test checks
// that the compare keeps the codes.
float lx_decode_code(vec4 texel)
{
	return min(floor(texel.r * 16777215.0 + 0.5), 16777215.0);
}
#else
float lx_decode_code(vec4 texel)
{
	vec3 b = floor(texel.rgb * 255.0 + 0.5);
	return dot(b, vec3(65536.0, 256.0, 1.0));
}
#endif
#else
// mediump (fp16, 11-bit mantissa): 2^24 is out of reach, so keep 11 bits,
// q = floor(d * 2047), stored in the same layout (n = q * 8192) and compared as q.
float lx_depth_code(float d)
{
	return min(floor(clamp(d, 0.0, 1.0) * 2047.0), 2047.0);
}

vec4 lx_encode_code(float q)
{
	float hi = floor(q / 8.0);
	float mid = (q - hi * 8.0) * 32.0;
	return vec4((vec3(hi, mid, 255.0) + 0.25) / 255.0, 1.0);
}

vec4 lx_encode_depth(float d)
{
	return lx_encode_code(lx_depth_code(d));
}

float lx_decode_code(vec4 texel)
{
	vec2 b = floor(texel.rg * 255.0 + 0.5);
	return b.x * 8.0 + floor(b.y / 32.0);
}
#endif
