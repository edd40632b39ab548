// io::read_regular_file opens only regular files within their size limit;
// everything else is refused before a byte is read, without blocking.
#include <string>

#include <catch2/catch.hpp>

#include "io/read_file.hpp"
#include "scratch_folder.hpp"
#include "test_files.hpp"

using spanlight::io::read_regular_file;
using spanlight::io::ReadError;
using spanlight::scene::test::ScratchFolder;
namespace test = spanlight::io::test;

namespace {

// The message of the ReadError read_regular_file throws, or "" when it reads.
std::string refusal(const std::filesystem::path& file, std::uintmax_t max_bytes = 1024) {
  try {
    read_regular_file(file, "scene file", max_bytes);
  } catch (const ReadError& e) {
    CHECK(std::string(e.what()) == file.string() + ": " + e.expected());
    return e.expected();
  }
  return "";
}

}  // namespace

TEST_CASE("a regular file is read whole, an empty one as empty", "[io][read]") {
  const ScratchFolder folder;
  std::string bytes(3000, 'x');
  bytes[1234] = '\0';  // binary content survives
  CHECK(read_regular_file(folder.write("a.bin", bytes), "file", 3000) == bytes);
  CHECK(read_regular_file(folder.write("empty", ""), "file", 10).empty());
}

TEST_CASE("what is not a regular file is refused by kind, without blocking", "[io][read]") {
  const ScratchFolder folder;
  CHECK(refusal(folder.path() / "missing.json") == "expected an existing scene file, got no such file");
  CHECK(refusal(folder.path()) == "expected a regular file as a scene file, got a folder");
  CHECK(refusal("/dev/zero") == "expected a regular file as a scene file, got a character device");
  CHECK(refusal("/dev/urandom") == "expected a regular file as a scene file, got a character device");
  REQUIRE(test::make_fifo(folder.path() / "fifo"));
  CHECK(refusal(folder.path() / "fifo") == "expected a regular file as a scene file, got a FIFO");  // would block if opened
  REQUIRE(test::make_socket(folder.path() / "socket"));
  CHECK(refusal(folder.path() / "socket") == "expected a regular file as a scene file, got a socket");
}

TEST_CASE("symlinks are followed, a loop and a dangling link are refused", "[io][read]") {
  const ScratchFolder folder;
  folder.write("target", "content");
  std::filesystem::create_symlink("target", folder.path() / "link");
  CHECK(read_regular_file(folder.path() / "link", "file", 100) == "content");
  std::filesystem::create_symlink("loop_b", folder.path() / "loop_a");
  std::filesystem::create_symlink("loop_a", folder.path() / "loop_b");
  CHECK(refusal(folder.path() / "loop_a") == "expected a readable scene file, got a symlink loop");
  std::filesystem::create_symlink("nothing", folder.path() / "dangling");
  CHECK(refusal(folder.path() / "dangling") == "expected an existing scene file, got no such file");
}

TEST_CASE("a file over the limit is refused by its size, before it is read", "[io][read]") {
  const ScratchFolder folder;
  const auto file = folder.write("big", std::string(2 * 1024 * 1024 + 1, ' '));
  CHECK(refusal(file, 2 * 1024 * 1024) ==
        "expected a scene file of at most 2097152 bytes (2.0 MiB), got 2097153 bytes (2.0 MiB)");
  CHECK(read_regular_file(file, "file", 2 * 1024 * 1024 + 1).size() == 2 * 1024 * 1024 + 1);
  CHECK(spanlight::io::with_article("OBJ file") == "an OBJ file");
  CHECK(spanlight::io::with_article("image file") == "an image file");
  CHECK(spanlight::io::with_article("scene file") == "a scene file");
}
