# Cross builds for the boards, and running them under qemu-user (docs/boards.md).
#   sh tools/make-sysroot.sh arm64 sysroot-arm64      # once: the target's libraries
#   make cross ARCH=arm64 SYSROOT=sysroot-arm64        # build-arm64/lixel and its tests
#   make check-cross ARCH=arm64 SYSROOT=sysroot-arm64  # GL-free tests + one render, under qemu
#   make clean-cross                                   # removes build-arm64 and build-armhf
# ARCH is arm64 or armhf. Included by the Makefile; it defines only the targets above
# and CROSS_* variables, so the native build (all, check, asan) is untouched: the
# cross build is the Makefile itself run again with BUILD, CC and pkg-config's paths.

CROSS_TRIPLET_arm64 = aarch64-linux-gnu
CROSS_TRIPLET_armhf = arm-linux-gnueabihf
CROSS_QEMU_arm64 = qemu-aarch64
CROSS_QEMU_armhf = qemu-arm
# llvmpipe under qemu-arm renders wrongly (softpipe is right), so armhf uses softpipe.
CROSS_GALLIUM_arm64 = llvmpipe
CROSS_GALLIUM_armhf = softpipe
# The render under qemu fails above this mismatch (percent; a native run gives ~0.005).
CROSS_MAX_MISMATCH ?= 0.5

CROSS_T = $(CROSS_TRIPLET_$(ARCH))
CROSS_ROOT = $(abspath $(SYSROOT))
CROSS_BUILD = build-$(ARCH)
CROSS_LIBDIRS = $(CROSS_ROOT)/lib/$(CROSS_T):$(CROSS_ROOT)/usr/lib/$(CROSS_T)
CROSS_PC = PKG_CONFIG_SYSROOT_DIR=$(CROSS_ROOT) \
	PKG_CONFIG_LIBDIR=$(CROSS_ROOT)/usr/lib/$(CROSS_T)/pkgconfig:$(CROSS_ROOT)/usr/share/pkgconfig \
	PKG_CONFIG_PATH=
CROSS_CC = $(CROSS_T)-gcc --sysroot=$(CROSS_ROOT)
CROSS_TEST_BINS = $(TESTS:%=$(CROSS_BUILD)/tests/%)

# One line and exit 2 on a bad ARCH or SYSROOT.
define CROSS_ARGS
case "$(ARCH)" in arm64|armhf) ;; \
  *) echo "lixel: ARCH must be arm64 or armhf (got '$(ARCH)'): make $@ ARCH=arm64 SYSROOT=DIR" >&2; exit 2 ;; esac; \
if [ -z "$(SYSROOT)" ] || [ ! -d "$(CROSS_ROOT)/usr/lib/$(CROSS_T)/pkgconfig" ]; then \
  echo "lixel: SYSROOT='$(SYSROOT)' is not an $(ARCH) sysroot; make one with: sh tools/make-sysroot.sh $(ARCH) DIR" >&2; exit 2; fi
endef

# Installs the Debian packages named in $$want that are missing, like tools/install-deps.sh.
define CROSS_APT
missing=""; for p in $$want; do \
  dpkg-query -W -f='$${Status}' "$$p" 2>/dev/null | grep -q '^install ok installed$$' || missing="$$missing $$p"; done; \
if [ -n "$$missing" ]; then \
  if [ "$$(id -u)" -ne 0 ]; then echo "lixel: missing Debian packages:$$missing -- run: sudo apt-get install$$missing" >&2; exit 1; fi; \
  echo "lixel: installing Debian packages:$$missing" >&2; \
  export DEBIAN_FRONTEND=noninteractive; \
  apt-get update -qq >&2 && apt-get install -y -qq --no-install-recommends $$missing >&2 || exit 1; \
fi
endef

.PHONY: cross check-cross clean-cross

clean-cross:
	rm -rf build-arm64 build-armhf

cross:
	@$(CROSS_ARGS)
	@want="crossbuild-essential-$(ARCH) pkg-config make"; $(CROSS_APT)
	@$(CROSS_PC) pkg-config --exists --print-errors $(GL_PKGS) libgpiod cmocka \
		|| { echo "lixel: the sysroot $(SYSROOT) lacks pkg-config packages; rerun tools/make-sysroot.sh $(ARCH) $(SYSROOT)" >&2; exit 1; }
	@echo "lixel: cross-building for $(ARCH) ($(CROSS_T)-gcc, sysroot $(SYSROOT)) into $(CROSS_BUILD)/"
	@$(CROSS_PC) $(MAKE) --no-print-directory BUILD=$(CROSS_BUILD) CC="$(CROSS_CC)" PKG_CONFIG=pkg-config \
		LDFLAGS="$(LDFLAGS) -Wl,-rpath-link,$(CROSS_LIBDIRS)" $(CROSS_BUILD)/lixel $(CROSS_TEST_BINS)
	@echo "lixel: built $(CROSS_BUILD)/lixel and $(words $(CROSS_TEST_BINS)) test programs for $(ARCH)"

# The GL-free unit tests and one measured render, each under qemu-user with -L SYSROOT.
# Mesa comes from the sysroot: the guest's libraries, OSMesa's gallium driver chosen by
# GALLIUM_DRIVER, the DRI drivers and glvnd's EGL vendor file for --platform egl.
check-cross: cross
	@want="qemu-user-static"; \
	if ! command -v $(CROSS_QEMU_$(ARCH))-static >/dev/null 2>&1 && ! command -v $(CROSS_QEMU_$(ARCH)) >/dev/null 2>&1; then $(CROSS_APT); fi
	@qemu=$$(command -v $(CROSS_QEMU_$(ARCH))-static || command -v $(CROSS_QEMU_$(ARCH))); \
	now() { date +%s%N | cut -c1-13; }; \
	secs() { awk -v a="$$1" -v b="$$2" 'BEGIN { printf "%.1f", (b - a) / 1000 }'; }; \
	run() { "$$qemu" -L "$(CROSS_ROOT)" -E LD_LIBRARY_PATH="$(CROSS_LIBDIRS)" \
		-E LIBGL_ALWAYS_SOFTWARE=1 -E GALLIUM_DRIVER=$(CROSS_GALLIUM_$(ARCH)) \
		-E LIBGL_DRIVERS_PATH="$(CROSS_ROOT)/usr/lib/$(CROSS_T)/dri" \
		-E __EGL_VENDOR_LIBRARY_DIRS="$(CROSS_ROOT)/usr/share/glvnd/egl_vendor.d" "$$@"; }; \
	tmp=$$(mktemp -d); passed=0; failed=0; failed_names=""; \
	echo "lixel: $(ARCH) under $$qemu -L $(SYSROOT), GALLIUM_DRIVER=$(CROSS_GALLIUM_$(ARCH))"; \
	t0=$$(now); \
	for t in $(filter-out %/test_render %/test_filter,$(CROSS_TEST_BINS)); do \
	  name=$${t##*/}; s=$$(now); \
	  if run "$$t" > "$$tmp/$$name.log" 2>&1; then passed=$$((passed + 1)); echo "PASS $$name ($$(secs $$s $$(now)) s)"; \
	  else failed=$$((failed + 1)); failed_names="$$failed_names $$name"; echo "FAIL $$name ($$(secs $$s $$(now)) s):"; tail -n 15 "$$tmp/$$name.log"; fi; \
	done; \
	t1=$$(now); units=$$(secs $$t0 $$t1); \
	echo "lixel: unit tests under qemu: $$passed passed, $$failed failed in $$units s"; \
	if run $(CROSS_BUILD)/lixel render --measure --json --size 320x240 --out "$$tmp/x.png" > "$$tmp/render.json" 2> "$$tmp/render.err" \
	  && [ -s "$$tmp/x.png" ]; then \
	  pct=$$(sed -n 's/.*"mismatch_pct": \([0-9.e+-]*\).*/\1/p' "$$tmp/render.json"); \
	  depth=$$(sed -n 's/.*"depth_path": "\([^"]*\)".*/\1/p' "$$tmp/render.json"); \
	  renderer=$$(sed -n 's/.*"renderer": "\([^"]*\)".*/\1/p' "$$tmp/render.json"); \
	  frame=$$(sed -n 's/.*"frame_ms": \([0-9.e+-]*\).*/\1/p' "$$tmp/render.json"); \
	  echo "lixel: render 320x240 on $$renderer: mismatch_pct $$pct, depth_path $$depth, frame_ms $$frame, $$(secs $$t1 $$(now)) s"; \
	  if [ -n "$$pct" ] && awk -v p="$$pct" -v m=$(CROSS_MAX_MISMATCH) 'BEGIN { exit !(p <= m) }'; then passed=$$((passed + 1)); echo "PASS render"; \
	  else failed=$$((failed + 1)); failed_names="$$failed_names render"; echo "FAIL render: mismatch_pct '$$pct' is not at most $(CROSS_MAX_MISMATCH)"; fi; \
	else failed=$$((failed + 1)); failed_names="$$failed_names render"; echo "FAIL render:"; tail -n 15 "$$tmp/render.err"; fi; \
	rm -rf "$$tmp"; \
	[ -z "$$failed_names" ] || echo "failed:$$failed_names"; \
	echo "check-cross $(ARCH): $$passed passed, $$failed failed"; \
	[ "$$failed" -eq 0 ]
