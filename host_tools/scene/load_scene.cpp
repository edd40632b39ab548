#include "scene/scene.hpp"

#include "json_document.hpp"
#include "json_field.hpp"
#include "scene_readers.hpp"

namespace spanlight::scene {

Scene load_scene(const std::filesystem::path& file) {
  const detail::Json document = detail::read_json_document(file);
  const detail::JsonField root(document, "", file);
  if (!document.is_object()) root.fail("expected a JSON object");
  // The version first: a file of another version may well have other fields.
  const int version = detail::read_version(root);
  root.expect_object_with_fields(
      {"spanlight_scene", "name", "output", "camera", "ambient", "textures", "objects", "projectors"});

  Scene scene;
  scene.file = file;
  scene.version = version;
  scene.name = root.has("name") ? root.required("name").string() : file.stem().string();
  detail::read_output(root.required("output"), scene);
  scene.camera = detail::read_camera(root.required("camera"));
  if (const auto ambient = root.optional("ambient")) scene.ambient = ambient->vec3(detail::closed_interval(0.0, 1.0));
  if (const auto textures = root.optional("textures")) scene.textures = detail::read_textures(*textures, version);
  if (const auto objects = root.optional("objects")) scene.objects = detail::read_objects(*objects, scene.textures, version);
  if (const auto projectors = root.optional("projectors")) {
    scene.projectors = detail::read_projectors(*projectors, scene.textures, version);
  }
  return scene;
}

}  // namespace spanlight::scene
