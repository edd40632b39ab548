// Writing an output file whole or not at all: through a temporary file and a rename.
#pragma once

#include <filesystem>
#include <string>

namespace spanlight::bake {

// Writes text to file through file.partial and a rename. Throws std::runtime_error naming the
// file when it cannot be written (the temporary file is removed).
void write_atomically(const std::filesystem::path& file, const std::string& text);

}  // namespace spanlight::bake
