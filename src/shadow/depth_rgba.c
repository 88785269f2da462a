#include "depth_rgba.h"
#include <math.h>

uint32_t lx_depth_code(double d)
{
	float f = (float)d;
	if (!(f >= 0.0f)) /* negative or NaN: NaN means no valid depth, treat as far */
		return isnan(f) ? LX_DEPTH_MAX_CODE : 0u;
	if (f >= 1.0f)
		return LX_DEPTH_MAX_CODE;
	float n = floorf(f * 16777215.0f);
	if (n > 16777215.0f)
		n = 16777215.0f;
	return (uint32_t)n;
}

static uint8_t to_unorm8(float value, enum lx_unorm_conversion conv)
{
	float x = fminf(fmaxf(value, 0.0f), 1.0f) * 255.0f;
	return (uint8_t)(conv == LX_UNORM_ROUND ? floorf(x + 0.5f) : floorf(x));
}

void lx_depth_encode_rgba8(double d, enum lx_unorm_conversion conv, uint8_t out[4])
{
	float n = (float)lx_depth_code(d);
	float hi = floorf(n / 65536.0f);
	float rem = n - hi * 65536.0f;
	float mid = floorf(rem / 256.0f);
	float lo = rem - mid * 256.0f;
	out[0] = to_unorm8((hi + 0.25f) / 255.0f, conv);
	out[1] = to_unorm8((mid + 0.25f) / 255.0f, conv);
	out[2] = to_unorm8((lo + 0.25f) / 255.0f, conv);
	out[3] = to_unorm8(1.0f, conv);
}

uint32_t lx_depth_decode_code(const uint8_t in[4])
{
	return ((uint32_t)in[0] << 16) | ((uint32_t)in[1] << 8) | in[2];
}

double lx_depth_decode_rgba8(const uint8_t in[4])
{
	return lx_depth_decode_code(in) / (double)LX_DEPTH_MAX_CODE;
}

float lx_fp16(float x)
{
	if (x == 0.0f || !isfinite(x))
		return x;
	int e;
	float m = frexpf(x, &e); /* x = m * 2^e, 0.5 <= |m| < 1 */
	if (e < -13)             /* below fp16's normal range: denormals keep fixed steps of 2^-24 */
		return ldexpf(rintf(ldexpf(x, 24)), -24);
	/* rintf rounds to nearest, ties to even (the default mode); past fp16's largest
	 * finite value, 65504, a rounded result is infinite */
	float r = ldexpf(rintf(ldexpf(m, 11)), e - 11);
	return fabsf(r) > 65504.0f ? copysignf(INFINITY, r) : r;
}

float lx_fp16_div(float a, float b) { return lx_fp16(lx_fp16(a) / lx_fp16(b)); }

float lx_fp16_rcp_mul(float a, float b) { return lx_fp16(lx_fp16(a) * lx_fp16(1.0f / lx_fp16(b))); }

/* The 11-bit code of an fp16 depth, as the mediump shader path clamps and scales it. */
static uint32_t code11(float d)
{
	if (!(d >= 0.0f))
		return isnan(d) ? 2047u : 0u;
	if (d >= 1.0f)
		return 2047u;
	float q = floorf(lx_fp16(d * 2047.0f));
	return q > 2047.0f ? 2047u : (uint32_t)q;
}

uint32_t lx_depth_code_fp16_projected(float z, float w, bool rcp)
{
	return code11(rcp ? lx_fp16_rcp_mul(z, w) : lx_fp16_div(z, w));
}

uint32_t lx_depth_code_fp16(double d) { return code11(lx_fp16((float)d)); }

void lx_depth_encode_rgba8_fp16(double d, enum lx_unorm_conversion conv, uint8_t out[4])
{
	float q = (float)lx_depth_code_fp16(d);
	float hi = floorf(lx_fp16(q / 8.0f));
	float mid = lx_fp16(lx_fp16(q - lx_fp16(hi * 8.0f)) * 32.0f);
	out[0] = to_unorm8(lx_fp16(lx_fp16(hi + 0.25f) / 255.0f), conv);
	out[1] = to_unorm8(lx_fp16(lx_fp16(mid + 0.25f) / 255.0f), conv);
	out[2] = to_unorm8(lx_fp16(255.25f / 255.0f), conv);
	out[3] = to_unorm8(1.0f, conv);
}

uint32_t lx_depth_decode_code_fp16(const uint8_t in[4]) { return (uint32_t)in[0] * 8u + in[1] / 32u; }
