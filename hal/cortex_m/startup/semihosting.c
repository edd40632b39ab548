/* Arm semihosting over bkpt 0xAB (the M-profile convention: no SVC). */
#include "startup/semihosting.h"

#include <stdint.h>
#include <string.h>

enum {
  SYS_OPEN = 0x01,
  SYS_CLOSE = 0x02,
  SYS_WRITE0 = 0x04,
  SYS_WRITE = 0x05,
  SYS_SEEK = 0x0A,
  SYS_GET_CMDLINE = 0x15,
  SYS_EXIT = 0x18,
  SYS_EXIT_EXTENDED = 0x20,
};

/* ADP_Stopped_ApplicationExit: "the program finished", the only reason QEMU treats as normal. */
static const uint32_t kApplicationExit = 0x20026u;

/* r0 = operation, r1 = argument (usually a pointer to a parameter block); result in r0.
 * The "memory" clobber: the host reads and writes the blocks and buffers r1 points to. */
static int semihost_call(uint32_t operation, const void *argument) {
  register uint32_t r0 __asm__("r0") = operation;
  register const void *r1 __asm__("r1") = argument;
  __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return (int)r0;
}

int spanlight_semihost_open(const char *path, int mode) {
  const uintptr_t block[3] = {(uintptr_t)path, (uintptr_t)mode, (uintptr_t)strlen(path)};
  return semihost_call(SYS_OPEN, block);
}

int spanlight_semihost_write(int handle, const void *data, size_t length) {
  const uintptr_t block[3] = {(uintptr_t)handle, (uintptr_t)data, (uintptr_t)length};
  return semihost_call(SYS_WRITE, block);
}

int spanlight_semihost_seek(int handle, size_t position) {
  const uintptr_t block[2] = {(uintptr_t)handle, (uintptr_t)position};
  return semihost_call(SYS_SEEK, block);
}

int spanlight_semihost_close(int handle) {
  const uintptr_t block[1] = {(uintptr_t)handle};
  return semihost_call(SYS_CLOSE, block);
}

void spanlight_semihost_write0(const char *text) { (void)semihost_call(SYS_WRITE0, text); }

int spanlight_semihost_get_cmdline(char *buffer, size_t capacity) {
  /* The host writes the length back into the block, so it must not be const. */
  uintptr_t block[2] = {(uintptr_t)buffer, (uintptr_t)capacity};
  return semihost_call(SYS_GET_CMDLINE, block);
}

void spanlight_semihost_exit(int status) {
  const uintptr_t block[2] = {kApplicationExit, (uintptr_t)(uint32_t)status};
  (void)semihost_call(SYS_EXIT_EXTENDED, block);
  /* A host without SYS_EXIT_EXTENDED returns here: plain SYS_EXIT still says pass or fail. */
  (void)semihost_call(SYS_EXIT, (const void *)(uintptr_t)(status == 0 ? kApplicationExit : 0u));
  for (;;) {
  }
}
