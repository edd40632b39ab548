// Every file the generator writes, by its path under scenes/: the one list both
// the generator (main.cpp) and the test that the committed files are up to date
// (tests/meshes/) read.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "indexed_mesh.hpp"
#include "rgb_image.hpp"

namespace spanlight::mesh_generator {

struct MeshAsset {
  std::filesystem::path path;  // relative to scenes/
  IndexedMesh mesh;
  std::string obj;  // the file's text: obj_text(mesh, a header naming the generator)
};

struct TextureAsset {
  std::filesystem::path path;  // relative to scenes/, a PNG
  RgbImage image;
};

struct Assets {
  std::vector<MeshAsset> meshes;
  std::vector<TextureAsset> textures;
};

Assets generated_assets();

}  // namespace spanlight::mesh_generator
