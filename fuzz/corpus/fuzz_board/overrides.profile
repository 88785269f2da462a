gpio-chip auto
gpio-line-name GPIO17
gpio-bias disabled
gpio-active high
display /dev/dri/card1
mode 1920x1080@60
depth-precision mediump
methods uniform, none
