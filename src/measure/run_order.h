/* The order in which lixel bench times its runs, round after round: a fresh order each
 * round (no run always first, none always after the same one), drawn from a fixed
 * sequence so that runs repeat, and over the runs sorted by name, so that the order
 * they were listed in changes nothing of what is measured. GL-free. */
#ifndef LX_RUN_ORDER_H
#define LX_RUN_ORDER_H

#define LX_RUN_ORDER_MAX 64

/* A sequence's state at its start (each configuration's rounds begin here). */
#define LX_RUN_ORDER_SEED 0x6c697865ull

/* order[0, n): the indices of the runs named names[0, n) (n <= LX_RUN_ORDER_MAX), in the
 * order of this round of *seq, which steps on. The same names in any listed order give
 * the same sequence of names. */
void lx_run_order(const char *const *names, int n, unsigned long long *seq, int *order);

#endif
