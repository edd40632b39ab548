/* Exception handlers the vector table points at. */
#ifndef SPANLIGHT_STARTUP_HANDLERS_H
#define SPANLIGHT_STARTUP_HANDLERS_H

#ifdef __cplusplus
extern "C" {
#endif

/* Paints the stack, enables the FPU, initialises C/C++ state, runs main, exits with its status. */
__attribute__((noreturn)) void Reset_Handler(void);
/* Every other exception and interrupt: reports which one and exits non-zero. */
__attribute__((noreturn)) void spanlight_fault_handler(void);

/* Provided by the app side (hal/cortex_m defines it and calls the app's app_main). */
int main(void);

#ifdef __cplusplus
}
#endif

#endif
