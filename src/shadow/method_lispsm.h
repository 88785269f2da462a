/* Light space perspective shadow maps ([LiSPSM]):
 * the parts the tests reach directly. */
#ifndef LX_METHOD_LISPSM_H
#define LX_METHOD_LISPSM_H

/* Below this sin(gamma) (view nearly parallel to the light) the warp is off: uniform. */
#define LX_LISPSM_MIN_SIN_GAMMA 0.02

/* The free parameter: n = (z_n + sqrt(z_n (z_n + d sin g))) / sin g, with z_n the view's
 * near distance, d the body's extent along the warp axis (a flat body, d = 0, is fine)
 * and sin g > 0. For sin g = 1 this is n_opt = z_n + sqrt(z_n z_f), z_f = z_n + d. */
double lx_lispsm_n(double z_n, double d, double sin_gamma);
/* The warp along its axis: y in [n, n + d] (distance from the projection centre) to
 * [-1, 1]. d is kept above a tiny floor so a flat body divides by nothing. */
double lx_lispsm_warp(double y, double n, double d);

#endif
