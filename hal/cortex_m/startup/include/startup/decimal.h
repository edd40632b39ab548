/* Number formatting for the startup's messages: no printf (it would pull in newlib's stdio,
 * which allocates). */
#ifndef SPANLIGHT_STARTUP_DECIMAL_H
#define SPANLIGHT_STARTUP_DECIMAL_H

#include <stdint.h>

/* Writes value in decimal into out (at least 11 chars) and returns out. */
char *spanlight_format_decimal(uint32_t value, char *out);
/* Writes value as 0x%08x into out (at least 11 chars) and returns out. */
char *spanlight_format_hex(uint32_t value, char *out);

#endif
