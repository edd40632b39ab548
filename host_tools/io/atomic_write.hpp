// Writing an output file so that nothing is lost and nothing is left half
// done: check_output_file() first; then a temporary file beside the target
// (same folder, so the rename stays on one file system), written in full,
// fsync'ed, the target checked again, and renamed over it. Readers see the old
// file or the new one, never a part; on any failure (a full disk included) the
// temporary is removed and the target is as it was.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string_view>

#include <sys/types.h>
#include <unistd.h>

#include "io/output_check.hpp"

namespace spanlight::io {

// The system calls a write goes through: a seam, so tests can make one of them
// fail (a full disk, an fsync error) where no real file system would.
struct SystemCalls {
  ssize_t (*write)(int fd, const void* data, std::size_t size) = ::write;
  int (*fsync)(int fd) = ::fsync;
  int (*rename)(const char* from, const char* to) = ::rename;
};

// Writes `bytes` to `file` (through a symlink: the file it names) or throws
// OutputError ("FILE: OPTION: expected ..., got ..."). Several processes may
// write one file at once: each has its own temporary, the last rename wins.
void write_file_atomically(const std::filesystem::path& file, std::string_view bytes, std::string_view option,
                           const RunInputs& inputs, const SystemCalls& calls = {});

}  // namespace spanlight::io
