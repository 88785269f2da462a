#include "out_file.h"
#include <errno.h>
#include <fcntl.h>
#include <libgen.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The folder of path, in buf. */
static const char *folder(const char *path, char *buf, size_t len)
{
	snprintf(buf, len, "%s", path);
	return dirname(buf);
}

bool lx_out_check(const char *path, char *err, size_t errlen)
{
	char buf[4096];
	if (!path || !*path || strlen(path) >= sizeof buf) {
		snprintf(err, errlen, "'%s': expected a file name", path ? path : "");
		return false;
	}
	const char *dir = folder(path, buf, sizeof buf);
	struct stat st;
	if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
		snprintf(err, errlen, "%s: no such folder '%s'", path, dir);
		return false;
	}
	if (access(dir, W_OK | X_OK) != 0) {
		snprintf(err, errlen, "%s: cannot write into folder '%s': %s", path, dir, strerror(errno));
		return false;
	}
	if (lstat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
		snprintf(err, errlen, "%s: exists and is not a regular file (%s): not replaced", path,
			 S_ISLNK(st.st_mode) ? "a symbolic link" : S_ISDIR(st.st_mode) ? "a folder" : "a device or other");
		return false;
	}
	return true;
}

bool lx_out_write(const char *path, bool (*write)(FILE *f, void *ctx), void *ctx, char *err, size_t errlen)
{
	if (!lx_out_check(path, err, errlen))
		return false;
	char buf[4096], tmp[4200];
	char base[4096];
	snprintf(base, sizeof base, "%s", path);
	snprintf(tmp, sizeof tmp, "%s/.%s.XXXXXX", folder(path, buf, sizeof buf), basename(base));
	int fd = mkstemp(tmp);
	if (fd < 0) {
		snprintf(err, errlen, "%s: cannot create a temporary file: %s", path, strerror(errno));
		return false;
	}
	mode_t mask = umask(0); /* the mode a plain fopen would have given */
	umask(mask);
	bool ok = fchmod(fd, 0666 & ~mask) == 0;
	FILE *f = ok ? fdopen(fd, "wb") : NULL;
	if (!f) {
		snprintf(err, errlen, "%s: cannot write: %s", path, strerror(errno));
		close(fd);
		unlink(tmp);
		return false;
	}
	ok = write(f, ctx);
	ok = fflush(f) == 0 && ok;
	ok = fsync(fileno(f)) == 0 && ok;
	ok = fclose(f) == 0 && ok;
	/* checked again just before: something may have appeared at the target meanwhile */
	if (ok && !lx_out_check(path, err, errlen)) {
		unlink(tmp);
		return false;
	}
	if (!ok || rename(tmp, path) != 0) {
		snprintf(err, errlen, "%s: %s", path, ok ? strerror(errno) : "writing failed");
		unlink(tmp);
		return false;
	}
	return true;
}
