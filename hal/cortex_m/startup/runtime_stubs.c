/* The few C/C++ runtime hooks bare-metal code still references, defined here so that
 * newlib's versions (which reach for stdio, signals and, through them, the heap) never link. */
#include "startup/decimal.h"
#include "startup/semihosting.h"

#include <stdint.h>

/* Status of a run that called abort() or failed an assert, as a POSIX shell reports SIGABRT. */
enum { kAbortStatus = 134 };

/* Identifies this "shared object" to __cxa_atexit; crtbegin.o would define it. */
void *__dso_handle = 0;

/* Static destructors are never registered: the run ends by semihosting exit, not by
 * returning through exit(), so there is nothing to run them and no reason to keep a table. */
int __cxa_atexit(void (*destructor)(void *), void *object, void *dso) {
  (void)destructor;
  (void)object;
  (void)dso;
  return 0;
}
int __aeabi_atexit(void *object, void (*destructor)(void *), void *dso) {
  return __cxa_atexit(destructor, object, dso);
}

__attribute__((noreturn)) void abort(void) {
  spanlight_semihost_write0("spanlight: abort\n");
  spanlight_semihost_exit(kAbortStatus);
}

/* newlib's assert() calls this; its own version formats with fiprintf. */
__attribute__((noreturn)) void __assert_func(const char *file, int line, const char *function,
                                             const char *expression) {
  char number[12];
  spanlight_semihost_write0("spanlight: assertion failed: ");
  spanlight_semihost_write0(expression);
  spanlight_semihost_write0(" in ");
  spanlight_semihost_write0(function != 0 ? function : "?");
  spanlight_semihost_write0(" at ");
  spanlight_semihost_write0(file);
  spanlight_semihost_write0(":");
  spanlight_semihost_write0(spanlight_format_decimal((uint32_t)line, number));
  spanlight_semihost_write0("\n");
  spanlight_semihost_exit(kAbortStatus);
}

/* A call through a pure virtual slot: a bug, reported like abort. */
__attribute__((noreturn)) void __cxa_pure_virtual(void) {
  spanlight_semihost_write0("spanlight: pure virtual call\n");
  spanlight_semihost_exit(kAbortStatus);
}
