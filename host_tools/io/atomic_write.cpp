#include "io/atomic_write.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

#include <fcntl.h>

namespace spanlight::io {
namespace {

std::filesystem::path folder_of(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

// A symlink is written through: the file it names is replaced, the link kept
// (as a shell's `>` does). check_output_file() has made sure that file exists.
std::filesystem::path write_target(const std::filesystem::path& file) {
  if (look_at_link(file).kind != FileKind::symlink) return file;
  std::error_code error;
  const auto resolved = std::filesystem::canonical(file, error);
  return error ? file : resolved;
}

// Created with O_EXCL under a name no other writer uses: hidden, beside the
// target, with the process id and a per-process counter.
class Temporary {
 public:
  explicit Temporary(const std::filesystem::path& target) {
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
      std::string name = ".";  // appended piecewise: "." + string trips GCC 12's -Wrestrict false positive
      name += target.filename().string();
      name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
      path_ = folder_of(target) / name;
      fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);  // umask applies
      if (fd_ < 0 && errno != EEXIST) break;
    }
    if (fd_ < 0) error_ = errno;
  }
  ~Temporary() {
    close();
    if (!renamed_ && error_ == 0) ::unlink(path_.c_str());
  }
  Temporary(const Temporary&) = delete;
  Temporary& operator=(const Temporary&) = delete;

  int fd() const { return fd_; }
  int open_error() const { return error_; }
  const std::filesystem::path& path() const { return path_; }
  int close() {
    const int result = fd_ >= 0 ? ::close(fd_) : 0;
    fd_ = -1;
    return result;
  }
  void mark_renamed() { renamed_ = true; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  int error_ = 0;
  bool renamed_ = false;
};

// Loops over short writes; false with errno set on an error.
bool write_all(int fd, std::string_view bytes, const SystemCalls& calls) {
  while (!bytes.empty()) {
    const ssize_t written = calls.write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) return false;
    if (written == 0) {  // no progress and no error: treat as a full device
      errno = ENOSPC;
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
  return true;
}

// The rename is durable once the folder is on disk too; a failure here loses
// nothing the user had, so it is not an error.
void sync_folder(const std::filesystem::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void write_file_atomically(const std::filesystem::path& file, std::string_view bytes, std::string_view option,
                           const RunInputs& inputs, const SystemCalls& calls) {
  check_output_file(file, option, inputs);
  const std::filesystem::path target = write_target(file);
  const std::string size = std::to_string(bytes.size()) + " bytes";
  // `error` is the errno of the call that failed, read before anything else can change it.
  const auto fail = [&](const std::string& what, int error) {
    throw OutputError(file, option, "expected to " + what + ", got " + std::strerror(error) + " (nothing written)");
  };

  Temporary temporary(target);
  if (temporary.fd() < 0) fail("create a file in " + folder_of(target).string(), temporary.open_error());
  if (!write_all(temporary.fd(), bytes, calls)) {
    const int error = errno;
    fail("write " + size, error);
  }
  if (calls.fsync(temporary.fd()) != 0) {
    const int error = errno;
    fail("write " + size + " to disk", error);
  }
  if (temporary.close() != 0) {
    const int error = errno;
    fail("write " + size, error);
  }
  // Again, right before the rename: the path may have become a device or an input meanwhile.
  check_output_file(file, option, inputs);
  if (calls.rename(temporary.path().c_str(), target.c_str()) != 0) {
    const int error = errno;
    fail("rename " + temporary.path().string() + " over it", error);
  }
  temporary.mark_renamed();
  sync_folder(folder_of(target));
}

}  // namespace spanlight::io
