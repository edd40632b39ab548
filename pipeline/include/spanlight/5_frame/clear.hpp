// Stage 5, the clears: every pixel's colour and depth (and each shadow map) set once a frame
// before the passes draw. On Arm the words go out by store-multiples, two of four registers
// a round of eight words: 0.06 instruction a byte, where newlib's memset (built for size)
// takes about 0.6. Elsewhere the C library and plain loops do it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace spanlight {

#if defined(__arm__)
// `rounds` rounds of eight words from the word-aligned `at` set to `value`; returns the end.
// Assembly, so the words may belong to objects of any type.
[[gnu::noinline]] inline void* store_word_rounds(void* at, std::size_t rounds, std::uint32_t value) {
  register std::uint32_t a asm("r2") = value, b asm("r3") = value, c asm("r4") = value, d asm("r5") = value;
  for (; rounds > 0; --rounds)
    asm volatile("stmia %0!, {%1, %2, %3, %4}\n\tstmia %0!, {%1, %2, %3, %4}" : "+l"(at) : "r"(a), "r"(b), "r"(c), "r"(d) : "memory");
  return at;
}
#endif

// n bytes from `at` set to `value`.
inline void fill_bytes(void* at, std::size_t n, std::uint8_t value) {
#if defined(__arm__)
  auto* p = static_cast<std::uint8_t*>(at);
  for (; n > 0 && (reinterpret_cast<std::uintptr_t>(p) & 3u) != 0; --n) *p++ = value;
  p = static_cast<std::uint8_t*>(store_word_rounds(p, n / 32, value * 0x01010101u));
  for (std::size_t k = 0; k < n % 32; ++k) p[k] = value;
#else
  std::memset(at, value, n);
#endif
}

// n stored depths set to the clear value: bytes of 0xFF where it fills a 16-bit type (16-bit
// depth), words otherwise.
template <typename DepthT>
inline void clear_depth(DepthT* depth, std::size_t n, std::uint32_t clear) {
  if (sizeof(DepthT) == 2 && clear == 0xFFFFu) return fill_bytes(depth, n * 2, 0xFF);
  std::size_t i = 0;
#if defined(__arm__)
  if constexpr (sizeof(DepthT) == 4) {
    store_word_rounds(depth, n / 8, clear);
    i = n & ~std::size_t{7};
  }
#endif
  for (; i < n; ++i) depth[i] = static_cast<DepthT>(clear);
}

}  // namespace spanlight
