// The scene's fixed parts: framebuffer size, camera.
#include "scene_readers.hpp"

namespace spanlight::scene::detail {
namespace {

constexpr int max_output_side = 4096;

}  // namespace

void read_output(const JsonField& output, Scene& scene) {
  output.expect_object_with_fields({"width", "height"});
  scene.width = static_cast<int>(output.required("width").integer(1, max_output_side));
  scene.height = static_cast<int>(output.required("height").integer(1, max_output_side));
}

Camera read_camera(const JsonField& camera) {
  camera.expect_object_with_fields({"eye", "target", "up", "fovy_deg", "near", "far"});
  const ViewVolume view = read_view_volume(camera);
  return Camera{view.eye, view.target, view.up, view.fovy_deg, view.near, view.far};
}

}  // namespace spanlight::scene::detail
