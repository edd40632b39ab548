// io::write_file_atomically: the whole file or nothing. Failures of write,
// fsync and rename are injected through io::SystemCalls (a full disk where no
// real disk is full); tests/io/full_disk.sh fills a real one.
#include <algorithm>
#include <cerrno>
#include <string>

#include <catch2/catch.hpp>

#include "io/atomic_write.hpp"
#include "scratch_folder.hpp"
#include "test_files.hpp"

using spanlight::io::OutputError;
using spanlight::io::RunInputs;
using spanlight::io::SystemCalls;
using spanlight::io::write_file_atomically;
using spanlight::scene::test::ScratchFolder;
namespace fs = std::filesystem;
namespace test = spanlight::io::test;

namespace {

const std::string previous = "an earlier output, to be kept whole on any failure";

// Write calls succeed with at most `chunk` bytes each until `budget` bytes are
// written, then fail with ENOSPC: a disk with `budget` bytes free.
thread_local std::size_t budget = 0;
thread_local std::size_t chunk = 0;
ssize_t limited_write(int fd, const void* data, std::size_t size) {
  if (budget == 0) {
    errno = ENOSPC;
    return -1;
  }
  const std::size_t n = std::min({size, chunk, budget});
  budget -= n;
  return ::write(fd, data, n);
}
int failing_fsync(int) {
  errno = EIO;
  return -1;
}
int failing_rename(const char*, const char*) {
  errno = EXDEV;
  return -1;
}

std::string failure(const fs::path& file, const std::string& bytes, const SystemCalls& calls) {
  return test::message_of<OutputError>([&] { write_file_atomically(file, bytes, "--out", {}, calls); });
}

}  // namespace

TEST_CASE("a write replaces the file whole and leaves nothing else", "[io][write]") {
  const ScratchFolder folder;
  const auto out = folder.path() / "out.bin";
  std::string bytes(100000, 'a');
  bytes[5] = '\0';
  write_file_atomically(out, bytes, "--out", {});
  CHECK(test::contents(out) == bytes);
  write_file_atomically(out, "short", "--out", {});
  CHECK(test::contents(out) == "short");
  CHECK(test::entries(folder.path()) == std::vector<std::string>{"out.bin"});
}

TEST_CASE("short writes are continued until every byte is written", "[io][write]") {
  const ScratchFolder folder;
  budget = 1 << 20;
  chunk = 7;
  SystemCalls calls;
  calls.write = limited_write;
  const std::string bytes(10000, 'b');
  write_file_atomically(folder.path() / "out", bytes, "--out", {}, calls);
  CHECK(test::contents(folder.path() / "out") == bytes);
}

TEST_CASE("a full disk, an fsync error or a failed rename leave the old file and no temporary", "[io][write]") {
  const ScratchFolder folder;
  const auto out = folder.write("out.png", previous);
  const std::string bytes(50000, 'c');
  SystemCalls calls;
  std::string message;
  SECTION("the disk fills after 4096 bytes") {
    budget = 4096;
    chunk = 1000;
    calls.write = limited_write;
    message = failure(out, bytes, calls);
    CHECK(message == out.string() + ": --out: expected to write 50000 bytes, got No space left on device (nothing written)");
  }
  SECTION("the disk is full from the start") {
    budget = 0;
    calls.write = limited_write;
    message = failure(out, bytes, calls);
    CHECK(message.find("No space left on device") != std::string::npos);
  }
  SECTION("fsync fails") {
    calls.fsync = failing_fsync;
    message = failure(out, bytes, calls);
    CHECK(message.find("to disk, got Input/output error") != std::string::npos);
  }
  SECTION("rename fails") {
    calls.rename = failing_rename;
    message = failure(out, bytes, calls);
    CHECK(message.find("expected to rename") != std::string::npos);
  }
  CHECK(!message.empty());
  CHECK(test::contents(out) == previous);
  CHECK(test::entries(folder.path()) == std::vector<std::string>{"out.png"});
}

TEST_CASE("a failed first write leaves no file at all", "[io][write]") {
  const ScratchFolder folder;
  budget = 100;
  chunk = 100;
  SystemCalls calls;
  calls.write = limited_write;
  CHECK(!failure(folder.path() / "new.png", std::string(1000, 'd'), calls).empty());
  CHECK(test::entries(folder.path()).empty());
}

TEST_CASE("refused outputs are left as they are", "[io][write]") {
  const ScratchFolder folder;
  const auto input = folder.write("scene.json", previous);
  CHECK_THROWS_AS(write_file_atomically(input, "x", "--out", RunInputs{input}), OutputError);
  CHECK(test::contents(input) == previous);
  REQUIRE(test::make_fifo(folder.path() / "fifo"));
  CHECK_THROWS_AS(write_file_atomically(folder.path() / "fifo", "x", "--out", {}), OutputError);
  CHECK(fs::is_fifo(folder.path() / "fifo"));
  CHECK_THROWS_AS(write_file_atomically("/dev/null", "x", "--out", {}), OutputError);
  CHECK(test::is_character_device("/dev/null"));
  CHECK(test::entries(folder.path()) == std::vector<std::string>{"fifo", "scene.json"});
}

TEST_CASE("writing through a symlink replaces the file it names and keeps the link", "[io][write]") {
  const ScratchFolder folder;
  fs::create_directory(folder.path() / "real");
  const auto target = folder.write("real/out.png", previous);
  fs::create_symlink("real/out.png", folder.path() / "link.png");
  write_file_atomically(folder.path() / "link.png", "new", "--out", {});
  CHECK(fs::is_symlink(folder.path() / "link.png"));
  CHECK(test::contents(target) == "new");
  CHECK(test::entries(folder.path() / "real") == std::vector<std::string>{"out.png"});
}
