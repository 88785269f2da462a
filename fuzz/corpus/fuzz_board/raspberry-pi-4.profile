# Raspberry Pi 4 and 400: VideoCore VI through Mesa's v3d. One DRM card is render-only
# (v3d), the other the display controller (vc4-kms), and which is card0 changes from
# boot to boot: display auto takes the first that can mode-set.
name raspberry-pi-4
description Raspberry Pi 4, VideoCore VI (v3d), display chosen automatically
gpio-chip gpiochip0
gpio-line 17
gpio-active low
gpio-bias pull-up
debounce-ms 30
long-press-ms 1000
display auto
mode preferred
plane-lixels 350
fallback-lixels 128
uniform-lixels 512
methods plane,uniform,lispsm,psm,tsm,none
