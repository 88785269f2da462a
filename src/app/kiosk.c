#include "commands.h"
#include "board.h"
#include "button.h"
#include "cli_args.h"
#include "gl_api.h"
#include "gpio_button.h"
#include "method_run.h"
#include "overlay.h"
#include "platform.h"
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <limits.h>
#include <time.h>

static volatile sig_atomic_t stop_requested;

static void on_signal(int sig)
{
	(void)sig;
	stop_requested = 1;
}

static int64_t now_ns(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}

static void usage(FILE *f)
{
	fprintf(f, "usage: lixel kiosk [--platform kms|x11] [--board NAME|FILE] [--frames N] [--size WxH]\n"
		   "                   [--device PATH] [--mode WxH[@HZ]] [--overlay]\n"
		   "                   [--scene NAME|FILE] [--methods LIST] [--gpio-chip NAME] [--gpio-line N]\n"
		   "                   [--gpio-active low|high] [--debounce-ms N] [--long-press-ms N]\n"
		   "                   [--depth-precision auto|highp|mediump]\n"
		   "\n"
		   "Shows the animated scene and switches the shadow method on a button press: a short\n"
		   "press goes to the next method of the board's order, a long press (1 s) toggles the\n"
		   "overlay. On a desktop (x11) the keyboard is the button: space a short press, l a\n"
		   "long press, q or Escape quits. Prints 'method: OLD -> NEW' on each change and a\n"
		   "status line every 5 seconds.\n"
		   "\n"
		   "  --platform NAME   kms (full screen on a board; the default) or x11 (a window; needs\n"
		   "                    DISPLAY; chosen by itself when KMS cannot be used and DISPLAY is set)\n"
		   "  --device PATH     the DRM device (default: the board's, else the first that can\n"
		   "                    mode-set)\n"
		   "  --mode WxH[@HZ]   the display mode (default: the board's, else the preferred one)\n"
		   "  --board NAME|FILE a board profile: %s (default desktop)\n"
		   "  --frames N        stop after N frames\n"
		   "  --size WxH        the window's size on x11 (default 1024x768)\n"
		   "  --methods LIST    the order the button cycles through (default: the board's)\n"
		   "  --overlay         start with the overlay on (method, FPS, the planes' sampling)\n"
		   "  --gpio-chip (a name, path or label), --gpio-line (an offset), --gpio-line-name\n"
		   "  (GPIO17: found on the named chip, or on any with --gpio-chip auto),\n"
		   "  --gpio-active, --debounce-ms, --long-press-ms,\n"
		   "  --plane-lixels, --fallback-lixels, --uniform-lixels, --depth-precision\n"
		   "                    override the board profile's values (depth-precision: auto, the\n"
		   "                    start-up self-test choosing, highp or mediump; --mediump is\n"
		   "                    --depth-precision mediump)\n"
		   "\n"
		   "On SIGINT, SIGTERM or SIGHUP it puts back the display mode it found and exits 0.\n"
		   "When its window is closed or destroyed, or another process takes the display (DRM\n"
		   "master), it says so in one line and exits 0; when the X server or the DRM device\n"
		   "goes away, one line and exit status 1.\n"
		   "Exit status: 0 stopped (q, a signal, N frames, the window closed, the display taken);\n"
		   "1 no display, or the display went away; 2 bad input.\n",
		lx_board_names());
}

static int bad(const char *opt, const char *expected, const char *got)
{
	return lx_arg_bad("kiosk", opt, expected, got);
}

int lx_kiosk_main(int argc, char **argv)
{
	const char *platform = NULL, *board_arg = "desktop", *scene_arg = NULL;
	const char *methods_arg = NULL;
	long frames = -1;
	bool overlay = false;
	int width = 1024, height = 768;
	struct lx_board board;
	char err[512];
	/* the board first: the other options override it */
	for (int i = 0; i + 1 < argc; i++)
		if (!strcmp(argv[i], "--board"))
			board_arg = argv[i + 1];
	if (!lx_board_load(board_arg, &board, err, sizeof err)) {
		fprintf(stderr, "lixel: %s\n", err);
		return 2;
	}
	for (int i = 0; i < argc; i++) {
		const char *a = argv[i];
		if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
			usage(stdout);
			return 0;
		}
		if (!strcmp(a, "--overlay")) {
			overlay = true;
			continue;
		}
		if (!strcmp(a, "--mediump")) {
			board.depth_precision = LX_DEPTH_MEDIUMP;
			continue;
		}
		static const char *const with_value[] = {"--platform", "--board", "--frames", "--size", "--scene", "--methods",
							 "--gpio-chip", "--gpio-line", "--gpio-line-name", "--gpio-active", "--debounce-ms",
							 "--long-press-ms", "--device", "--mode", "--plane-lixels",
							 "--fallback-lixels", "--uniform-lixels", "--depth-precision"};
		const char *v;
		int st = lx_arg_value("kiosk", argc, argv, &i, with_value, sizeof with_value / sizeof with_value[0], &v);
		if (st)
			return st;
		if (!strcmp(a, "--platform")) {
			if (strcmp(v, "x11") && strcmp(v, "kms"))
				return bad(a, "x11 or kms", v);
			platform = v;
		} else if (!strcmp(a, "--frames")) {
			enum lx_number_error e = lx_number_whole(v, 1, LONG_MAX, &frames);
			if (e)
				return lx_arg_bad_number("kiosk", a, "a whole number of frames >= 1", v, e);
		} else if (!strcmp(a, "--size")) {
			int hz;
			if (!lx_parse_mode(v, &width, &height, &hz) || hz)
				return bad(a, "WxH", v);
		} else if (!strcmp(a, "--scene"))
			scene_arg = v;
		else if (!strcmp(a, "--methods"))
			methods_arg = v;
		else if (!strcmp(a, "--device")) {
			if (strlen(v) >= sizeof board.display)
				return bad(a, "a device path", v);
			strcpy(board.display, v);
		} else if (!strcmp(a, "--mode")) {
			if (!strcmp(v, "preferred"))
				board.mode_w = board.mode_h = board.mode_hz = 0;
			else if (!lx_parse_mode(v, &board.mode_w, &board.mode_h, &board.mode_hz))
				return bad(a, "WxH or WxH@HZ", v);
		}
		else if (strcmp(a, "--board")) {
			/* a button override: parsed as a one-line profile, so a line break in the
			 * value would smuggle in another line */
			if (strpbrk(v, "\n\r"))
				return bad(a, "a value without line breaks", "(a value with a line break)");
			char line[256];
			snprintf(line, sizeof line, "%s %s\n", a + 2, v);
			if (!lx_board_apply(line, a, &board, err, sizeof err)) {
				fprintf(stderr, "lixel kiosk: %s\n", strchr(err, ' ') ? strchr(err, ' ') + 1 : err);
				return 2;
			}
		}
	}
	/* the overrides together: a --gpio-chip may come before its --gpio-line */
	if (!lx_board_check(&board, "--gpio-chip", 0, err, sizeof err)) {
		fprintf(stderr, "lixel kiosk: %s\n", strchr(err, ' ') ? strchr(err, ' ') + 1 : err);
		return 2;
	}
	if (methods_arg) {
		if (strpbrk(methods_arg, "\n\r"))
			return bad("--methods", "a value without line breaks", "(a value with a line break)");
		char line[256];
		snprintf(line, sizeof line, "methods %s\n", methods_arg);
		if (!lx_board_parse(line, "--methods", &board, err, sizeof err)) {
			fprintf(stderr, "lixel kiosk: %s\n", strchr(err, ' ') ? strchr(err, ' ') + 1 : err);
			return 2;
		}
	}
	struct lx_scene scene;
	if (!lx_arg_scene(scene_arg, &scene))
		return 2;
	/* KMS unless told otherwise; a desktop (DISPLAY set, no KMS device to use) gets x11 */
	const char *device = board.display[0] ? board.display : NULL;
	struct lx_platform *plat = lx_platform_create_display(platform ? platform : "kms", width, height, device,
							      board.mode_w, board.mode_h, board.mode_hz, err, sizeof err);
	if (!plat && !platform && getenv("DISPLAY")) {
		printf("lixel kiosk: %s; using x11 (DISPLAY is set)\n", err);
		plat = lx_platform_create_display("x11", width, height, NULL, 0, 0, 0, err, sizeof err);
	}
	if (!plat) {
		fprintf(stderr, "lixel kiosk: %s\n", err);
		return 1;
	}
	struct lx_gl_caps caps;
	lx_gl_caps_probe(&caps);
	struct lx_scene_meshes meshes;
	if (!lx_meshes_build(&scene, &meshes)) {
		fprintf(stderr, "lixel: out of memory\n");
		lx_platform_destroy(plat);
		return 1;
	}
	struct lx_method_run runs[LX_BOARD_MAX_METHODS];
	int ready = 0, status = 0;
	for (; ready < board.method_count; ready++) {
		status = lx_method_run_init(&runs[ready], board.methods[ready], &scene, &meshes, &caps, &board.lixels,
					    plat->width, plat->height, board.depth_precision, LX_DEFAULT_BIAS_CODES, true, err,
					    sizeof err);
		if (status) {
			fprintf(stderr, "lixel: %s\n", err);
			goto out;
		}
	}
	printf("lixel kiosk: GL_VENDOR %s, GL_RENDERER %s, GL_VERSION %s; %s %dx%d; fragment precision %s (%d bits); "
	       "depth %s, self-test %s; board %s\n",
	       caps.vendor, caps.renderer, caps.version, plat->name, plat->width, plat->height,
	       caps.fragment_highp ? "highp" : "mediump",
	       caps.fragment_highp ? caps.fragment_highp_bits : caps.fragment_mediump_bits, runs[0].depth.path,
	       runs[0].depth.selftest, board.name);
	if (runs[0].depth.warning[0])
		printf("lixel kiosk: warning: %s\n", runs[0].depth.warning);
	struct lx_gpio_button *gpio = NULL;
	if (board.gpio_chip[0]) {
		gpio = lx_gpio_button_open(&board, err, sizeof err);
		if (!gpio)
			printf("lixel kiosk: warning: %s; the keyboard still works\n", err);
	}
	int64_t start = now_ns();
	struct lx_button button;
	lx_button_init(&button, gpio && !lx_gpio_button_kernel_debounce() ? board.debounce_ms : 0, board.long_press_ms,
		       board.active_low, gpio ? lx_gpio_button_level(gpio) : !board.active_low, start);
	fflush(stdout);
	signal(SIGINT, on_signal);
	signal(SIGTERM, on_signal);
	signal(SIGHUP, on_signal); /* a closed terminal or session: the same clean stop */
	int current = 0;
	struct lx_overlay *ov = lx_overlay_create(err, sizeof err);
	if (!ov)
		printf("lixel kiosk: warning: no overlay: %s\n", err);
	char text[2 + LX_MAX_PLANES][96];
	const char *lines[2 + LX_MAX_PLANES];
	int nlines = 0;
	int64_t text_time = 0;
	double fps = 0;
	long frame = 0, window_frames = 0;
	int64_t window_start = start;
	while (!stop_requested && (frames < 0 || frame < frames)) {
		int64_t t = now_ns();
		struct lx_frame f;
		if (!lx_frame_setup(&f, &scene, &meshes, (t - start) / 1e9, plat->width, plat->height, err, sizeof err)) {
			fprintf(stderr, "lixel kiosk: %s\n", err);
			status = 2;
			break;
		}
		lx_method_run_draw(&runs[current], &f);
		if (overlay && ov) {
			/* the text once a second: the method, the frame rate, each plane's figures */
			if (t - text_time >= 1000000000LL || !nlines) {
				text_time = t;
				nlines = 0;
				snprintf(text[nlines++], sizeof text[0], "lixel  %s", board.methods[current]);
				snprintf(text[nlines++], sizeof text[0], "%.1f fps", fps);
				for (int p = 0; p < scene.plane_count && nlines < 2 + LX_MAX_PLANES; p++) {
					struct lx_plane_sampling ps;
					if (lx_plane_sampling_sparse(&f, &runs[current].atlas, &runs[current].result, p, 16, &ps))
						snprintf(text[nlines++], sizeof text[0], "%s  lpp %.2f  m %.2f  aniso %.2f",
							 scene.planes[p].name, ps.lpp_median, ps.m_max, ps.aniso_max);
				}
				for (int i = 0; i < nlines; i++)
					lines[i] = text[i];
				lx_overlay_set_text(ov, lines, nlines, plat->height >= 720 ? 3 : 2);
			}
			lx_overlay_draw(ov, plat->width, plat->height);
		}
		plat->swap(plat);
		frame++, window_frames++;
		/* input: keys, then the button's edges and the time that passed; every press
		 * counts, even several within one frame (a slow frame must not swallow one) */
		int shorts = 0, longs = 0;
		for (int key; (key = plat->poll_key(plat)) != 0;) {
			if (key == 'q' || key == 27)
				stop_requested = 1;
			else if (key == ' ')
				shorts++;
			else if (key == 'l')
				longs++;
		}
		if (gpio) {
			struct pollfd pfd = {.fd = lx_gpio_button_fd(gpio), .events = POLLIN};
			while (poll(&pfd, 1, 0) > 0) {
				struct lx_gpio_edge edges[64];
				int n = lx_gpio_button_read(gpio, edges, 64);
				if (n <= 0)
					break;
				for (int i = 0; i < n; i++) {
					enum lx_button_event e = lx_button_edge(&button, edges[i].high, edges[i].t_ns);
					shorts += e == LX_BUTTON_SHORT, longs += e == LX_BUTTON_LONG;
				}
			}
			enum lx_button_event e = lx_button_tick(&button, now_ns());
			shorts += e == LX_BUTTON_SHORT, longs += e == LX_BUTTON_LONG;
		}
		for (int k = 0; k < shorts && board.method_count > 1; k++) {
			int next = (current + 1) % board.method_count;
			printf("method: %s -> %s\n", board.methods[current], board.methods[next]);
			fflush(stdout);
			current = next;
		}
		for (int k = 0; k < longs; k++) {
			overlay = !overlay;
			nlines = 0; /* fresh text at once */
			printf("overlay: %s\n", overlay ? "on" : "off");
			fflush(stdout);
		}
		if (plat->state != LX_DISPLAY_OK) {
			/* the window closed or the display taken: a clean stop; the display gone: 1 */
			printf("lixel kiosk: %s; stopping\n", plat->why);
			fflush(stdout);
			status = plat->state == LX_DISPLAY_LOST;
			break;
		}
		int64_t now = now_ns();
		if (now - window_start >= 5000000000LL) {
			double secs = (now - window_start) / 1e9;
			fps = window_frames / secs;
			printf("%ld frames in %.1f s = %.1f FPS (%s)\n", window_frames, secs, fps, board.methods[current]);
			if (overlay)
				for (int i = 2; i < nlines; i++)
					printf("overlay: %s\n", lines[i]);
			fflush(stdout);
			window_start = now;
			window_frames = 0;
		}
	}
	double secs = (now_ns() - window_start) / 1e9;
	if (window_frames && secs > 0)
		printf("%ld frames in %.1f s = %.1f FPS (%s)\n", window_frames, secs, window_frames / secs,
		       board.methods[current]);
	lx_gpio_button_close(gpio);
	lx_overlay_destroy(ov);
out:
	for (int m = 0; m < ready; m++)
		lx_method_run_free(&runs[m]);
	lx_meshes_free(&meshes);
	lx_platform_destroy(plat);
	return status;
}
