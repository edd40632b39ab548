// Deliberately allocates and throws: the compiled object must make check_no_heap.sh fail,
// which proves the check can see what it looks for. Compiled only, never linked or run.
#include <cstdlib>

// Returned, so the compiler cannot drop the allocations.
void* canary_malloc() { return std::malloc(16); }

int* canary_new() { return new int(7); }

void canary_throw() { throw 42; }
