#include "assets.hpp"

#include "bear.hpp"
#include "obj_text.hpp"
#include "terrain.hpp"
#include "textures.hpp"
#include "torus_knot.hpp"

namespace spanlight::mesh_generator {

namespace {

MeshAsset mesh_asset(const std::filesystem::path& path, const std::string& what, IndexedMesh mesh) {
  const std::string header = path.filename().string() + ": " + what + "\n" + std::to_string(mesh.positions.size()) +
                             " positions, " + std::to_string(mesh.uvs.size()) + " uvs, " +
                             std::to_string(mesh.faces.size()) + " triangles\n" +
                             "Written by tools/mesh_generator: cmake --build build --target regenerate_mesh_assets";
  std::string obj = obj_text(mesh, header);
  return {path, std::move(mesh), std::move(obj)};
}

}  // namespace

Assets generated_assets() {
  Assets assets;
  assets.meshes.push_back(mesh_asset("assets/meshes/bear.obj", "a knitted teddy bear (scenes/mesh_bear.json)", bear_body()));
  assets.meshes.push_back(mesh_asset("assets/meshes/bear_buttons.obj", "the bear's eyes and nose", bear_buttons()));
  assets.meshes.push_back(mesh_asset("checks/assets/torus_knot.obj", "a (2, 3) torus knot (check scene)", torus_knot()));
  assets.meshes.push_back(mesh_asset("checks/assets/terrain.obj", "a terrain patch (check scene)", terrain()));
  assets.textures.push_back({"assets/textures/knit.png", knit_texture()});
  assets.textures.push_back({"checks/assets/tiles.png", tile_texture()});
  assets.textures.push_back({"checks/assets/grass.png", grass_texture()});
  return assets;
}

}  // namespace spanlight::mesh_generator
