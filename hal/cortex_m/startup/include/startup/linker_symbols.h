/* Addresses defined by the linker script (hal/cortex_m/mps2/mps2.ld). Declared as arrays so their address is the value. */
#ifndef SPANLIGHT_STARTUP_LINKER_SYMBOLS_H
#define SPANLIGHT_STARTUP_LINKER_SYMBOLS_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_limit[], __stack_top[];

typedef void (*spanlight_init_fn)(void);
extern spanlight_init_fn __preinit_array_start[], __preinit_array_end[];
extern spanlight_init_fn __init_array_start[], __init_array_end[];

#ifdef __cplusplus
}
#endif

#endif
