// A fresh temporary folder for files a test writes (scenes, OBJ files,
// images), removed with everything in it when the test ends. Unique per
// process, since ctest runs test cases in parallel processes.
#pragma once

#include <filesystem>
#include <string_view>

namespace spanlight::scene::test {

class ScratchFolder {
 public:
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // Writes text to path()/name and returns that path.
  std::filesystem::path write(std::string_view name, std::string_view text) const;

 private:
  std::filesystem::path path_;
};

}  // namespace spanlight::scene::test
