// io::OutputFolder: a command writes into a folder that is new, empty or its
// own (every file listed in the manifest); anything else is refused unless
// forced, and nothing but its own earlier files is ever removed.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "io/output_folder.hpp"
#include "scratch_folder.hpp"
#include "test_files.hpp"

using spanlight::io::OutputError;
using spanlight::io::OutputFolder;
using spanlight::io::RunInputs;
using spanlight::scene::test::ScratchFolder;
namespace fs = std::filesystem;
namespace test = spanlight::io::test;
using Names = std::vector<std::string>;

namespace {

const std::string manifest(OutputFolder::manifest_name);

std::string refusal(const fs::path& dir, bool force = false, const RunInputs& inputs = {}) {
  return test::message_of<OutputError>([&] { OutputFolder folder(dir, "--out", force, inputs); });
}

}  // namespace

TEST_CASE("a new folder is created at the first write, with its manifest", "[io][folder]") {
  const ScratchFolder scratch;
  const auto dir = scratch.path() / "new" / "out";
  OutputFolder folder(dir, "--out", false, {});
  CHECK_FALSE(fs::exists(dir));  // a refused or failed run leaves no folder
  folder.write("a.txt", "A");
  folder.write("images/1.png", "P");
  CHECK(folder.has_written("images/1.png"));
  CHECK(test::entries(dir) == Names{manifest, "a.txt", "images"});
  CHECK(test::contents(dir / manifest).find("\na.txt\nimages/1.png\n") != std::string::npos);
}

TEST_CASE("running again into its own folder works and replaces its files", "[io][folder]") {
  const ScratchFolder scratch;
  const auto dir = scratch.path() / "out";
  OutputFolder(dir, "--out", false, {}).write("a.txt", "first");
  OutputFolder again(dir, "--out", false, {});
  again.write("a.txt", "second");
  CHECK(test::contents(dir / "a.txt") == "second");
}

TEST_CASE("a folder holding other files is refused, naming them - --force writes and removes none", "[io][folder]") {
  const ScratchFolder scratch;
  const auto dir = scratch.path() / "out";
  OutputFolder(dir, "--out", false, {}).write("a.txt", "ours");
  scratch.write("out/notes.md", "the user's");
  const std::string message = refusal(dir);
  CHECK(message.find("--out: expected a new or empty folder") != std::string::npos);
  CHECK(message.find("got 1 other file(s): notes.md") != std::string::npos);

  OutputFolder forced(dir, "--out", true, {});
  forced.write("a.txt", "again");
  CHECK(test::contents(dir / "notes.md") == "the user's");
  CHECK(refusal(dir).find("notes.md") != std::string::npos);  // still not ours
}

TEST_CASE("an empty folder is fine, a file given as the folder is refused", "[io][folder]") {
  const ScratchFolder scratch;
  fs::create_directory(scratch.path() / "empty");
  CHECK(refusal(scratch.path() / "empty").empty());
  const auto file = scratch.write("file", "x");
  CHECK(refusal(file).find("expected a folder or a new name, got a regular file") != std::string::npos);
  CHECK(refusal(file / "sub").find("got a regular file at " + file.string()) != std::string::npos);
  CHECK(refusal("/dev/null").find("got a character device") != std::string::npos);
}

TEST_CASE("only this command's earlier files are removed, never the user's", "[io][folder]") {
  const ScratchFolder scratch;
  const auto dir = scratch.path() / "out";
  {
    OutputFolder first(dir, "--out", false, {});
    first.write("images/1.png", "old");
    first.write("images/2.png", "old");
  }
  OutputFolder second(dir, "--out", false, {});
  second.write("images/2.png", "new");
  second.remove_earlier_files_under("images");
  CHECK(test::entries(dir / "images") == Names{"2.png"});
  CHECK(test::contents(dir / manifest).find("images/1.png") == std::string::npos);
}

TEST_CASE("a planted manifest grants nothing outside the folder", "[io][folder]") {
  const ScratchFolder scratch;
  const auto dir = scratch.path() / "out";
  const auto outside = scratch.write("precious.txt", "keep me");
  fs::create_directories(dir);
  fs::create_directory(scratch.path() / "elsewhere");
  scratch.write("elsewhere/x.png", "keep me too");
  fs::create_directory_symlink(scratch.path() / "elsewhere", dir / "images");
  scratch.write("out/" + manifest, "../precious.txt\n/etc/passwd\nimages/x.png\n");
  // The symlink is not the command's file: refused.
  CHECK(refusal(dir).find("other file(s): images") != std::string::npos);
  OutputFolder forced(dir, "--out", true, {});
  forced.remove_earlier_files_under("images");
  forced.remove_earlier_files_under("..");
  CHECK(test::contents(outside) == "keep me");
  CHECK(test::contents(scratch.path() / "elsewhere" / "x.png") == "keep me too");
  CHECK_THROWS_AS(forced.write("../escape.txt", "x"), OutputError);
  CHECK_FALSE(fs::exists(scratch.path() / "escape.txt"));
}

TEST_CASE("a file of the folder that is one of the run's inputs is not written", "[io][folder]") {
  const ScratchFolder scratch;
  const auto dir = scratch.path() / "out";
  OutputFolder(dir, "--out", false, {}).write("sweep.csv", "ours");
  fs::remove(dir / "sweep.csv");
  const auto scene = scratch.write("scene.json", "{}");
  fs::create_hard_link(scene, dir / "sweep.csv");  // listed, but now the scene itself
  OutputFolder folder(dir, "--out", true, RunInputs{scene});
  CHECK_THROWS_AS(folder.write("sweep.csv", "overwrite"), OutputError);
  CHECK(test::contents(scene) == "{}");
}
