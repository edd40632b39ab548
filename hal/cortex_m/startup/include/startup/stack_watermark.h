/* Stack high-water mark from the paint the reset code puts on the whole stack. */
#ifndef SPANLIGHT_STARTUP_STACK_WATERMARK_H
#define SPANLIGHT_STARTUP_STACK_WATERMARK_H

#include <stddef.h>

/* Written over [__stack_limit, __stack_top) before main; "STAK" in ASCII, unlikely as data. */
#define SPANLIGHT_STACK_PAINT 0x4B415453u

#ifdef __cplusplus
extern "C" {
#endif

/* Deepest stack use since reset, in bytes (a word that happens to hold the paint value
 * at the edge can make it read up to a few words low). */
size_t spanlight_stack_peak_bytes(void);
/* Paints the stack below the caller again, so that the next peak counts only what runs after
 * this call (the earlier peak is lost: read it first), and returns the stack in use here. */
size_t spanlight_stack_mark(void);
/* Size of the whole stack region. */
size_t spanlight_stack_size_bytes(void);

#ifdef __cplusplus
}
#endif

#endif
