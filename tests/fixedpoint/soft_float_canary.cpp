// Code that check_no_soft_float.sh must refuse on Cortex-M0+: a float product and
// an integer division, which ARMv6-M can only do through libgcc routines.
extern "C" float canary_scale(float x, float y) { return x * y; }
extern "C" unsigned canary_divide(unsigned a, unsigned b) { return a / b; }
