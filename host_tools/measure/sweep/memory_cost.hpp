// Memory a grid point needs:
//   table bytes   the span reciprocal's table (2^(B+1) bytes of 16-bit entries)
//                 plus the vertex divide's own table (project.hpp), once
//   buffer bytes  colour + depth (2 bytes a pixel at 16 bits, 4 at 24) + shadow
//                 maps at the same depth size + the tie mask (multipass only)
//                 + the vertex buffer (max_vertex_count CachedVertex entries)
//   flash         the pipeline's code and tables in the sweep_bench ELF for that
//                 point's reciprocal: symbols of the spanlight and fixedpoint
//                 namespaces shared by all instantiations, plus the ones
//                 instantiated for its Features (table bits, Newton), plus the
//                 libgcc arithmetic helpers. Scene data, the HAL, the bench's own
//                 code, start-up and newlib are not counted.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "spanlight/knobs.hpp"
#include "spanlight/scene.hpp"

namespace spanlight::sweep {

std::size_t table_bytes(int table_bits);
std::size_t buffer_bytes(const PreparedScene& scene, const Knobs& knobs);

struct PipelineFlash {
  std::size_t shared = 0;  // every instantiation uses these
  std::map<std::pair<int, int>, std::size_t> instantiation;  // (table bits, Newton) -> bytes
  std::map<int, std::size_t> table;                           // reciprocal_table<B> bytes (span or vertex)
  std::optional<std::size_t> for_knobs(const Knobs& knobs) const;
};

// Reads the symbol sizes with `nm -C -S`; nullopt when the tool or the ELF fails.
std::optional<PipelineFlash> pipeline_flash(const std::filesystem::path& elf, const std::string& nm = "arm-none-eabi-nm");

// One demangled symbol name classified: "shared", "instantiation" (table_bits and
// newton set from its Features), "table" (table_bits set), or "" (not the pipeline's).
std::string classify_symbol(const std::string& demangled, int& table_bits, int& newton);

}  // namespace spanlight::sweep
