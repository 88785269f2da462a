/* The commands main() dispatches to: each takes argv after its name and returns the
 * exit status (0 done, 1 a GL or platform failure, 2 bad input). */
#ifndef LX_COMMANDS_H
#define LX_COMMANDS_H
int lx_render_main(int argc, char **argv);
int lx_bench_main(int argc, char **argv);
int lx_kiosk_main(int argc, char **argv);
#endif
