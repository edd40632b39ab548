#include "file_checks.hpp"

#include <string>
#include <system_error>

#include "scene/scene.hpp"

namespace spanlight::scene::detail {

void require_regular_file(const std::filesystem::path& file, std::string_view field, std::string_view kind) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  const std::string expected = "expected an existing " + std::string(kind);
  if (!std::filesystem::exists(status)) {
    throw SceneError(file.string(), std::string(field), expected + ", got no such file");
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw SceneError(file.string(), std::string(field), expected + ", got something that is not a regular file");
  }
}

}  // namespace spanlight::scene::detail
