# The development desktop: no GPIO (the keyboard is the button), any display.
name desktop
description desktop emulation: keyboard for the button
gpio-chip none
display auto
mode preferred
plane-lixels 350
fallback-lixels 128
uniform-lixels 512
methods plane,uniform,psm,lispsm,tsm,none
