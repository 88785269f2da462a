# Raspberry Pi 4 and 400: VideoCore VI through Mesa's v3d. card0 is render-only (v3d);
# the display controller (vc4-kms) is card1.
name raspberry-pi-4
description Raspberry Pi 4, VideoCore VI (v3d), display on card1
gpio-chip gpiochip0
gpio-line 17
gpio-active low
gpio-bias pull-up
debounce-ms 30
long-press-ms 1000
display /dev/dri/card1
mode preferred
plane-lixels 350
fallback-lixels 128
uniform-lixels 512
methods plane,uniform,lispsm,psm,tsm,none
