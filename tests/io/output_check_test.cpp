// io::check_output_file: an output may be a new name in an existing folder or
// a regular file that is none of the run's inputs, however it is spelled.
#include <string>

#include <catch2/catch.hpp>

#include "io/output_check.hpp"
#include "scratch_folder.hpp"
#include "test_files.hpp"

using spanlight::io::check_output_file;
using spanlight::io::OutputError;
using spanlight::io::RunInputs;
using spanlight::scene::test::ScratchFolder;
namespace fs = std::filesystem;
namespace test = spanlight::io::test;

namespace {

// The OutputError's message, or "" when the output is accepted.
std::string refusal(const fs::path& out, const RunInputs& inputs = {}) {
  return test::message_of<OutputError>([&] { check_output_file(out, "--out", inputs); });
}

}  // namespace

TEST_CASE("a new name in an existing folder and an existing regular file may be written", "[io][output]") {
  const ScratchFolder folder;
  CHECK(refusal(folder.path() / "new.png").empty());
  CHECK(refusal(folder.write("old.png", "x")).empty());
}

TEST_CASE("devices, FIFOs, sockets and folders are refused, named by kind", "[io][output]") {
  const ScratchFolder folder;
  CHECK(refusal("/dev/null") == "/dev/null: --out: expected a regular file or a new name, got a character device (left as it is)");
  CHECK(refusal("/dev/full").find("got a character device") != std::string::npos);
  CHECK(test::is_character_device("/dev/full"));
  REQUIRE(test::make_fifo(folder.path() / "fifo"));
  CHECK(refusal(folder.path() / "fifo").find("got a FIFO") != std::string::npos);
  REQUIRE(test::make_socket(folder.path() / "socket"));
  CHECK(refusal(folder.path() / "socket").find("got a socket") != std::string::npos);
  CHECK(refusal(folder.path()).find("got a folder") != std::string::npos);
}

TEST_CASE("a missing folder, a dangling symlink and a symlink loop are refused", "[io][output]") {
  const ScratchFolder folder;
  CHECK(refusal(folder.path() / "no_folder" / "out.png").find("expected an existing folder") != std::string::npos);
  const auto file = folder.write("file", "x");
  CHECK(refusal(file / "out.png").find("got a regular file") != std::string::npos);  // a file is no folder
  fs::create_symlink("nothing", folder.path() / "dangling");
  CHECK(refusal(folder.path() / "dangling").find("got a symlink to no file") != std::string::npos);
  fs::create_symlink("loop_b", folder.path() / "loop_a");
  fs::create_symlink("loop_a", folder.path() / "loop_b");
  CHECK(refusal(folder.path() / "loop_a").find("got a symlink loop") != std::string::npos);
}

TEST_CASE("an input is refused under any spelling, through symlinks and hard links", "[io][output]") {
  const ScratchFolder folder;
  fs::create_directory(folder.path() / "a");
  const auto scene = folder.write("scene.json", "{}");
  const auto texture = folder.write("a/wood.png", "png");
  const RunInputs inputs{scene, texture, folder.path() / "not_there.obj"};

  CHECK(refusal(scene, inputs) ==
        scene.string() + ": --out: expected a file that is not one of this run's inputs, got the same file as the input " +
            scene.string());
  CHECK(!refusal(folder.path() / "a" / ".." / "scene.json", inputs).empty());
  CHECK(!refusal(folder.path() / "." / "a" / "wood.png", inputs).empty());
  fs::create_symlink(texture, folder.path() / "link.png");
  CHECK(!refusal(folder.path() / "link.png", inputs).empty());
  fs::create_hard_link(scene, folder.path() / "hard.json");
  CHECK(!refusal(folder.path() / "hard.json", inputs).empty());
  // A copy is another file, and a missing input is no file at all.
  fs::copy_file(scene, folder.path() / "copy.json");
  CHECK(refusal(folder.path() / "copy.json", inputs).empty());
  CHECK(refusal(folder.path() / "not_there.obj", inputs).empty());
}
