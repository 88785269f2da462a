/* A 5x7 pixel font (digits, lower-case letters, a little punctuation; upper case drawn
 * as lower case) for the bench's plot and the kiosk's overlay. GL-free. */
#ifndef LX_FONT5X7_H
#define LX_FONT5X7_H
#include <stdint.h>

/* Seven rows of five bits (bit 4 the leftmost column), or NULL for a blank. */
const uint8_t *lx_font5x7(char c);

#endif
