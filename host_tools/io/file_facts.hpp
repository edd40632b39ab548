// What is at a path, as the system sees it (stat), for the checks before a
// file is read or written: its kind, its identity (device and inode, the same
// for every spelling, symlink and hard link of one file) and its size.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include <sys/stat.h>

namespace spanlight::io {

struct FileIdentity {
  std::uint64_t device = 0;
  std::uint64_t inode = 0;
  friend bool operator==(const FileIdentity&, const FileIdentity&) = default;
};

enum class FileKind {
  missing,
  regular,
  folder,
  character_device,
  block_device,
  fifo,
  socket,
  symlink,        // only from lstat: the link itself
  symlink_loop,   // ELOOP: too many links to follow
  inaccessible,   // any other error (permission denied on a folder on the way, ...)
};

struct FileFacts {
  FileKind kind = FileKind::missing;
  FileIdentity identity;
  std::uintmax_t size = 0;
  int error = 0;  // errno when kind is missing, symlink_loop or inaccessible
};

FileFacts facts_of(const struct stat& status);
// What a failed stat, lstat or open says about the path, from its errno.
FileFacts facts_of_error(int error);
// stat(): symlinks followed.
FileFacts look_at(const std::filesystem::path& path);
// lstat(): a symlink is reported as one.
FileFacts look_at_link(const std::filesystem::path& path);

// "no such file", "a regular file", "a character device", "a FIFO", ... for messages.
std::string describe(const FileFacts& facts);

}  // namespace spanlight::io
