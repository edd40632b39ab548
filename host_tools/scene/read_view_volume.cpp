// eye/target/up/fovy_deg/near/far, shared by the camera and the projectors,
// with the checks that keep lookAt and perspective well defined.
#include <cmath>

#include <glm/geometric.hpp>

#include "json_describe.hpp"
#include "scene_readers.hpp"

namespace spanlight::scene::detail {
namespace {

// lookAt normalises cross(target - eye, up), so it must not vanish. An up
// within ~1e-6 radians of the view direction is surely a mistake, and it
// would leave the camera's roll to rounding, so it is refused too.
constexpr double min_sine_view_to_up = 1e-6;

void check_view_frame(const JsonField& owner, const ViewVolume& view) {
  const glm::dvec3 direction = view.target - view.eye;
  if (glm::length(direction) == 0.0) {
    owner.required("target").fail_with("expected a point other than eye, got the same point " + format_vec3(view.target));
  }
  const JsonField up = owner.required("up");
  if (glm::length(view.up) == 0.0) up.fail_with("expected a non-zero direction, got " + format_vec3(view.up));
  const double sine = glm::length(glm::cross(glm::normalize(direction), glm::normalize(view.up)));
  if (!(sine >= min_sine_view_to_up)) {
    up.fail_with("expected a direction not parallel to the view direction target - eye = " + format_vec3(direction) +
                 ", got " + format_vec3(view.up));
  }
}

}  // namespace

ViewVolume read_view_volume(const JsonField& owner) {
  ViewVolume view;
  view.eye = owner.required("eye").vec3();
  view.target = owner.required("target").vec3();
  view.up = owner.required("up").vec3();
  check_view_frame(owner, view);
  view.fovy_deg = owner.required("fovy_deg").number(open_interval(0.0, 180.0));
  view.near = owner.required("near").number(greater_than(0.0));
  view.far = owner.required("far").number(greater_than_field(view.near, "near"));
  return view;
}

}  // namespace spanlight::scene::detail
