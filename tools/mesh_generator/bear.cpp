#include "bear.hpp"

#include "body_part.hpp"

namespace spanlight::mesh_generator {

namespace {

// World length one repeat of the 256-texel knit covers: on the bear as framed in
// scenes/mesh_bear.json about one texel a pixel, as a character's own texture is.
constexpr double knit_size = 1.2;

const glm::dvec3 back{0, 0, -1}, below{0, -1, 0}, inward{-1, 0, 0};

// The part as it is, and mirrored to the bear's other side (x -> -x).
void add_pair(IndexedMesh& mesh, BodyPart part) {
  append(mesh, body_part(part));
  part.from.x = -part.from.x;
  part.to.x = -part.to.x;
  part.seam_side.x = -part.seam_side.x;
  append(mesh, body_part(part));
}

}  // namespace

IndexedMesh bear_body() {
  IndexedMesh mesh;
  // body: pear-shaped, wider at the bottom, the seam down its back
  append(mesh, body_part({.from = {0, 0.03, 0}, .to = {0, 0.80, 0}, .seam_side = back, .radius_seam_side = 0.30,
                          .radius_sideways = 0.36, .roundness = 0.8, .taper = 0.75, .rings = 13, .segments = 22,
                          .texture_size = knit_size, .v_offset = 0.0}));
  // head
  append(mesh, body_part({.from = {0, 0.72, 0}, .to = {0, 1.26, 0}, .seam_side = back, .radius_seam_side = 0.25,
                          .radius_sideways = 0.29, .roundness = 0.95, .taper = 1.0, .rings = 12, .segments = 22,
                          .texture_size = knit_size, .v_offset = 0.55}));
  // snout, seam underneath
  append(mesh, body_part({.from = {0, 0.93, 0.10}, .to = {0, 0.91, 0.37}, .seam_side = below, .radius_seam_side = 0.085,
                          .radius_sideways = 0.105, .roundness = 0.85, .taper = 0.9, .rings = 6, .segments = 12,
                          .texture_size = knit_size, .v_offset = 0.1}));
  // ears: thick discs facing forward, tilted outward
  add_pair(mesh, {.from = {0.20, 1.19, -0.05}, .to = {0.205, 1.20, 0.03}, .seam_side = below, .radius_seam_side = 0.085,
                  .radius_sideways = 0.09, .roundness = 0.7, .taper = 1.0, .rings = 4, .segments = 10,
                  .texture_size = knit_size, .v_offset = 0.6});
  // arms: shoulder to paw, reaching forward, paws a little thicker; seam on the inside
  add_pair(mesh, {.from = {0.22, 0.68, 0.0}, .to = {0.46, 0.34, 0.16}, .seam_side = inward, .radius_seam_side = 0.10,
                  .radius_sideways = 0.10, .roundness = 0.6, .taper = 1.15, .rings = 8, .segments = 12,
                  .texture_size = knit_size, .v_offset = 0.2});
  // legs: hip to foot, stretched out in front, seam underneath
  add_pair(mesh, {.from = {0.15, 0.15, -0.04}, .to = {0.30, 0.13, 0.44}, .seam_side = below, .radius_seam_side = 0.125,
                  .radius_sideways = 0.125, .roundness = 0.6, .taper = 1.15, .rings = 8, .segments = 12,
                  .texture_size = knit_size, .v_offset = 0.4});
  return mesh;
}

IndexedMesh bear_buttons() {
  IndexedMesh mesh;
  // eyes: small spheres half sunk into the head
  add_pair(mesh, {.from = {0.095, 1.04, 0.20}, .to = {0.095, 1.04, 0.26}, .seam_side = below, .radius_seam_side = 0.03,
                  .radius_sideways = 0.03, .roundness = 1.0, .taper = 1.0, .rings = 4, .segments = 8,
                  .texture_size = 0.2, .v_offset = 0.0});
  // nose: a flattened ball on the tip of the snout
  append(mesh, body_part({.from = {0, 0.935, 0.325}, .to = {0, 0.95, 0.385}, .seam_side = below, .radius_seam_side = 0.03,
                          .radius_sideways = 0.045, .roundness = 0.9, .taper = 1.0, .rings = 5, .segments = 10,
                          .texture_size = 0.2, .v_offset = 0.0}));
  return mesh;
}

}  // namespace spanlight::mesh_generator
