// The two functions the QEMU instruction-count plugin watches (tools/qemu_icount): it counts
// every instruction executed from entering spanlight_measure_begin to entering
// spanlight_measure_end. They must stay real, distinct, out-of-line functions:
// noipa = noinline + noclone + no identical-code folding (two empty bodies would otherwise be
// merged into one address), and extern "C" gives the runner stable names to look up with nm.
// Each body is the single instruction `bx lr`, which keeps the fixed overhead of a region at
// two instructions (this return and the call into the end marker).
extern "C" {

__attribute__((noipa, used)) void spanlight_measure_begin() { __asm__ volatile("" ::: "memory"); }

__attribute__((noipa, used)) void spanlight_measure_end() { __asm__ volatile("" ::: "memory"); }

}
