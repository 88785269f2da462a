/* Output files written as careful tools write them: the target checked before any work
 * (its folder exists and is writable, it is a regular file or absent), the data written
 * to a fresh temporary beside it (mkstemp: O_EXCL, a name no one else can have planted),
 * flushed to disk, and renamed into place, never over anything but a regular file. On
 * any failure nothing of the run is left behind. */
#ifndef LX_OUT_FILE_H
#define LX_OUT_FILE_H
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* Whether path can be written: false with one line in err ("PATH: why") when not. */
bool lx_out_check(const char *path, char *err, size_t errlen);
/* Writes path through write(f, ctx) (which returns false on failure). */
bool lx_out_write(const char *path, bool (*write)(FILE *f, void *ctx), void *ctx, char *err, size_t errlen);

#endif
