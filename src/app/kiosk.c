#include "commands.h"
#include "board.h"
#include "button.h"
#include "cli_args.h"
#include "gl_api.h"
#include "gpio_button.h"
#include "method_run.h"
#include "out_file.h"
#include "overlay.h"
#include "png_out.h"
#include "platform.h"
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
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

static void sleep_until(int64_t t_ns)
{
	struct timespec ts = {.tv_sec = t_ns / 1000000000, .tv_nsec = t_ns % 1000000000};
	while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR && !stop_requested)
		;
}

static void usage(FILE *f)
{
	fprintf(f, "usage: lixel kiosk [--platform kms|x11] [--board NAME|FILE] [--frames N] [--max-fps N]\n"
		   "                   [--size WxH] [--device PATH] [--mode WxH[@HZ]] [--overlay]\n"
		   "                   [--scene NAME|FILE] [--snapshot FILE.png] [--methods LIST]\n"
		   "                   [--gpio-chip NAME] [--gpio-line N]\n"
		   "                   [--gpio-active low|high] [--debounce-ms N] [--long-press-ms N]\n"
		   "                   [--depth-precision auto|highp|mediump|texture] [--filters LIST]\n"
		   "\n"
		   "Shows the animated scene and switches the shadow method on a button press: a short\n"
		   "press goes to the next method of the board's order (or, on a board whose profile\n"
		   "lists filters, to the method's next filter first), a long press (1 s) toggles the\n"
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
		   "  --max-fps N       at most N frames a second (default: as fast as the display takes\n"
		   "                    them; where nothing paces it, as in a window under Xvfb)\n"
		   "  --snapshot FILE.png  with --frames N: frame N, read back before it is shown, as a PNG\n"
		   "  --scene NAME|FILE a built-in scene (default, table, spotlight, projector, twolights;\n"
		   "                    default default) or a scene file (docs/scene-format.md)\n"
		   "  --size WxH        the window's size on x11 (default 1024x768)\n"
		   "  --methods LIST    the order the button cycles through (default: the board's)\n"
		   "  --filters LIST    the shadow filters a press steps through within each method,\n"
		   "                    from none, pcf2x2 and pcf3x3 (default: the board's, else none;\n"
		   "                    the method is then shown as METHOD+FILTER)\n"
		   "  --overlay         start with the overlay on (method, FPS, the planes' sampling)\n"
		   "  --gpio-chip (a name, path or label), --gpio-line (an offset), --gpio-line-name\n"
		   "  (GPIO17: found on the named chip, or on any with --gpio-chip auto),\n"
		   "  --gpio-active, --debounce-ms, --long-press-ms,\n"
		   "  --plane-lixels, --fallback-lixels, --uniform-lixels, --light-budget (each light's\n"
		   "  share of those, e.g. 1,0.5), --depth-precision\n"
		   "                    override the board profile's values (depth-precision: auto, the\n"
		   "                    start-up self-test choosing, highp, mediump or texture; --mediump is\n"
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

#define bad(opt, expected, got) lx_arg_bad("kiosk", opt, expected, got)

/* What the command line asks for; the board profile with its overrides applied. */
struct kiosk_args {
	const char *platform, *scene_arg, *methods_arg, *filters_arg;
	const char *snapshot; /* with --frames: the last frame as a PNG, or NULL */
	long frames; /* -1: until stopped */
	int max_fps; /* 0: as fast as the display takes frames (a board's vsync paces it) */
	bool overlay;
	int width, height;
	struct lx_board board;
};

/* Prints err, a "FILE:LINE: ..." of a one-line profile, without its "FILE:LINE:" part. */
static int bad_override(const char *err)
{
	fprintf(stderr, "lixel kiosk: %s\n", strchr(err, ' ') ? strchr(err, ' ') + 1 : err);
	return 2;
}

/* One option and its value: 0 or 2 after the one line. */
static int kiosk_option(struct kiosk_args *k, const char *a, const char *v)
{
	struct lx_board *b = &k->board;
	if (!strcmp(a, "--platform")) {
		if (strcmp(v, "x11") && strcmp(v, "kms"))
			return bad(a, "x11 or kms", v);
		k->platform = v;
	} else if (!strcmp(a, "--frames")) {
		enum lx_number_error e = lx_number_whole(v, 1, LONG_MAX, &k->frames);
		if (e)
			return lx_arg_bad_number("kiosk", a, "a whole number of frames >= 1", v, e);
	} else if (!strcmp(a, "--max-fps")) {
		long n;
		enum lx_number_error e = lx_number_whole(v, 1, 1000, &n);
		if (e)
			return lx_arg_bad_number("kiosk", a, "a whole number of frames a second from 1 to 1000", v, e);
		k->max_fps = (int)n;
	} else if (!strcmp(a, "--size")) {
		int hz;
		if (!lx_parse_mode(v, &k->width, &k->height, &hz) || hz)
			return bad(a, "WxH", v);
	} else if (!strcmp(a, "--scene"))
		k->scene_arg = v;
	else if (!strcmp(a, "--snapshot")) {
		char err[4300];
		if (!lx_out_check(v, err, sizeof err)) {
			fprintf(stderr, "lixel kiosk: --snapshot: %s\n", err);
			return 2;
		}
		k->snapshot = v;
	}
	else if (!strcmp(a, "--methods"))
		k->methods_arg = v;
	else if (!strcmp(a, "--filters"))
		k->filters_arg = v;
	else if (!strcmp(a, "--device")) {
		if (strlen(v) >= sizeof b->display)
			return bad(a, "a device path", v);
		strcpy(b->display, v);
	} else if (!strcmp(a, "--mode")) {
		if (!strcmp(v, "preferred"))
			b->mode_w = b->mode_h = b->mode_hz = 0;
		else if (!lx_parse_mode(v, &b->mode_w, &b->mode_h, &b->mode_hz))
			return bad(a, "WxH or WxH@HZ", v);
	} else if (strcmp(a, "--board")) {
		/* a button override: parsed as a one-line profile, so a line break in the
		 * value would smuggle in another line */
		if (strpbrk(v, "\n\r"))
			return bad(a, "a value without line breaks", "(a value with a line break)");
		char line[256], err[512];
		snprintf(line, sizeof line, "%s %s\n", a + 2, v);
		if (!lx_board_apply(line, a, b, err, sizeof err))
			return bad_override(err);
	}
	return 0;
}

/* The board (named by --board, loaded first: the other options override it), then the
 * options in order, then the overrides checked together. 0, 2 after the one line, or -1
 * when --help was printed. */
static int kiosk_parse(int argc, char **argv, struct kiosk_args *k)
{
	*k = (struct kiosk_args){.frames = -1, .width = 1024, .height = 768};
	const char *board_arg = "desktop";
	char err[512];
	for (int i = 0; i + 1 < argc; i++)
		if (!strcmp(argv[i], "--board"))
			board_arg = argv[i + 1];
	if (!lx_board_load(board_arg, &k->board, err, sizeof err)) {
		fprintf(stderr, "lixel: %s\n", err);
		return 2;
	}
	static const char *const with_value[] = {"--platform", "--board", "--frames", "--max-fps", "--size", "--scene", "--snapshot", "--methods",
						 "--gpio-chip", "--gpio-line", "--gpio-line-name", "--gpio-active", "--debounce-ms",
						 "--long-press-ms", "--device", "--mode", "--plane-lixels",
						 "--fallback-lixels", "--uniform-lixels", "--light-budget", "--depth-precision",
						 "--filters"};
	for (int i = 0; i < argc; i++) {
		const char *a = argv[i], *v;
		if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
			usage(stdout);
			return -1;
		}
		if (!strcmp(a, "--overlay")) {
			k->overlay = true;
			continue;
		}
		if (!strcmp(a, "--mediump")) {
			k->board.depth_precision = LX_DEPTH_MEDIUMP;
			continue;
		}
		int st = lx_arg_value("kiosk", argc, argv, &i, with_value, sizeof with_value / sizeof with_value[0], &v);
		if (st || (st = kiosk_option(k, a, v)))
			return st;
	}
	/* the overrides together: a --gpio-chip may come before its --gpio-line */
	if (!lx_board_check(&k->board, "--gpio-chip", 0, err, sizeof err))
		return bad_override(err);
	/* the lists as one-line profiles, checked as the profile's are */
	const char *lists[2][2] = {{"--methods", k->methods_arg}, {"--filters", k->filters_arg}};
	for (int i = 0; i < 2; i++) {
		if (!lists[i][1])
			continue;
		if (strpbrk(lists[i][1], "\n\r"))
			return bad(lists[i][0], "a value without line breaks", "(a value with a line break)");
		char line[256];
		snprintf(line, sizeof line, "%s %s\n", lists[i][0] + 2, lists[i][1]);
		if (!lx_board_parse(line, lists[i][0], &k->board, err, sizeof err))
			return bad_override(err);
	}
	if (k->snapshot && k->frames < 0)
		return bad("--snapshot", "--frames N with it (the snapshot is frame N)", k->snapshot);
	return 0;
}

/* The overlay's lines at most: the method, the frame rate, and the planes' figures. */
#define KIOSK_LINES (2 + 2 * LX_MAX_PLANES)

/* The running kiosk: its display, scene, one set-up run per method, the button, the
 * overlay and the figures of the last status window. */
struct kiosk {
	struct kiosk_args *args;
	struct lx_platform *plat;
	struct lx_gl_caps caps;
	struct lx_scene scene;
	struct lx_scene_meshes meshes;
	struct lx_method_run runs[LX_BOARD_MAX_METHODS];
	int ready, current, filter; /* the method shown, and the board's filter it runs with */
	struct lx_gpio_button *gpio;
	struct lx_button button;
	struct lx_overlay *ov;
	char text[KIOSK_LINES][96];
	const char *lines[KIOSK_LINES];
	int nlines;
	int64_t start, text_time, window_start;
	double fps;
	long frame, window_frames;
};

/* The display: KMS unless told otherwise; a desktop (DISPLAY set, no KMS device to use)
 * gets x11. NULL after the one line. */
static struct lx_platform *kiosk_display(const struct kiosk_args *a)
{
	char err[512];
	const struct lx_board *b = &a->board;
	const char *device = b->display[0] ? b->display : NULL;
	struct lx_platform *plat = lx_platform_create_display(a->platform ? a->platform : "kms", a->width, a->height,
							      device, b->mode_w, b->mode_h, b->mode_hz, err, sizeof err);
	if (!plat && !a->platform && getenv("DISPLAY")) {
		printf("lixel kiosk: %s; using x11 (DISPLAY is set)\n", err);
		plat = lx_platform_create_display("x11", a->width, a->height, NULL, 0, 0, 0, err, sizeof err);
	}
	if (!plat)
		fprintf(stderr, "lixel kiosk: %s\n", err);
	return plat;
}

/* Each method set up with every filter of the board built (so that a shader error shows
 * at start) and every variant warmed (lx_renderer_warm), running with the first. 0, or the
 * status after the line. */
static int kiosk_run_filters(struct kiosk *k, struct lx_method_run *run)
{
	char err[512];
	const struct lx_board *b = &k->args->board;
	for (int f = b->filter_count - 1; f >= 0; f--)
		if (lx_method_run_set_filter(run, b->filters[f], err, sizeof err)) {
			fprintf(stderr, "lixel: %s\n", err);
			return 1;
		}
	lx_method_run_warm(run); /* every variant compiled now, not mid-show */
	return 0;
}

/* Every method set up to draw, then the banner line. 0, or the status after the line. */
static int kiosk_methods(struct kiosk *k)
{
	char err[512];
	const struct lx_board *b = &k->args->board;
	lx_gl_caps_probe(&k->caps);
	if (!lx_meshes_build(&k->scene, &k->meshes)) {
		fprintf(stderr, "lixel: out of memory\n");
		return 1;
	}
	for (; k->ready < b->method_count; k->ready++) {
		int status = lx_method_run_init(&k->runs[k->ready], b->methods[k->ready], &k->scene, &k->meshes, &k->caps,
						&b->lixels, k->plat->width, k->plat->height, b->depth_precision,
						LX_DEFAULT_BIAS_CODES, true, err, sizeof err);
		if (status) {
			fprintf(stderr, "lixel: %s\n", err);
			return status;
		}
		if ((status = kiosk_run_filters(k, &k->runs[k->ready]))) {
			k->ready++; /* set up: freed with the others */
			return status;
		}
	}
	const struct lx_gl_caps *c = &k->caps;
	char lights[64] = ""; /* "point", or "point, spot" */
	for (int i = 0; i < lx_scene_light_count(&k->scene); i++)
		snprintf(lights + strlen(lights), sizeof lights - strlen(lights), "%s%s", i ? ", " : "",
			 lx_light_kind_name(&k->scene.lights[i]));
	printf("lixel kiosk: GL_VENDOR %s, GL_RENDERER %s, GL_VERSION %s; %s %dx%d; fragment precision %s (%d bits); "
	       "depth %s, self-test %s; board %s; light%s %s\n",
	       c->vendor, c->renderer, c->version, k->plat->name, k->plat->width, k->plat->height,
	       c->fragment_highp ? "highp" : "mediump", c->fragment_highp ? c->fragment_highp_bits : c->fragment_mediump_bits,
	       k->runs[0].depth.path, k->runs[0].depth.selftest, b->name, lx_scene_light_count(&k->scene) > 1 ? "s" : "",
	       lights);
	if (k->runs[0].depth.warning[0])
		printf("lixel kiosk: warning: %s\n", k->runs[0].depth.warning);
	return 0;
}

/* The button (a GPIO line, or only the keyboard when there is none), the overlay, the
 * signals that stop the loop. */
static void kiosk_inputs(struct kiosk *k)
{
	char err[512];
	const struct lx_board *b = &k->args->board;
	if (b->gpio_chip[0]) {
		k->gpio = lx_gpio_button_open(b, err, sizeof err);
		if (!k->gpio)
			printf("lixel kiosk: warning: %s; the keyboard still works\n", err);
	}
	k->start = k->window_start = now_ns();
	lx_button_init(&k->button, k->gpio && !lx_gpio_button_kernel_debounce() ? b->debounce_ms : 0, b->long_press_ms,
		       b->active_low, k->gpio ? lx_gpio_button_level(k->gpio) : !b->active_low, k->start);
	signal(SIGINT, on_signal);
	signal(SIGTERM, on_signal);
	signal(SIGHUP, on_signal); /* a closed terminal or session: the same clean stop */
	/* A write to a display server that has died (X11's socket) must come back as an error, which
	 * the platform reports as a lost display, not end the kiosk silently with SIGPIPE. */
	signal(SIGPIPE, SIG_IGN);
	/* Only now the start line reaches a file or pipe: whoever waits for it (a supervisor, the
	 * tests) may stop the kiosk or kill its display from then on. */
	fflush(stdout);
	k->ov = lx_overlay_create(err, sizeof err);
	if (!k->ov)
		printf("lixel kiosk: warning: no overlay: %s\n", err);
}

/* What the kiosk shows as the method: its name, with +FILTER when it runs filtered (never
 * for none, which reads no map). */
static const char *shown(const struct kiosk *k, char *out, size_t len)
{
	const struct lx_board *b = &k->args->board;
	const char *m = b->methods[k->current];
	enum lx_filter f = strcmp(m, "none") ? b->filters[k->filter] : LX_FILTER_NONE;
	snprintf(out, len, "%s%s%s", m, f ? "+" : "", f ? lx_filter_name(f) : "");
	return out;
}

/* The overlay's text once a second (the method, the frame rate, each plane's figures),
 * drawn every frame. */
static void kiosk_overlay(struct kiosk *k, int64_t t)
{
	if (t - k->text_time >= 1000000000LL || !k->nlines) {
		const struct lx_method_run *run = &k->runs[k->current];
		k->text_time = t;
		k->nlines = 0;
		char name[40];
		snprintf(k->text[k->nlines++], sizeof k->text[0], "lixel  %s", shown(k, name, sizeof name));
		snprintf(k->text[k->nlines++], sizeof k->text[0], "%.1f fps", k->fps);
		/* each light's planes, as long as the lines last (lx_method_run keeps each light's frame) */
		for (int i = 0; i < run->light_count * k->scene.plane_count && k->nlines < KIOSK_LINES; i++) {
			const struct lx_light_maps *lm = &run->lights[i / k->scene.plane_count];
			int p = i % k->scene.plane_count;
			struct lx_plane_sampling ps;
			char name[LX_NAME_MAX + 8]; /* a copy: the text and the scene share *k */
			if (run->light_count > 1) /* "light2 floor": light 2's figures on the floor (the font has no capitals) */
				snprintf(name, sizeof name, "light%d %s", i / k->scene.plane_count + 1, k->scene.planes[p].name);
			else
				snprintf(name, sizeof name, "%s", k->scene.planes[p].name);
			if (lx_plane_sampling_sparse(&lm->frame, &lm->atlas, &lm->result, p, 16, &ps))
				snprintf(k->text[k->nlines++], sizeof k->text[0], "%s  lpp %.2f  m %.2f  aniso %.2f", name,
					 ps.lpp_median, ps.m_max, ps.aniso_max);
		}
		for (int i = 0; i < k->nlines; i++)
			k->lines[i] = k->text[i];
		lx_overlay_set_text(k->ov, k->lines, k->nlines, k->plat->height >= 720 ? 3 : 2);
	}
	lx_overlay_draw(k->ov, k->plat->width, k->plat->height);
}

/* Keys, then the button's edges and the time that passed: every press counts, even
 * several within one frame (a slow frame must not swallow one). */
static void kiosk_presses(struct kiosk *k, int *shorts, int *longs)
{
	for (int key; (key = k->plat->poll_key(k->plat)) != 0;) {
		if (key == 'q' || key == 27)
			stop_requested = 1;
		*shorts += key == ' ', *longs += key == 'l';
	}
	if (!k->gpio)
		return;
	struct pollfd pfd = {.fd = lx_gpio_button_fd(k->gpio), .events = POLLIN};
	while (poll(&pfd, 1, 0) > 0) {
		struct lx_gpio_edge edges[64];
		int n = lx_gpio_button_read(k->gpio, edges, 64);
		if (n <= 0)
			break;
		for (int i = 0; i < n; i++) {
			enum lx_button_event e = lx_button_edge(&k->button, edges[i].high, edges[i].t_ns);
			*shorts += e == LX_BUTTON_SHORT, *longs += e == LX_BUTTON_LONG;
		}
	}
	enum lx_button_event e = lx_button_tick(&k->button, now_ns());
	*shorts += e == LX_BUTTON_SHORT, *longs += e == LX_BUTTON_LONG;
}

/* The button's cycle one step on: the method's next filter, else the next method with
 * the board's first filter (none, which reads no map, is one step). */
static void kiosk_step(struct kiosk *k)
{
	const struct lx_board *b = &k->args->board;
	char err[512];
	if (strcmp(b->methods[k->current], "none") && k->filter + 1 < b->filter_count)
		k->filter++;
	else
		k->current = (k->current + 1) % b->method_count, k->filter = 0;
	if (lx_method_run_set_filter(&k->runs[k->current], b->filters[k->filter], err, sizeof err))
		printf("lixel kiosk: warning: %s\n", err); /* cannot happen: built at start */
}

/* A short press: the next method (or filter); a long one: the overlay on or off. */
static void kiosk_act(struct kiosk *k, int shorts, int longs)
{
	const struct lx_board *b = &k->args->board;
	int steps = 0; /* the cycle's length */
	for (int m = 0; m < b->method_count; m++)
		steps += strcmp(b->methods[m], "none") ? b->filter_count : 1;
	for (int i = 0; i < shorts && steps > 1; i++) {
		char from[40], to[40];
		shown(k, from, sizeof from);
		kiosk_step(k);
		printf("method: %s -> %s\n", from, shown(k, to, sizeof to));
		fflush(stdout);
	}
	for (int i = 0; i < longs; i++) {
		k->args->overlay = !k->args->overlay;
		k->nlines = 0; /* fresh text at once */
		printf("overlay: %s\n", k->args->overlay ? "on" : "off");
		fflush(stdout);
	}
}

/* The status line every 5 seconds (and the overlay's plane lines when it is on); at the
 * end (final) whatever the last window holds. */
static void kiosk_status(struct kiosk *k, bool final)
{
	int64_t now = now_ns();
	double secs = (now - k->window_start) / 1e9;
	char method[40];
	shown(k, method, sizeof method);
	if (final) {
		if (k->window_frames && secs > 0)
			printf("%ld frames in %.1f s = %.1f FPS (%s)\n", k->window_frames, secs, k->window_frames / secs, method);
		return;
	}
	if (now - k->window_start < 5000000000LL)
		return;
	k->fps = k->window_frames / secs; /* secs >= 5 */
	printf("%ld frames in %.1f s = %.1f FPS (%s)\n", k->window_frames, secs, k->fps, method);
	if (k->args->overlay)
		for (int i = 2; i < k->nlines; i++)
			printf("overlay: %s\n", k->lines[i]);
	fflush(stdout);
	k->window_start = now;
	k->window_frames = 0;
}

/* Frames until stopped: by a key or a signal, after N frames, or when the display goes
 * away. Returns the exit status. */
/* --snapshot: the frame just drawn, read back before it is shown. */
static bool kiosk_snapshot(struct kiosk *k)
{
	char err[4400];
	size_t bytes = (size_t)k->plat->width * k->plat->height * 4;
	uint8_t *rgba = malloc(bytes);
	if (!rgba) {
		fprintf(stderr, "lixel kiosk: --snapshot: out of memory for a %dx%d image\n", k->plat->width, k->plat->height);
		return false;
	}
	lx_renderer_read(k->runs[k->current].renderer, rgba);
	bool ok = lx_png_write(k->args->snapshot, rgba, k->plat->width, k->plat->height, err, sizeof err);
	if (!ok)
		fprintf(stderr, "lixel kiosk: --snapshot: %s\n", err);
	free(rgba);
	return ok;
}

/* The frame shown at time t (ns), or false after a line on stderr. */
static bool kiosk_frame_at(const struct kiosk *k, int64_t t, struct lx_frame *f)
{
	char err[512];
	if (lx_frame_setup(f, &k->scene, &k->meshes, (t - k->start) / 1e9, k->plat->width, k->plat->height, err,
			   sizeof err))
		return true;
	fprintf(stderr, "lixel kiosk: %s\n", err);
	return false;
}

/* Each frame drawn for the time the one before foretold (when it began, plus the time
 * the one before that took), so that its light matrices are made while the GL draws
 * the frame before (lx_method_run_draw's `next`); the first one for now. */
static int kiosk_loop(struct kiosk *k)
{
	struct lx_frame frames[2], *f = &frames[0], *next = &frames[1];
	int64_t began = now_ns(), step = 1000000000 / 60; /* until a frame has been timed */
	int status = kiosk_frame_at(k, began, f) ? 0 : 2;
	while (!status && !stop_requested && (k->args->frames < 0 || k->frame < k->args->frames)) {
		int64_t t = now_ns();
		if (k->frame > 0) /* the last frame's time, within 1-100 ms (a stall foretells nothing) */
			step = t - began < 1000000 ? 1000000 : t - began > 100000000 ? 100000000 : t - began;
		began = t;
		bool more = k->args->frames < 0 || k->frame + 1 < k->args->frames;
		if (more && !kiosk_frame_at(k, t + step, next)) {
			status = 2;
			break;
		}
		lx_method_run_draw(&k->runs[k->current], f, more ? next : NULL);
		struct lx_frame *drawn = f;
		f = next, next = drawn; /* the next frame's bytes, as the run set them up */
		if (k->args->overlay && k->ov)
			kiosk_overlay(k, t);
		if (k->args->snapshot && k->frame + 1 == k->args->frames && !kiosk_snapshot(k)) {
			status = 1; /* the path was checked at start: a write that fails now is the system's */
			break;
		}
		k->plat->swap(k->plat);
		if (k->args->max_fps) /* no vsync (a window under Xvfb): keep the CPU for others */
			sleep_until(t + 1000000000 / k->args->max_fps);
		k->frame++, k->window_frames++;
		int shorts = 0, longs = 0;
		kiosk_presses(k, &shorts, &longs);
		kiosk_act(k, shorts, longs);
		if (k->plat->state != LX_DISPLAY_OK) {
			/* the window closed or the display taken: a clean stop; the display gone: 1 */
			printf("lixel kiosk: %s; stopping\n", k->plat->why);
			fflush(stdout);
			status = k->plat->state == LX_DISPLAY_LOST;
			break;
		}
		kiosk_status(k, false);
	}
	kiosk_status(k, true);
	return status;
}

int lx_kiosk_main(int argc, char **argv)
{
	struct kiosk_args args;
	int status = kiosk_parse(argc, argv, &args);
	if (status)
		return status < 0 ? 0 : status;
	static struct kiosk k; /* large (the runs and their atlases): not on the stack */
	memset(&k, 0, sizeof k);
	k.args = &args;
	if (!lx_arg_scene(args.scene_arg, &k.scene))
		return 2;
	if (!(k.plat = kiosk_display(&args)))
		return 1;
	if (!(status = kiosk_methods(&k))) {
		kiosk_inputs(&k);
		status = kiosk_loop(&k);
		lx_gpio_button_close(k.gpio);
		lx_overlay_destroy(k.ov);
	}
	for (int m = 0; m < k.ready; m++)
		lx_method_run_free(&k.runs[m]);
	lx_meshes_free(&k.meshes);
	lx_platform_destroy(k.plat);
	return status;
}
