# lixel: an OpenGL ES 2.0 shadow renderer for fill-rate-limited boards.
#   make          build build/lixel
#   make run      render the default scene to out/default.png (installs Debian packages first)
#   make check    build and run every test (installs Debian packages first)
#   make soak     the kiosk for 10 minutes under Xvfb, keys every 50 ms, its memory watched
#                 (SOAK_SECONDS=N to shorten; not part of make check)
#   make fuzz     build the libFuzzer harnesses (fuzz/) and run each FUZZ_SECONDS seconds
#   make install  PREFIX=/usr/local DESTDIR=

PREFIX ?= /usr/local
DESTDIR ?=
BINDIR = $(PREFIX)/bin
MANDIR = $(PREFIX)/share/man/man1
DATADIR = $(PREFIX)/share/lixel
UNITDIR ?= $(PREFIX)/lib/systemd/system
UDEVDIR ?= $(PREFIX)/lib/udev/rules.d
CC ?= cc
PKG_CONFIG ?= pkg-config
BUILD ?= build

# GL entry points are loaded at run time (src/gl/gl_api.h); glesv2 gives only headers.
GL_PKGS = osmesa egl glesv2 libpng x11 libdrm gbm
# -g1: line tables (backtraces, sanitizer reports, breakpoints by line) at a sixth less
# build time than -g's full debug information, which `make CFLAGS="-O0 -g"` gives;
# -pipe: no temporary files between the compiler's stages (a tenth less)
CFLAGS ?= -O2 -g1 -pipe
WARN = -Wall -Wextra
# -MMD -MP: each object's header dependencies, written beside it (BUILD/*.d)
DEPFLAGS = -MMD -MP
# pkg_once(VAR,ARGS): pkg-config ARGS, asked when VAR is first used (after deps-check has
# installed what is missing) and kept, not asked again for every command that uses it
pkg_once = $(eval $(1) := $$(shell $(PKG_CONFIG) $(2) 2>/dev/null))$($(1))
PKG_GL_CFLAGS = $(call pkg_once,PKG_GL_CFLAGS,--cflags $(GL_PKGS))
# libOSMesa is opened at run time (platform_osmesa.c): only its headers come from pkg-config
PKG_GL_LIBS = $(call pkg_once,PKG_GL_LIBS,--libs egl libpng x11 libdrm gbm)
PKG_PNG_LIBS = $(call pkg_once,PKG_PNG_LIBS,--libs libpng)
PKG_X11_LIBS = $(call pkg_once,PKG_X11_LIBS,--libs x11)
PKG_CMOCKA_CFLAGS = $(call pkg_once,PKG_CMOCKA_CFLAGS,--cflags cmocka)
PKG_CMOCKA_LIBS = $(call pkg_once,PKG_CMOCKA_LIBS,--libs cmocka)
PKG_GPIOD_CFLAGS = $(call pkg_once,PKG_GPIOD_CFLAGS,--cflags libgpiod)
PKG_GPIOD_LIBS = $(call pkg_once,PKG_GPIOD_LIBS,--libs libgpiod)
PKG_GPIOD_V2 = $(call pkg_once,PKG_GPIOD_V2,--atleast-version=2 libgpiod && echo -DLX_GPIOD_V2)
CPPFLAGS_ALL = -std=c11 -D_DEFAULT_SOURCE -Isrc -I$(BUILD) $(PKG_GL_CFLAGS)
LIBS_GL = $(PKG_GL_LIBS) -ldl -lpthread -lm
# libgpiod: the v2 API from 2.0 on (Debian 13, Raspberry Pi OS), the v1 API before
GPIOD_CFLAGS = $(PKG_GPIOD_CFLAGS) $(PKG_GPIOD_V2)
LIBS_GPIOD = $(PKG_GPIOD_LIBS)

# The layers, lowest first; a file includes headers of its own layer and of the layers
# LAYERS_<name> lists (tools/check-layers.sh checks it; docs/lixel.md has the table).
LAYERS = base geom scene shadow measure gl platform kiosk app
SRC_DIRS = $(LAYERS:%=src/%)
vpath %.c $(SRC_DIRS)
vpath %.h $(SRC_DIRS)
CPPFLAGS_ALL += $(SRC_DIRS:%=-I%)

# GL-free: no file here includes a GL, EGL, X11 or DRM header, directly or through
# another header (tools/check-layers.sh); built into BUILD/liblixel-core.a, which the
# unit tests link alone.
CORE_SRC = $(wildcard src/base/*.c src/geom/*.c src/scene/*.c src/shadow/*.c src/measure/*.c) \
	src/gl/shader_text.c src/platform/display_loss.c src/platform/kms_select.c \
	src/kiosk/board.c src/kiosk/button.c src/kiosk/gpio_lookup.c src/app/cli_args.c
CORE_SRC := $(sort $(CORE_SRC))
# The GL side, the platforms and the commands.
GL_SRC = $(filter-out src/gl/shader_text.c,$(wildcard src/gl/*.c)) \
	$(filter-out src/platform/display_loss.c src/platform/kms_select.c,$(wildcard src/platform/*.c)) \
	$(filter-out src/app/cli_args.c src/app/main.c,$(wildcard src/app/*.c))
SHADERS = $(sort $(wildcard shaders_es/*.vert shaders_es/*.frag shaders_es/*.glsl))
BOARDS = $(sort $(wildcard board/*.profile))

CORE_OBJ = $(patsubst %.c,$(BUILD)/%.o,$(notdir $(CORE_SRC))) $(BUILD)/boards_embedded.o $(BUILD)/shaders_embedded.o \
	$(BUILD)/slide_embedded.o
CORE_LIB = $(BUILD)/liblixel-core.a
GL_OBJ = $(patsubst %.c,$(BUILD)/%.o,$(notdir $(GL_SRC)))

TESTS = test_gpio test_kms_select test_display_loss test_linalg test_number test_json test_button test_board test_depth_rgba test_atlas test_lookup test_shaders test_scene test_uniform test_plane test_warps test_reference test_run_order test_render test_extremes test_filter
TEST_BINS = $(TESTS:%=$(BUILD)/tests/%)

.PHONY: all run slide setup-hash setup-time check check-layers soak deps deps-check deps-asan deps-fuzz install uninstall clean asan fuzz fuzz-build

all: $(BUILD)/lixel

deps:
	@sh tools/install-deps.sh build

deps-check:
	@sh tools/install-deps.sh check

deps-asan:
	@sh tools/install-deps.sh asan

deps-fuzz:
	@sh tools/install-deps.sh fuzz

# Before anything compiles: every library pkg-config must find, or one line naming the
# Debian packages to install (pkg-config's own errors are otherwise lost in the flags).
$(BUILD)/deps.ok: tools/install-deps.sh | $(BUILD)
	@sh tools/install-deps.sh build --verify
	@touch $@

$(BUILD)/%.o: %.c | $(BUILD) $(BUILD)/deps.ok
	$(CC) $(CPPFLAGS_ALL) $(DEPFLAGS) $(WARN) $(CFLAGS) -c $< -o $@

$(BUILD)/gpio_button.o: gpio_button.c | $(BUILD) $(BUILD)/deps.ok
	$(CC) $(CPPFLAGS_ALL) $(GPIOD_CFLAGS) $(DEPFLAGS) $(WARN) $(CFLAGS) -c $< -o $@

$(BUILD)/shaders_embedded.c: $(SHADERS) tools/embed-files.sh | $(BUILD)
	sh tools/embed-files.sh lx_shader_files $(SHADERS) > $@.tmp && mv $@.tmp $@

$(BUILD)/boards_embedded.c: $(BOARDS) tools/embed-files.sh | $(BUILD)
	sh tools/embed-files.sh lx_board_files $(BOARDS) > $@.tmp && mv $@.tmp $@

# lixel's own slide, kept in the repository as tests/data/slide.png: `make slide` redraws it.
slide: $(BUILD)/make-slide
	$(BUILD)/make-slide tests/data/slide.png

$(BUILD)/make-slide: tools/make-slide.c $(BUILD)/png_out.o $(BUILD)/font5x7.o $(BUILD)/out_file.o | $(BUILD)
	$(CC) $(CPPFLAGS_ALL) $(WARN) $(CFLAGS) $^ $(PKG_PNG_LIBS) -lm -o $@

# The set-up's outputs hashed over every method, built-in scene and configuration and 40
# random views each (tools/setup_hash.c): the same hash before and after a change to the
# set-up says it computes the same (SETUP_HASH_ARGS=-v lists each set-up's own).
setup-hash: $(BUILD)/setup-hash
	$(BUILD)/setup-hash $(SETUP_HASH_ARGS)

$(BUILD)/setup-hash: tools/setup_hash.c $(CORE_LIB) | $(BUILD)
	$(CC) $(CPPFLAGS_ALL) $(WARN) $(CFLAGS) $< $(CORE_LIB) $(PKG_PNG_LIBS) -lm -o $@

# The set-up timed without a GL, warm, after work that wears the CPU's caches and
# branch predictor, and after a sleep (tools/setup_time.c): figures, no verdict
# (SETUP_TIME_ARGS: -n, -s, methods).
setup-time: $(BUILD)/setup-time
	$(BUILD)/setup-time $(SETUP_TIME_ARGS)

$(BUILD)/setup-time: tools/setup_time.c $(CORE_LIB) | $(BUILD)
	$(CC) $(CPPFLAGS_ALL) $(WARN) $(CFLAGS) $< $(CORE_LIB) $(PKG_PNG_LIBS) -lm -o $@

$(BUILD)/slide_embedded.c: tests/data/slide.png tools/embed-binary.sh | $(BUILD)
	sh tools/embed-binary.sh lx_builtin_slide_png tests/data/slide.png > $@.tmp && mv $@.tmp $@

$(BUILD)/%_embedded.o: $(BUILD)/%_embedded.c src/base/embedded.h
	$(CC) $(CPPFLAGS_ALL) $(DEPFLAGS) $(WARN) $(CFLAGS) -c $< -o $@

$(CORE_LIB): $(CORE_OBJ)
	rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/lixel: $(BUILD)/main.o $(GL_OBJ) $(BUILD)/gpio_button.o $(CORE_LIB)
	$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LIBS_GL) $(LIBS_GPIOD) -o $@

$(BUILD):
	mkdir -p $(BUILD)/tests

run: deps
	@$(MAKE) --no-print-directory $(BUILD)/lixel
	@mkdir -p out
	$(BUILD)/lixel render --out out/default.png --measure

# Unit tests link the GL-free library alone; the render tests link the GL side too,
# test_gpio the libgpiod button.
GL_TESTS = test_render test_extremes test_filter
$(BUILD)/tests/%: tests/%.c $(CORE_LIB) $(GL_OBJ) $(BUILD)/gpio_button.o | $(BUILD)
	$(CC) $(CPPFLAGS_ALL) $(PKG_CMOCKA_CFLAGS) $(DEPFLAGS) $(WARN) $(CFLAGS) $< \
		$(if $(filter $(GL_TESTS),$*),$(GL_OBJ) $(BUILD)/gpio_button.o,) \
		$(if $(filter test_gpio,$*),$(BUILD)/gpio_button.o,) $(CORE_LIB) \
		$(PKG_CMOCKA_LIBS) $(PKG_PNG_LIBS) $(if $(filter $(GL_TESTS),$*),$(LIBS_GL) $(LIBS_GPIOD),) \
		$(if $(filter test_gpio,$*),$(LIBS_GPIOD),) -lpthread -lm -o $@

# The GL-free library needs nothing of the GL side: every one of its objects linked alone.
$(BUILD)/core_alone: tests/core_alone.c $(CORE_LIB) | $(BUILD)
	$(CC) $(WARN) $(CFLAGS) $(LDFLAGS) $< -Wl,--whole-archive $(CORE_LIB) -Wl,--no-whole-archive $(PKG_PNG_LIBS) -lm -o $@

# A helper of tests/kiosk_x11.sh: closes the kiosk's window from another X client.
$(BUILD)/tests/destroy_window: tests/destroy_window.c | $(BUILD)
	$(CC) $(CPPFLAGS_ALL) $(WARN) $(CFLAGS) $(LDFLAGS) $< $(PKG_X11_LIBS) -o $@

# The suite runs twice: as built, then under AddressSanitizer and UBSan (cheap here).
# The libgpiod v2 path compiles against the v2 API's declarations (tests/gpiod-v2-api)
# wherever the machine only has v1; it is linked only where libgpiod 2 is installed.
$(BUILD)/gpio_button_v2_check.o: src/kiosk/gpio_button.c src/kiosk/gpio_button.h tests/gpiod-v2-api/gpiod.h | $(BUILD)
	$(CC) $(CPPFLAGS_ALL) -Itests/gpiod-v2-api -DLX_GPIOD_V2 $(WARN) $(CFLAGS) -c $< -o $@

# Everything built at once, then every test in one pool over the CPUs. `make asan` runs
# every test again under ASan and UBSan, with a few seconds of each fuzzer (clang builds
# them beside gcc's); CI (.ci/run) runs it and a 20-second `make soak` after make check.
check: deps-check check-layers
	@$(MAKE) --no-print-directory $(CHECK_JOBS) \
		$(BUILD)/lixel $(TEST_BINS) $(BUILD)/tests/destroy_window $(BUILD)/gpio_button_v2_check.o $(BUILD)/core_alone \
		$(BUILD)/setup-hash $(BUILD)/setup-time
	@sh tests/run-tests.sh $(BUILD)

# The kiosk under Xvfb for SOAK_SECONDS (default 600): a key every 50 ms, its own memory sampled.
soak: deps-check
	@$(MAKE) --no-print-directory $(BUILD)/lixel
	@sh tests/kiosk_soak.sh $(BUILD)/lixel

# make check's builds use every CPU (its sub-makes are its own: nothing else shares them)
CHECK_JOBS ?= -j$(shell nproc 2>/dev/null || echo 1)
# make asan's fuzzing, in seconds (make fuzz runs longer)
ASAN_FUZZ_SECONDS ?= 2

# The include rules between the layers, the GL-free files' freedom from GL headers,
# and no function over 80 lines.
check-layers:
	@sh tools/check-layers.sh $(CORE_SRC) && echo "layers: every include follows the rules (tools/check-layers.sh)"
	@sh tools/check-function-length.sh 80 && echo "functions: none in src/ over 80 lines (tools/check-function-length.sh)"

# The same tests under AddressSanitizer and UBSan, in their own build directory, and a
# few seconds of each fuzzer (unoptimised: half the compile time, for seconds of fuzzing),
# all in one pool.
asan: deps-asan
	@$(MAKE) --no-print-directory $(CHECK_JOBS) BUILD=build-asan CFLAGS="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer" \
		LDFLAGS="-fsanitize=address,undefined" FUZZ_DIR=build-asan/fuzz-quick FUZZ_OPT="-O0 -gline-tables-only" \
		build-asan/lixel $(TEST_BINS:$(BUILD)/%=build-asan/%) build-asan/tests/destroy_window \
		$(FUZZ_NAMES:%=build-asan/fuzz-quick/%)
	@LIXEL_TEST_QUICK=1 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
		FUZZ_SECONDS=$(ASAN_FUZZ_SECONDS) FUZZ_NAMES="$(FUZZ_NAMES)" FUZZ_DIR=build-asan/fuzz-quick \
		sh tests/run-tests.sh build-asan

# libFuzzer harnesses (fuzz/*.c) over the GL-free core, built with clang under ASan and
# UBSan into $(BUILD)/fuzz/. make fuzz runs each FUZZ_SECONDS seconds from the seeds in
# fuzz/corpus/NAME/ (tools/fuzz.sh works in a temporary folder and says where any
# finding is); make asan runs each for a few seconds.
FUZZ_CC ?= clang
FUZZ_SECONDS ?= 60
FUZZ_NAMES = fuzz_scene fuzz_board fuzz_methods fuzz_cli
# make asan builds them apart, unoptimised; make fuzz at -O1, for the runs per second of
# long sessions
FUZZ_DIR ?= $(BUILD)/fuzz
FUZZ_OPT ?= -O1 -g
FUZZ_BINS = $(FUZZ_NAMES:%=$(FUZZ_DIR)/%)
FUZZ_CFLAGS = -std=c11 -D_DEFAULT_SOURCE $(SRC_DIRS:%=-I%) -I$(BUILD) $(WARN) $(FUZZ_OPT) -pipe -fno-omit-frame-pointer \
	-fsanitize=address,undefined -fno-sanitize-recover=all
# The harnesses reach the parsers and what they call, not the measuring side, the shaders'
# text or the kiosk's inputs: those are not built for them (a harness that comes to need
# one fails its link, naming the symbol), a third less to compile.
FUZZ_UNUSED = src/base/font5x7.c src/base/json.c src/base/out_file.c src/base/png_out.c src/gl/shader_text.c \
	src/kiosk/button.c src/kiosk/gpio_lookup.c src/measure/metrics.c src/measure/reference.c \
	src/measure/soft_reference.c src/platform/display_loss.c src/platform/kms_select.c src/scene/configs.c \
	src/shadow/depth_rgba.c src/shadow/lookup_region.c
FUZZ_OBJ = $(patsubst %.c,$(FUZZ_DIR)/obj/%.o,$(notdir $(filter-out $(FUZZ_UNUSED),$(CORE_SRC)))) \
	$(FUZZ_DIR)/obj/boards_embedded.o $(FUZZ_DIR)/obj/slide_embedded.o

$(FUZZ_DIR)/obj/%.o: %.c | $(FUZZ_DIR)/obj
	$(FUZZ_CC) $(FUZZ_CFLAGS) $(DEPFLAGS) -fsanitize=fuzzer-no-link -c $< -o $@

$(FUZZ_DIR)/obj/%_embedded.o: $(BUILD)/%_embedded.c src/base/embedded.h | $(FUZZ_DIR)/obj
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link -c $< -o $@

$(FUZZ_BINS): $(FUZZ_DIR)/%: fuzz/%.c $(FUZZ_OBJ)
	$(FUZZ_CC) $(FUZZ_CFLAGS) $(DEPFLAGS) -fsanitize=fuzzer $< $(FUZZ_OBJ) $(PKG_PNG_LIBS) -lpthread -lm -o $@

$(FUZZ_DIR)/obj: | $(BUILD)
	mkdir -p $@

fuzz-build: deps-fuzz
	@$(MAKE) --no-print-directory $(CHECK_JOBS) $(FUZZ_BINS)

fuzz: fuzz-build
	@sh tools/fuzz.sh $(FUZZ_DIR) $(FUZZ_SECONDS) $(FUZZ_NAMES)

# The binary (shaders and board profiles are built in), the man page, the profiles as
# files to copy and edit (--board FILE), and the kiosk's systemd unit.
install: $(BUILD)/lixel
	install -d $(DESTDIR)$(BINDIR) $(DESTDIR)$(MANDIR) $(DESTDIR)$(DATADIR)/board $(DESTDIR)$(UNITDIR)
	install -m 755 $(BUILD)/lixel $(DESTDIR)$(BINDIR)/lixel
	install -m 644 docs/lixel.1 $(DESTDIR)$(MANDIR)/lixel.1
	install -m 644 $(BOARDS) $(DESTDIR)$(DATADIR)/board/
	sed 's|@BINDIR@|$(BINDIR)|' board/lixel-kiosk.service > $(DESTDIR)$(UNITDIR)/lixel-kiosk.service
	install -d $(DESTDIR)$(UDEVDIR)
	install -m 644 board/60-lixel-gpio.rules $(DESTDIR)$(UDEVDIR)/60-lixel-gpio.rules
	chmod 644 $(DESTDIR)$(UNITDIR)/lixel-kiosk.service

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/lixel $(DESTDIR)$(MANDIR)/lixel.1 $(DESTDIR)$(UNITDIR)/lixel-kiosk.service
	rm -rf $(DESTDIR)$(DATADIR)

clean:
	rm -rf build build-asan out
-include tools/cross.mk

# the header dependencies -MMD wrote (none before the first build)
-include $(wildcard $(BUILD)/*.d $(BUILD)/tests/*.d $(BUILD)/fuzz*/*.d $(BUILD)/fuzz*/obj/*.d)
