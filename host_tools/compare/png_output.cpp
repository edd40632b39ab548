#include <atomic>
#include <string>
#include <system_error>

#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include "compare/compare.hpp"

namespace spanlight::compare {

namespace {

// A name no other writer uses at the same time: hidden, beside the target, with
// the process id and a per-process counter.
std::filesystem::path temporary_beside(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::string name = ".";  // appended piecewise: "." + string trips GCC 12's -Wrestrict false positive
  name += target.filename().string();
  name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return target.parent_path() / name;
}

bool fail(std::string* error, const std::string& why) {
  if (error) *error = why;
  return false;
}

}  // namespace

bool write_png_atomically(const std::filesystem::path& path, int width, int height,
                          std::span<const std::uint8_t> rgb8, std::string* error) {
  const auto expected = static_cast<std::size_t>(width > 0 ? width : 0) * static_cast<std::size_t>(height > 0 ? height : 0) * 3;
  if (width <= 0 || height <= 0 || rgb8.size() != expected) {
    return fail(error, path.string() + ": RGB8 buffer does not hold a " + std::to_string(width) + " x " +
                           std::to_string(height) + " image");
  }
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ignored;
  if (!std::filesystem::is_directory(folder, ignored)) {
    return fail(error, path.string() + ": folder " + folder.string() + " does not exist");
  }
  const std::filesystem::path temporary = temporary_beside(path);

  auto output = OIIO::ImageOutput::create("png");  // by format name: the temporary has no .png ending
  if (!output) return fail(error, "no PNG writer: " + OIIO::geterror());
  const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  if (!output->open(temporary.string(), spec)) {
    std::filesystem::remove(temporary, ignored);  // in case the writer created it before failing
    return fail(error, path.string() + ": " + output->geterror());
  }
  const bool written = output->write_image(OIIO::TypeDesc::UINT8, rgb8.data());
  const bool closed = output->close();
  if (!written || !closed) {
    const std::string why = output->geterror();
    std::filesystem::remove(temporary, ignored);
    return fail(error, path.string() + ": " + why);
  }

  std::error_code renamed;
  std::filesystem::rename(temporary, path, renamed);  // atomic within one file system
  if (renamed) {
    std::filesystem::remove(temporary, ignored);
    return fail(error, path.string() + ": " + renamed.message());
  }
  return true;
}

}  // namespace spanlight::compare
