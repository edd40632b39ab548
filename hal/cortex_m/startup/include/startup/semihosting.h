/* Arm semihosting calls (bkpt 0xAB): the debugger, here QEMU with
 * -semihosting-config enable=on,target=native, performs the operation on the host.
 * Only the calls spanlight needs; each is a thin wrapper over one operation number. */
#ifndef SPANLIGHT_STARTUP_SEMIHOSTING_H
#define SPANLIGHT_STARTUP_SEMIHOSTING_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* SYS_OPEN modes (the index into the fopen mode table "r","rb","r+","r+b","w","wb",...). */
enum { SPANLIGHT_SEMIHOST_MODE_WRITE_BINARY = 5 };

/* SYS_OPEN: returns a host file handle, or -1. */
int spanlight_semihost_open(const char *path, int mode);
/* SYS_WRITE: returns 0 when every byte was written. */
int spanlight_semihost_write(int handle, const void *data, size_t length);
/* SYS_SEEK to an absolute byte position: returns 0 on success. */
int spanlight_semihost_seek(int handle, size_t position);
/* SYS_CLOSE: returns 0 on success. */
int spanlight_semihost_close(int handle);
/* SYS_WRITE0: a NUL-terminated string to the host's console. */
void spanlight_semihost_write0(const char *text);
/* SYS_GET_CMDLINE into buffer (NUL-terminated): returns 0 on success. */
int spanlight_semihost_get_cmdline(char *buffer, size_t capacity);
/* SYS_EXIT_EXTENDED: QEMU exits with this status. Never returns. */
__attribute__((noreturn)) void spanlight_semihost_exit(int status);

#ifdef __cplusplus
}
#endif

#endif
