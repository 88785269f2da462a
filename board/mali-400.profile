# A generic Allwinner/Rockchip board with an ARM Mali-400 (Mesa lima): fragment shaders
# run in fp16 although lima reports highp, so lixel's start-up depth self-test fails the
# 24-bit path and takes the 11-bit one (the log says "depth mediump11, self-test
# fell-back"); depth-precision mediump would force it.
name mali-400
description generic Mali-400 board (lima), display chosen automatically
gpio-chip gpiochip0
gpio-line 10
gpio-active low
gpio-bias pull-up
debounce-ms 30
long-press-ms 1000
display auto
mode 1280x720
# MP1 at 210 Mpixel/s: keep the maps as the paper had them
plane-lixels 350
fallback-lixels 128
uniform-lixels 512
# a scene of several lights: the second and later lights' maps get half the lixels
# (their shadow passes fill half as much)
light-budget 1,0.5
depth-precision auto
methods plane,uniform,lispsm,none
