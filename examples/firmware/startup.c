/* Start-up for a Cortex-M4F: the vector table and the reset handler, which enables the FPU,
 * copies .data from flash, clears .bss, runs C++ static constructors and calls main().
 * The addresses come from the linker script (boards/sections.ld). */
#include <stdint.h>
#include <string.h>

extern uint32_t __stack_top[], __data_start[], __data_end[], __data_load[], __bss_start[], __bss_end[];
typedef void (*handler)(void);
extern handler __init_array_start[], __init_array_end[];
int main(void);

void Reset_Handler(void);

/* Any other exception or interrupt: this example enables none, so it is a fault. Stop here,
 * where a debugger shows it. */
void Default_Handler(void) {
  for (;;) {
  }
}

/* 15 system exceptions after the initial stack pointer, then the interrupts: 82 on the
 * STM32F405/407 (the mps2-an386 has fewer and never reads the rest). */
enum { system_exceptions = 15, interrupts = 82 };
__attribute__((section(".vectors"), used)) const struct {
  uint32_t *initial_stack_pointer;
  handler vectors[system_exceptions + interrupts];
} vector_table = {__stack_top, {Reset_Handler, [1 ... system_exceptions + interrupts - 1] = Default_Handler}};

void Reset_Handler(void) {
  /* CPACR bits 20-23: full access to CP10 and CP11, the FPU, which -mfloat-abi=hard code may use
   * anywhere; the barriers make it apply to the next instruction. */
  *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
  __asm__ volatile("dsb\n\tisb" ::: "memory");
  memcpy(__data_start, __data_load, (size_t)((char *)__data_end - (char *)__data_start));
  memset(__bss_start, 0, (size_t)((char *)__bss_end - (char *)__bss_start));
  for (handler *constructor = __init_array_start; constructor < __init_array_end; ++constructor) {
    (*constructor)();
  }
  main();
  for (;;) {
  }
}
