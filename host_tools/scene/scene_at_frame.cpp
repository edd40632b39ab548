// scene_at_frame: a scene with the poses of one frame of its animation.
#include <cmath>
#include <stdexcept>
#include <string>

#include "scene/animation.hpp"

namespace spanlight::scene {
namespace {

// Q15.16 to double: exact.
glm::dvec3 to_glm(const fixedpoint::Vec3Q16& v) {
  return {std::ldexp(static_cast<double>(v.x), -16), std::ldexp(static_cast<double>(v.y), -16), std::ldexp(static_cast<double>(v.z), -16)};
}

template <typename View>
void pose(View& view, const AnimatedView& animated, std::uint32_t frame, std::uint32_t frame_count) {
  const fixedpoint::ViewPose p = fixedpoint::pose_at_frame(animated.track(), frame, frame_count);
  view.eye = to_glm(p.eye);
  view.target = to_glm(p.target);
  view.up = to_glm(p.up);
  view.fovy_deg = fixedpoint::degrees(p.fovy);
}

}  // namespace

Scene scene_at_frame(const Scene& scene, const Animation& animation, std::uint32_t frame) {
  if (frame >= animation.frame_count || animation.projectors.size() != scene.projectors.size()) {
    throw std::out_of_range("scene_at_frame: frame " + std::to_string(frame) + " of an animation of " +
                            std::to_string(animation.frame_count) + " frames, or an animation of another scene");
  }
  Scene out = scene;
  pose(out.camera, animation.camera, frame, animation.frame_count);
  for (std::size_t j = 0; j < out.projectors.size(); ++j) pose(out.projectors[j], animation.projectors[j], frame, animation.frame_count);
  return out;
}

}  // namespace spanlight::scene
