#include "io/read_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

#include "io/file_facts.hpp"

namespace spanlight::io {
namespace {

// "52428800 bytes (50.0 MiB)": exact, and readable.
std::string size_text(std::uintmax_t bytes) {
  char mib[32] = "";
  if (bytes >= mebibyte) std::snprintf(mib, sizeof mib, " (%.1f MiB)", static_cast<double>(bytes) / static_cast<double>(mebibyte));
  return std::to_string(bytes) + " bytes" + mib;
}

// The checks on what is there, shared by the look before opening and the look at the open descriptor.
void require_readable_regular(const std::filesystem::path& file, const FileFacts& facts, std::string_view kind,
                              std::uintmax_t max_bytes) {
  if (facts.kind == FileKind::missing) throw ReadError(file, "expected an existing " + std::string(kind) + ", got no such file");
  if (facts.kind == FileKind::symlink_loop || facts.kind == FileKind::inaccessible) {
    throw ReadError(file, "expected a readable " + std::string(kind) + ", got " + describe(facts));
  }
  if (facts.kind != FileKind::regular) {
    throw ReadError(file, "expected a regular file as " + with_article(kind) + ", got " + describe(facts));
  }
  if (facts.size > max_bytes) {
    throw ReadError(file, "expected " + with_article(kind) + " of at most " + size_text(max_bytes) + ", got " +
                    size_text(facts.size));
  }
}

class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

std::string with_article(std::string_view kind) {
  const bool vowel = !kind.empty() && std::strchr("AEIOUaeiou", kind.front()) != nullptr;
  return (vowel ? "an " : "a ") + std::string(kind);
}

std::string read_regular_file(const std::filesystem::path& file, std::string_view kind, std::uintmax_t max_bytes) {
  // Look first: opening a device or a FIFO can block or have effects of its own.
  require_readable_regular(file, look_at(file), kind, max_bytes);
  // O_NONBLOCK: should a FIFO have been put there since, open returns at once
  // (and fstat below refuses it) instead of waiting for a writer.
  const Descriptor fd(::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
  if (fd.get() < 0) require_readable_regular(file, facts_of_error(errno), kind, max_bytes);  // throws: an error is never a regular file
  struct stat status {};
  const FileFacts opened = ::fstat(fd.get(), &status) == 0 ? facts_of(status) : facts_of_error(errno);
  require_readable_regular(file, opened, kind, max_bytes);

  std::string bytes(static_cast<std::size_t>(opened.size), '\0');
  std::size_t have = 0;
  for (;;) {
    if (have == bytes.size()) bytes.resize(have + 65536);  // room to see whether the file grew since fstat
    const ssize_t got = ::read(fd.get(), bytes.data() + have, bytes.size() - have);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw ReadError(file, "expected a readable " + std::string(kind) + ", got a read error: " + std::strerror(errno));
    if (got == 0) break;
    have += static_cast<std::size_t>(got);
    if (have > max_bytes) {
      throw ReadError(file, "expected " + with_article(kind) + " of at most " + size_text(max_bytes) + ", got one growing past it");
    }
  }
  bytes.resize(have);
  return bytes;
}

}  // namespace spanlight::io
