# A generic Allwinner/Rockchip board with an ARM Mali-400 (Mesa lima): fragment shaders
# run in fp16, so lixel takes its 11-bit depth path there by itself.
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
methods plane,uniform,lispsm,none
