#include "startup_probe.hpp"

#include <cstdint>

namespace spanlight::selftest {
namespace {

constexpr std::uint32_t kDataValue = 0x5EED1234u;

// volatile: the compiler must keep real reads of these objects instead of folding in the
// values it knows they were initialised with.
volatile std::uint32_t data_word = kDataValue;  // lands in .data: needs the flash-to-RAM copy
volatile std::uint32_t bss_word;                // lands in .bss: needs the zeroing

// A dynamic initialiser (it reads a volatile), so it runs from .init_array at start-up.
struct ConstructorProbe {
  ConstructorProbe() : seen_data(data_word) {}
  std::uint32_t seen_data;
};
ConstructorProbe probe;

}  // namespace

bool startup_state_ok() { return data_word == kDataValue && bss_word == 0u && probe.seen_data == kDataValue; }

}  // namespace spanlight::selftest
