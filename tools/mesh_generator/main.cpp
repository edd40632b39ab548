// mesh_generator SCENES_FOLDER: writes the generated models and their textures
// (assets.hpp) under SCENES_FOLDER, normally the repository's scenes/.
//   cmake --build build --target regenerate_mesh_assets
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "assets.hpp"
#include "compare/compare.hpp"

namespace fs = std::filesystem;
using namespace spanlight::mesh_generator;

namespace {

// Through a temporary beside the file and a rename, as PNGs are written: a reader
// never sees half a file, and a failure leaves none.
bool write_text_atomically(const fs::path& path, const std::string& text, std::string& error) {
  const fs::path temporary = path.parent_path() / ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()));
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out.flush()) {
      error = path.string() + ": cannot write " + temporary.string();
      std::error_code ignored;
      fs::remove(temporary, ignored);
      return false;
    }
  }
  std::error_code renamed;
  fs::rename(temporary, path, renamed);
  if (renamed) {
    error = path.string() + ": " + renamed.message();
    std::error_code ignored;
    fs::remove(temporary, ignored);
    return false;
  }
  return true;
}

bool make_parent(const fs::path& path, std::string& error) {
  std::error_code made;
  fs::create_directories(path.parent_path(), made);
  if (made) error = path.parent_path().string() + ": " + made.message();
  return !made;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes spanlight's generated mesh assets (OBJ models and PNG textures) under SCENES_FOLDER."};
  fs::path scenes_folder;
  app.add_option("scenes_folder", scenes_folder, "the scenes/ folder of the repository")->required()->check(CLI::ExistingDirectory);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  const Assets assets = generated_assets();
  std::string error;
  for (const MeshAsset& mesh : assets.meshes) {
    const fs::path path = scenes_folder / mesh.path;
    if (!make_parent(path, error) || !write_text_atomically(path, mesh.obj, error)) {
      std::fprintf(stderr, "mesh_generator: %s\n", error.c_str());
      return 1;
    }
    std::printf("%s: %zu triangles, %zu positions, %zu uvs\n", path.string().c_str(), mesh.mesh.faces.size(),
                mesh.mesh.positions.size(), mesh.mesh.uvs.size());
  }
  for (const TextureAsset& texture : assets.textures) {
    const fs::path path = scenes_folder / texture.path;
    if (!make_parent(path, error) ||
        !spanlight::compare::write_png_atomically(path, texture.image.width, texture.image.height, texture.image.rgb, &error)) {
      std::fprintf(stderr, "mesh_generator: %s\n", error.c_str());
      return 1;
    }
    std::printf("%s: %d x %d\n", path.string().c_str(), texture.image.width, texture.image.height);
  }
  return 0;
}
