#include "bake/write_atomically.hpp"

#include <fstream>
#include <stdexcept>

namespace spanlight::bake {

void write_atomically(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path temp = file.string() + ".partial";
  {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    if (!out.flush()) {
      std::error_code ignored;
      std::filesystem::remove(temp, ignored);
      throw std::runtime_error(file.string() + ": cannot write");
    }
  }
  std::filesystem::rename(temp, file);
}

}  // namespace spanlight::bake
