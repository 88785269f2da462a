# Raspberry Pi 5: VideoCore VII through Mesa's v3d; the header's GPIOs are on the RP1
# chip, which Linux 6.6.45 moved from gpiochip4 to gpiochip0: the button is found by the
# chip's label and the line's name, which did not move.
name raspberry-pi-5
description Raspberry Pi 5, VideoCore VII (v3d), button on header GPIO17 by name
gpio-chip pinctrl-rp1
gpio-line-name GPIO17
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
# VideoCore VII has fill to spare over the older boards: the button also steps through
# a filtered lookup within each method (plane, plane+pcf2x2, uniform, ...)
filters none,pcf2x2
