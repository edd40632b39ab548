/* The vector table. The linker script puts .vectors at address 0, where the core reads the
 * initial stack pointer and the reset handler on reset (QEMU ignores the ELF entry point). */
#include "startup/handlers.h"
#include "startup/linker_symbols.h"

enum {
  kSystemExceptions = 15, /* NMI .. SysTick: vector numbers 1-15, reset included */
  kInterrupts = 32,       /* external IRQs: ARMv6-M has at most 32; none is enabled */
};

typedef void (*spanlight_handler)(void);

struct spanlight_vectors {
  uint32_t *initial_stack_pointer;
  spanlight_handler system[kSystemExceptions];
  spanlight_handler interrupts[kInterrupts];
};

/* Every entry but reset goes to the catch-all: nothing in spanlight takes interrupts, so any
 * exception is a bug and should stop the run with a non-zero status. Reserved slots too: an
 * escalation to one of them would be just as unexpected. */
#define CATCH_ALL spanlight_fault_handler
#define CATCH_ALL_4 CATCH_ALL, CATCH_ALL, CATCH_ALL, CATCH_ALL
#define CATCH_ALL_16 CATCH_ALL_4, CATCH_ALL_4, CATCH_ALL_4, CATCH_ALL_4

__attribute__((section(".vectors"), used)) const struct spanlight_vectors spanlight_vector_table = {
    .initial_stack_pointer = __stack_top,
    .system = {Reset_Handler, CATCH_ALL_4, CATCH_ALL_4, CATCH_ALL_4, CATCH_ALL, CATCH_ALL},
    .interrupts = {CATCH_ALL_16, CATCH_ALL_16},
};
