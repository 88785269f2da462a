/* lixel: the command line. main only dispatches: render (render_cmd.c), bench (bench.c)
 * and kiosk (kiosk.c). */
#include "commands.h"
#include <stdio.h>
#include <string.h>

#define LIXEL_VERSION "0.1.0"

static void usage(FILE *f)
{
	fprintf(f, "usage: lixel COMMAND [OPTIONS]\n"
		   "\n"
		   "An OpenGL ES 2.0 shadow renderer for fill-rate-limited boards, measuring its\n"
		   "shadows against an exact ray-cast reference.\n"
		   "\n"
		   "commands:\n"
		   "  render     render one frame to a PNG and print its figures\n"
		   "  bench      every method over the standard configurations: time and accuracy\n"
		   "  kiosk      the animated scene with a button (or keys) switching the method\n"
		   "\n"
		   "  lixel render --help    options of render\n"
		   "  lixel bench --help     options of bench\n"
		   "  lixel --version        the version\n");
}

int main(int argc, char **argv)
{
	if (argc < 2) {
		fprintf(stderr, "lixel: expected a command (render or bench); see lixel --help\n");
		return 2;
	}
	if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help") || !strcmp(argv[1], "help")) {
		usage(stdout);
		return 0;
	}
	if (!strcmp(argv[1], "--version")) {
		printf("lixel %s\n", LIXEL_VERSION);
		return 0;
	}
	if (!strcmp(argv[1], "render"))
		return lx_render_main(argc - 2, argv + 2);
	if (!strcmp(argv[1], "bench"))
		return lx_bench_main(argc - 2, argv + 2);
	if (!strcmp(argv[1], "kiosk"))
		return lx_kiosk_main(argc - 2, argv + 2);
	fprintf(stderr, "lixel: unknown command '%s', expected render or bench (see lixel --help)\n", argv[1]);
	return 2;
}
