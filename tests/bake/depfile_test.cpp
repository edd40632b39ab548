// `spanlight bake --depfile`: which files a bake lists, how it writes them, and which depfile
// names it refuses (host_tools/bake/depfile.hpp).
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "bake/depfile.hpp"
#include "scene/scene_files.hpp"
#include "scene/scene.hpp"

namespace fs = std::filesystem;
using spanlight::bake::depfile_refusal;
using spanlight::bake::depfile_text;
using spanlight::scene::files_read;

namespace {

const fs::path assets = fs::path(SPANLIGHT_SOURCE_DIR) / "scenes" / "assets";

// A fresh folder under the system's temporary folder, removed at the end of the test.
struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("spanlight-depfile-" + std::to_string(::getpid()));
  Scratch() {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
};

void write_text(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

fs::path normal(const fs::path& file) { return fs::absolute(file).lexically_normal(); }

std::vector<fs::path> normal(const std::vector<fs::path>& files) {
  std::vector<fs::path> out;
  for (const fs::path& file : files) out.push_back(normal(file));
  return out;
}

}  // namespace

TEST_CASE("files_read lists the scene, each image and each OBJ file once, inline meshes none") {
  Scratch scratch;
  fs::copy_file(assets / "textures" / "checker.png", scratch.dir / "checker.png");
  fs::copy_file(assets / "meshes" / "plane.obj", scratch.dir / "plane.obj");
  fs::copy_file(assets / "textures" / "brick.png", scratch.dir / "unused.png");  // never named
  // Two textures share one image; two objects share one OBJ; one object is inline.
  const fs::path scene_file = scratch.dir / "scene.json";
  write_text(scene_file, R"({
    "spanlight_scene": 1, "output": { "width": 8, "height": 8 },
    "camera": { "eye": [0, 2, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 60, "near": 0.1, "far": 20 },
    "textures": { "a": { "image": "checker.png" }, "b": { "image": "./checker.png", "filter": "nearest" } },
    "objects": [
      { "mesh": "plane.obj", "texture": "a" },
      { "mesh": "plane.obj", "texture": "b", "transform": { "translate": [0, 1, 0] } },
      { "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]] } ] })");

  const std::vector<fs::path> files = normal(files_read(spanlight::scene::load_scene(scene_file)));
  CHECK(files == normal({scene_file, scratch.dir / "checker.png", scratch.dir / "plane.obj"}));
}

TEST_CASE("depfile_text writes one Make rule with absolute paths, escaping space, '#' and '$'") {
  const fs::path out = "/build/baked";
  const std::string text = depfile_text({out / "baked_scene.cpp", out / "baked_config.hpp"},
                                        {"/scenes/my room.json", "/scenes/tex#1.png", "/scenes/$price.obj"});
  CHECK(text ==
        "/build/baked/baked_scene.cpp /build/baked/baked_config.hpp: \\\n"
        "  /scenes/my\\ room.json \\\n"
        "  /scenes/tex\\#1.png \\\n"
        "  /scenes/$$price.obj\n");

  const std::string relative = depfile_text({"out.cpp"}, {"scene.json"});
  CHECK(relative == normal("out.cpp").string() + ": \\\n  " + normal("scene.json").string() + "\n");
}

TEST_CASE("depfile_text refuses a file name with a line break, which Make cannot spell") {
  CHECK_THROWS_AS(depfile_text({"/out.cpp"}, {"/scenes/two\nlines.json"}), std::invalid_argument);
}

TEST_CASE("depfile_refusal: a new or regular file, never an input, an output, a directory or a FIFO") {
  Scratch scratch;
  const fs::path scene = scratch.dir / "scene.json";
  const fs::path output = scratch.dir / "baked_scene.cpp";
  write_text(scene, "{}");
  write_text(output, "");
  const std::vector<fs::path> inputs{scene};
  const std::vector<fs::path> outputs{output};

  CHECK(depfile_refusal(scratch.dir / "baked.d", inputs, outputs).empty());
  write_text(scratch.dir / "old.d", "old");
  CHECK(depfile_refusal(scratch.dir / "old.d", inputs, outputs).empty());

  CHECK(depfile_refusal(scene, inputs, outputs).find("other than the bake's inputs") != std::string::npos);
  // The same file under another spelling.
  CHECK(depfile_refusal(scratch.dir / "." / "scene.json", inputs, outputs).find("inputs") != std::string::npos);
  CHECK(depfile_refusal(output, inputs, outputs).find("other than the baked sources") != std::string::npos);
  CHECK(depfile_refusal(scratch.dir, inputs, outputs).find("a directory") != std::string::npos);
  const fs::path fifo = scratch.dir / "fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(depfile_refusal(fifo, inputs, outputs).find("FIFO") != std::string::npos);
}
