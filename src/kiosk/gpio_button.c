#include "gpio_button.h"
#include "gpio_lookup.h"
#include <dirent.h>
#include <errno.h>
#include <gpiod.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static int64_t monotonic_ns(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}

/* Kernel event stamps are CLOCK_MONOTONIC since Linux 5.7, CLOCK_REALTIME before:
 * a stamp far from the monotonic clock is moved by the difference of the two. */
static int64_t to_monotonic(int64_t stamp)
{
	int64_t mono = monotonic_ns();
	if (llabs(stamp - mono) < 10LL * 1000000000)
		return stamp;
	struct timespec rt;
	clock_gettime(CLOCK_REALTIME, &rt);
	return stamp - ((int64_t)rt.tv_sec * 1000000000 + rt.tv_nsec - mono);
}


/* One chip's name, label and line names, read through either API (below). */
static bool chip_describe(const char *path, struct lx_gpio_chip_info *info, char (**names)[32]);

#define MAX_CHIPS 32

/* The board's chip and line as a path and an offset: directly when it gives a chip name
 * or path and an offset, else looked up among the machine's chips by label and line name. */
static bool resolve(const struct lx_board *b, char *path, size_t plen, unsigned *offset, char *err, size_t errlen)
{
	if (!b->gpio_line_name[0] && (b->gpio_chip[0] == '/' || !strncmp(b->gpio_chip, "gpiochip", 8))) {
		snprintf(path, plen, "%s%s", b->gpio_chip[0] == '/' ? "" : "/dev/", b->gpio_chip);
		*offset = (unsigned)b->gpio_line;
		return true;
	}
	struct lx_gpio_chip_info info[MAX_CHIPS];
	char(*names[MAX_CHIPS])[32];
	const char **ptrs[MAX_CHIPS];
	int n = 0;
	DIR *d = opendir("/dev");
	for (struct dirent *e; d && (e = readdir(d)) && n < MAX_CHIPS;) {
		if (strncmp(e->d_name, "gpiochip", 8))
			continue;
		char p[272];
		snprintf(p, sizeof p, "/dev/%s", e->d_name);
		names[n] = NULL, ptrs[n] = NULL;
		if (!chip_describe(p, &info[n], &names[n]))
			continue;
		ptrs[n] = calloc((size_t)(info[n].lines > 0 ? info[n].lines : 1), sizeof(char *));
		for (int k = 0; ptrs[n] && names[n] && k < info[n].lines; k++)
			ptrs[n][k] = names[n][k];
		info[n].line_names = ptrs[n];
		n++;
	}
	if (d)
		closedir(d);
	int idx = lx_gpio_find(b, info, n, offset, err, errlen);
	if (idx >= 0)
		snprintf(path, plen, "%s", info[idx].path);
	for (int i = 0; i < n; i++)
		free(names[i]), free(ptrs[i]);
	return idx >= 0;
}

/* The button: its chip and line, and the line as the API holds it (a v2 request and its
 * event buffer, or a v1 line). */
struct lx_gpio_button {
	struct gpiod_chip *chip;
	unsigned int offset;
#ifdef LX_GPIOD_V2
	struct gpiod_line_request *request;
	struct gpiod_edge_event_buffer *buffer;
#else
	struct gpiod_line *line;
#endif
};

/* What both APIs' open starts with: the board's line resolved to a chip's path and an
 * offset, and that chip opened by its path (both APIs open chips alike). NULL after err. */
static struct lx_gpio_button *open_prelude(const struct lx_board *board, char *path, size_t plen, char *err,
					   size_t errlen)
{
	unsigned offset;
	if (!resolve(board, path, plen, &offset, err, errlen))
		return NULL;
	struct lx_gpio_button *g = calloc(1, sizeof(*g));
	if (!g) {
		snprintf(err, errlen, "gpio: out of memory");
		return NULL;
	}
	g->offset = offset;
	errno = 0;
	g->chip = gpiod_chip_open(path);
	if (!g->chip) {
		snprintf(err, errlen, "gpio: cannot open chip %s: %s", path, errno ? strerror(errno) : "no such chip");
		free(g);
		return NULL;
	}
	return g;
}

#ifdef LX_GPIOD_V2

#define GPIO_KERNEL_DEBOUNCE true
#define GPIO_API "libgpiod 2 (v2 API, kernel debounce)"

/* The line asked for both edges, biased and debounced as the board says, with an event
 * buffer; false after err (what was got is left for release_line). */
static bool request_line(struct lx_gpio_button *g, const struct lx_board *board, const char *path, char *err,
			 size_t errlen)
{
	struct gpiod_line_settings *s = gpiod_line_settings_new();
	struct gpiod_line_config *lc = gpiod_line_config_new();
	struct gpiod_request_config *rc = gpiod_request_config_new();
	static const enum gpiod_line_bias bias[] = {GPIOD_LINE_BIAS_AS_IS, GPIOD_LINE_BIAS_PULL_UP,
						    GPIOD_LINE_BIAS_PULL_DOWN, GPIOD_LINE_BIAS_DISABLED};
	if (s && lc && rc) {
		gpiod_line_settings_set_direction(s, GPIOD_LINE_DIRECTION_INPUT);
		gpiod_line_settings_set_edge_detection(s, GPIOD_LINE_EDGE_BOTH);
		gpiod_line_settings_set_bias(s, bias[board->bias]);
		gpiod_line_settings_set_debounce_period_us(s, (unsigned long)board->debounce_ms * 1000);
		gpiod_request_config_set_consumer(rc, "lixel");
		if (gpiod_line_config_add_line_settings(lc, &g->offset, 1, s) == 0)
			g->request = gpiod_chip_request_lines(g->chip, rc, lc);
	}
	int saved = errno;
	gpiod_line_settings_free(s);
	gpiod_line_config_free(lc);
	gpiod_request_config_free(rc);
	g->buffer = gpiod_edge_event_buffer_new(64);
	if (!g->request || !g->buffer) {
		snprintf(err, errlen, "gpio: cannot request line %u on %s: %s", g->offset, path, strerror(saved));
		return false;
	}
	return true;
}

static void release_line(struct lx_gpio_button *g)
{
	if (g->buffer)
		gpiod_edge_event_buffer_free(g->buffer);
	if (g->request)
		gpiod_line_request_release(g->request);
}

static bool chip_describe(const char *path, struct lx_gpio_chip_info *info, char (**names)[32])
{
	struct gpiod_chip *chip = gpiod_chip_open(path);
	struct gpiod_chip_info *ci = chip ? gpiod_chip_get_info(chip) : NULL;
	if (!ci) {
		if (chip)
			gpiod_chip_close(chip);
		return false;
	}
	snprintf(info->path, sizeof info->path, "%s", path);
	snprintf(info->name, sizeof info->name, "%s", gpiod_chip_info_get_name(ci));
	snprintf(info->label, sizeof info->label, "%s", gpiod_chip_info_get_label(ci));
	info->lines = (int)gpiod_chip_info_get_num_lines(ci);
	gpiod_chip_info_free(ci);
	*names = calloc((size_t)(info->lines > 0 ? info->lines : 1), sizeof **names);
	for (int k = 0; *names && k < info->lines; k++) {
		struct gpiod_line_info *li = gpiod_chip_get_line_info(chip, (unsigned int)k);
		const char *nm = li ? gpiod_line_info_get_name(li) : NULL;
		snprintf((*names)[k], sizeof (*names)[k], "%s", nm ? nm : "");
		if (li)
			gpiod_line_info_free(li);
	}
	gpiod_chip_close(chip);
	return true;
}

int lx_gpio_button_fd(const struct lx_gpio_button *g) { return gpiod_line_request_get_fd(g->request); }

bool lx_gpio_button_level(struct lx_gpio_button *g)
{
	return gpiod_line_request_get_value(g->request, g->offset) == GPIOD_LINE_VALUE_ACTIVE;
}

int lx_gpio_button_read(struct lx_gpio_button *g, struct lx_gpio_edge *edges, int max)
{
	int n = gpiod_line_request_read_edge_events(g->request, g->buffer, (size_t)(max < 64 ? max : 64));
	for (int i = 0; i < n; i++) {
		struct gpiod_edge_event *e = gpiod_edge_event_buffer_get_event(g->buffer, (unsigned long)i);
		edges[i].high = gpiod_edge_event_get_event_type(e) == GPIOD_EDGE_EVENT_RISING_EDGE;
		edges[i].t_ns = to_monotonic((int64_t)gpiod_edge_event_get_timestamp_ns(e));
	}
	return n;
}

#else /* the v1 API */

#define GPIO_KERNEL_DEBOUNCE false
#define GPIO_API "libgpiod 1 (v1 API, software debounce)"

/* The line asked for both edges, biased as the board says (lixel debounces); false after
 * err, with no line held. */
static bool request_line(struct lx_gpio_button *g, const struct lx_board *board, const char *path, char *err,
			 size_t errlen)
{
	g->line = gpiod_chip_get_line(g->chip, g->offset);
	static const int bias[] = {0, GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP, GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN,
				   GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE};
	struct gpiod_line_request_config cfg = {.consumer = "lixel", .request_type = GPIOD_LINE_REQUEST_EVENT_BOTH_EDGES,
						.flags = bias[board->bias]};
	if (!g->line || gpiod_line_request(g->line, &cfg, 0) != 0) {
		snprintf(err, errlen, "gpio: cannot request line %u on %s: %s", g->offset, path, strerror(errno));
		g->line = NULL;
		return false;
	}
	return true;
}

static void release_line(struct lx_gpio_button *g)
{
	if (g->line)
		gpiod_line_release(g->line);
}

static bool chip_describe(const char *path, struct lx_gpio_chip_info *info, char (**names)[32])
{
	struct gpiod_chip *chip = gpiod_chip_open(path);
	if (!chip)
		return false;
	snprintf(info->path, sizeof info->path, "%s", path);
	snprintf(info->name, sizeof info->name, "%s", gpiod_chip_name(chip));
	snprintf(info->label, sizeof info->label, "%s", gpiod_chip_label(chip));
	info->lines = (int)gpiod_chip_num_lines(chip);
	*names = calloc((size_t)(info->lines > 0 ? info->lines : 1), sizeof **names);
	for (int k = 0; *names && k < info->lines; k++) {
		struct gpiod_line *l = gpiod_chip_get_line(chip, (unsigned int)k);
		const char *nm = l ? gpiod_line_name(l) : NULL;
		snprintf((*names)[k], sizeof (*names)[k], "%s", nm ? nm : "");
	}
	gpiod_chip_close(chip);
	return true;
}

int lx_gpio_button_fd(const struct lx_gpio_button *g) { return gpiod_line_event_get_fd(g->line); }

bool lx_gpio_button_level(struct lx_gpio_button *g) { return gpiod_line_get_value(g->line) == 1; }

int lx_gpio_button_read(struct lx_gpio_button *g, struct lx_gpio_edge *edges, int max)
{
	struct gpiod_line_event ev[64];
	int n = gpiod_line_event_read_multiple(g->line, ev, (unsigned int)(max < 64 ? max : 64));
	for (int i = 0; i < n; i++) {
		edges[i].high = ev[i].event_type == GPIOD_LINE_EVENT_RISING_EDGE;
		edges[i].t_ns = to_monotonic((int64_t)ev[i].ts.tv_sec * 1000000000 + ev[i].ts.tv_nsec);
	}
	return n;
}

#endif

bool lx_gpio_button_kernel_debounce(void) { return GPIO_KERNEL_DEBOUNCE; }
const char *lx_gpio_button_api(void) { return GPIO_API; }

struct lx_gpio_button *lx_gpio_button_open(const struct lx_board *board, char *err, size_t errlen)
{
	char path[272];
	struct lx_gpio_button *g = open_prelude(board, path, sizeof path, err, errlen);
	if (g && !request_line(g, board, path, err, errlen)) {
		lx_gpio_button_close(g);
		return NULL;
	}
	return g;
}

void lx_gpio_button_close(struct lx_gpio_button *g)
{
	if (!g)
		return;
	release_line(g);
	gpiod_chip_close(g->chip); /* open_prelude leaves no button without its chip */
	free(g);
}
