/* `lixel kiosk`: the animated scene full screen (or in a window on a desktop), a push
 * button (or the keyboard) switching the shadow method, status lines every 5 seconds. */
#ifndef LX_KIOSK_H
#define LX_KIOSK_H

int lx_kiosk_main(int argc, char **argv);

#endif
