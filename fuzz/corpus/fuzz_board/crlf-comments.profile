gpio-chip none
	debounce-ms 0   # no debounce
mode preferred
long-press-ms 10000
depth-precision highp
