// Reading a whole input file, safely: only a regular file is opened for its
// contents (a device such as /dev/zero, a FIFO or a socket would block or never
// end), its size is checked against a limit before a byte is read, and the
// descriptor is checked again after opening, so a file swapped in between is
// caught too.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace spanlight::io {

// what() is "FILE: expected ..., got ..."; expected() the part after "FILE: ",
// for callers that put more in between (a scene: the field).
class ReadError : public std::runtime_error {
 public:
  ReadError(const std::filesystem::path& file, std::string expected)
      : std::runtime_error(file.string() + ": " + expected), expected_(std::move(expected)) {}
  const std::string& expected() const { return expected_; }

 private:
  std::string expected_;
};

inline constexpr std::uintmax_t mebibyte = std::uintmax_t{1} << 20;

// The contents of `file`, at most max_bytes long. `kind` names it in messages
// ("scene file", "OBJ file"). Throws ReadError.
std::string read_regular_file(const std::filesystem::path& file, std::string_view kind, std::uintmax_t max_bytes);

// "a scene file", "an OBJ file": the kind with its article.
std::string with_article(std::string_view kind);

}  // namespace spanlight::io
