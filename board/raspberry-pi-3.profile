# Raspberry Pi 3 (and 2, Zero 2 W): VideoCore IV through Mesa's vc4 driver, which does
# the display and the 3D on the same card.
name raspberry-pi-3
description Raspberry Pi 3, VideoCore IV (vc4)
# A push button between GPIO17 (header pin 11) and ground, with the pull-up inside.
gpio-chip gpiochip0
gpio-line 17
gpio-active low
gpio-bias pull-up
debounce-ms 30
long-press-ms 1000
display /dev/dri/card0
mode 1280x720@60
# VideoCore IV fills about 1 Gpixel/s; the paper's budgets fit its 2048 texture limit.
plane-lixels 350
fallback-lixels 128
uniform-lixels 512
# a scene of several lights: the second and later lights' maps get half the lixels
# (their shadow passes fill half as much)
light-budget 1,0.5
methods plane,uniform,lispsm,psm,tsm,none
