#include "io/file_facts.hpp"

#include <cerrno>
#include <cstring>

namespace spanlight::io {
namespace {

FileKind kind_of(mode_t mode) {
  if (S_ISREG(mode)) return FileKind::regular;
  if (S_ISDIR(mode)) return FileKind::folder;
  if (S_ISCHR(mode)) return FileKind::character_device;
  if (S_ISBLK(mode)) return FileKind::block_device;
  if (S_ISFIFO(mode)) return FileKind::fifo;
  if (S_ISSOCK(mode)) return FileKind::socket;
  return FileKind::symlink;  // S_ISLNK, the only kind left
}

}  // namespace

FileFacts facts_of(const struct stat& status) {
  FileFacts facts;
  facts.kind = kind_of(status.st_mode);
  facts.identity = {static_cast<std::uint64_t>(status.st_dev), static_cast<std::uint64_t>(status.st_ino)};
  facts.size = static_cast<std::uintmax_t>(status.st_size);
  return facts;
}

FileFacts facts_of_error(int error) {
  FileFacts facts;
  facts.error = error;
  facts.kind = error == ENOENT || error == ENOTDIR ? FileKind::missing
               : error == ELOOP                    ? FileKind::symlink_loop
                                                   : FileKind::inaccessible;
  return facts;
}

FileFacts look_at(const std::filesystem::path& path) {
  struct stat status {};
  return ::stat(path.c_str(), &status) == 0 ? facts_of(status) : facts_of_error(errno);
}

FileFacts look_at_link(const std::filesystem::path& path) {
  struct stat status {};
  return ::lstat(path.c_str(), &status) == 0 ? facts_of(status) : facts_of_error(errno);
}

std::string describe(const FileFacts& facts) {
  switch (facts.kind) {
    case FileKind::missing: return "no such file";
    case FileKind::regular: return "a regular file";
    case FileKind::folder: return "a folder";
    case FileKind::character_device: return "a character device";
    case FileKind::block_device: return "a block device";
    case FileKind::fifo: return "a FIFO";
    case FileKind::socket: return "a socket";
    case FileKind::symlink: return "a symlink";
    case FileKind::symlink_loop: return "a symlink loop";
    case FileKind::inaccessible: return std::string("an error: ") + std::strerror(facts.error);
  }
  return "an unknown kind of file";
}

}  // namespace spanlight::io
