// The depfile of a bake (`spanlight bake --depfile FILE`): one rule in Makefile syntax, which
// Ninja and Make (and CMake's DEPFILE) read, naming what the baked sources were made from:
//   OUT/baked_scene.cpp OUT/baked_config.hpp: SCENE IMAGE... OBJ...
// so a build bakes again when one of those files changes, and for nothing else.
#pragma once

#include <filesystem>
#include <string>
#include <vector>


namespace spanlight::bake {

// "targets: inputs" with every path made absolute and escaped for Make (space, '#', '$'), one
// input per line. Throws std::invalid_argument for a path with a line break: the syntax has none.
std::string depfile_text(const std::vector<std::filesystem::path>& targets,
                         const std::vector<std::filesystem::path>& inputs);

// Why `depfile` may not be written, as "expected ..." for a FILE: FIELD: message; empty when it
// may. It must be a new or regular file, and none of the bake's inputs or outputs.
std::string depfile_refusal(const std::filesystem::path& depfile, const std::vector<std::filesystem::path>& inputs,
                            const std::vector<std::filesystem::path>& outputs);

}  // namespace spanlight::bake
