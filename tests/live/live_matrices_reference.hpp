// The bound a frame's run-time matrices must meet against GLM on that frame's scene
// (scene_at_frame: the animation's poses, exact as doubles; near, far and a projector's
// aspect as the firmware holds them, in Q15.16; each model as its Mat4Block), entry by
// entry, from the builders' derived bounds (tests/fixedpoint/pose_reference.hpp):
//   clip   = block(P * (V * M)):        expected_perspective, expected_view_times,
//                                       expected_product, expected_block
//   light  = block(P_j * (V_j * M)):    the same with the projector's view and frustum
//   texture = block(B * (P_j * (V_j * M))): B is exact, one more product and block.
// Nothing is tuned: each term is a rounding or approximation bound stated in a header.
#pragma once

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "pose_reference.hpp"
#include "scene/scene.hpp"
#include "spanlight/pose.hpp"

namespace live_test {

namespace pr = pose_reference;

// GLM's matrix and the bound of one chain P * (V * M) (and, with `biased`, B times it),
// for the pipeline block `built`. The intermediate Mat4s are rebuilt here with the same
// calls build_frame_matrices makes, for their exponents (the bounds depend on them).
inline pr::Expected expected_chain(const spanlight::CameraPose& c, const spanlight::Mat4Block& model,
                                   const spanlight::Mat4Block& built, bool biased) {
  using namespace fixedpoint;
  const Mat4 m = mat4(model);
  const View view = look_at(c.view.eye, c.view.target, c.view.up);
  const Mat4 vm = view * m;
  const Mat4 p = perspective(c.view.fovy, c.aspect, c.near, c.far);
  const Mat4 pvm = p * vm;
  const pr::Expected e_vm = pr::expected_view_times(c.view.eye, c.view.target, c.view.up, pr::exact(model), vm);
  const pr::Expected e_p = pr::expected_perspective(c.view.fovy, c.aspect, c.near, c.far, p);
  const pr::Expected e_pvm = pr::expected_product(e_p, e_vm, p, vm, pvm);
  if (!biased) return pr::expected_block(e_pvm, built);
  const Mat4 b = bias();
  return pr::expected_block(pr::expected_product(pr::expected_bias(), e_pvm, b, pvm, b * pvm), built);
}

// GLM on the frame's scene itself: P * V * M as prepare builds it in double, from the
// scene's own fields (camera or projector), with near, far and aspect in Q15.16.
inline glm::dmat4 glm_view_projection(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up,
                                      double fovy_deg, double aspect, double near, double far) {
  const auto q = [](double v) { return std::ldexp(std::round(std::ldexp(v, 16)), -16); };
  return glm::perspective(glm::radians(fovy_deg), aspect, q(near), q(far)) * glm::lookAt(eye, target, up);
}

}  // namespace live_test
