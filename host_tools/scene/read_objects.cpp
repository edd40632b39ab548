// objects[]: geometry (an OBJ file or inline arrays), surface and transform.
#include <array>
#include <optional>

#include "file_checks.hpp"
#include "obj_mesh.hpp"
#include "scene_readers.hpp"

namespace spanlight::scene::detail {
namespace {

constexpr std::array<std::string_view, 3> inline_mesh_fields = {"positions", "uvs", "triangles"};

Mesh read_geometry(const JsonField& object) {
  if (object.has("mesh")) {
    for (const std::string_view field : inline_mesh_fields) {
      if (object.has(field)) {
        object.fail_member(field, "expected either mesh or inline positions/uvs/triangles, got both mesh and " +
                                      std::string(field));
      }
    }
    const JsonField mesh = object.required("mesh");
    const auto obj_file = resolve_against_scene(object.file(), mesh.string());
    return load_asset(object.file(), [&] { return load_obj_mesh(obj_file, mesh.path()); });
  }
  if (!object.has("positions")) object.fail_with("expected a mesh or inline positions and triangles, got neither");
  return read_inline_mesh(object);
}

// Spec: texgen replaces given uvs, so it is an error beside inline uvs (it overrides an OBJ's vt).
std::optional<Texgen> read_texgen_of(const JsonField& object) {
  const auto texgen = object.optional("texgen");
  if (!texgen) return std::nullopt;
  if (object.has("uvs")) {
    texgen->fail_with("expected either texgen or inline uvs, got both: texgen generates the uvs");
  }
  return read_texgen(*texgen);
}

Object read_object(const JsonField& object, std::size_t index, const std::vector<Texture>& textures, int version) {
  object.expect_object_with_fields(
      {"name", "mesh", "positions", "uvs", "triangles", "color", "texture", "cull", "transform", "texgen"});
  refuse_version_2_fields(object, version, {"texgen"});
  Object loaded;
  // The spec gives objects no default name; the field path is unique and findable.
  loaded.name = object.has("name") ? object.required("name").string() : "objects[" + std::to_string(index) + "]";
  loaded.mesh = read_geometry(object);
  if (const auto color = object.optional("color")) loaded.color = color->vec3(closed_interval(0.0, 1.0));
  if (const auto texture = object.optional("texture")) loaded.texture = find_texture(*texture, textures);
  if (const auto cull = object.optional("cull")) loaded.cull = cull->choice<Cull>({{"none", Cull::none}, {"back", Cull::back}});
  if (const auto transform = object.optional("transform")) loaded.model = read_transform(*transform);
  loaded.texgen = read_texgen_of(object);
  return loaded;
}

}  // namespace

std::vector<Object> read_objects(const JsonField& objects, const std::vector<Texture>& textures, int version) {
  std::vector<Object> loaded;
  const auto elements = objects.elements();
  for (std::size_t i = 0; i < elements.size(); ++i) loaded.push_back(read_object(elements[i], i, textures, version));
  return loaded;
}

}  // namespace spanlight::scene::detail
