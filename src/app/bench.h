/* `lixel bench`: every method over the standard configurations, frame times and
 * accuracy against the exact reference, measured in one run so they compare as ratios. */
#ifndef LX_BENCH_H
#define LX_BENCH_H

/* argv after "bench"; returns the exit status. */
int lx_bench_main(int argc, char **argv);

#endif
