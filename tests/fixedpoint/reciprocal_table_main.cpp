// spanlight_reciprocal_table: prints, as Markdown, the measured maximum relative
// error of fixedpoint::reciprocal for each table size and Newton step count,
// next to the proven bound. Its output is pasted into docs/reciprocal.md.
#include <cmath>
#include <cstdio>

#include "reciprocal_error.hpp"

namespace {

using namespace reciprocal_error;

constexpr std::uint32_t seed = 20240601u;  // the same samples as test_reciprocal.cpp
constexpr std::uint32_t random_count = 1u << 20;

template <int B, int Steps>
void print_row() {
  Stats s32 = exhaustive_u16<B, Steps>();
  s32.merge(random_u32<B, Steps>(seed, random_count));
  const Stats s64 = random_u64<B, Steps>(seed + 1, random_count);
  const long double bound = bound_u32(B, Steps);
  std::printf("| %2d | %4d | %d | %.3Le | %7.2Lf | %.3Le | %7.2Lf | %10llu | %.3Le | %.3Le |\n", B, 2 << B, Steps,
              s32.max_error, std::log2(s32.max_error), bound, std::log2(bound),
              static_cast<unsigned long long>(s32.worst_d), s64.max_error, bound_u64(B, Steps));
}

template <int B>
void print_table_size() {
  print_row<B, 0>();
  print_row<B, 1>();
  print_row<B, 2>();
}

}  // namespace

int main() {
  std::printf("| B | table bytes | Newton steps | max rel. error, 32-bit d | log2 | proven bound | log2 | worst d "
              "| max rel. error, 64-bit d | bound, 64-bit d |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  print_table_size<6>();
  print_table_size<8>();
  print_table_size<10>();
  print_table_size<12>();
  std::printf("\n32-bit d: all of [1, 65535] plus %u std::mt19937(%u) draws over [1, 2^32). "
              "64-bit d: %u draws with a uniform bit length in [1, 64] (seed %u).\n",
              random_count, seed, random_count, seed + 1);
  return 0;
}
