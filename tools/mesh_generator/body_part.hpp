// A rounded body part: a closed tube from one pole to the other whose outline
// is an ellipse (roundness 1, an ellipsoid) or, with smaller roundness, a box
// with rounded ends (about 0.6 reads as a capsule). Rings are spaced evenly in
// the outline's angle, so they crowd toward the poles as on a UV sphere.
#pragma once

#include <glm/glm.hpp>

#include "indexed_mesh.hpp"

namespace spanlight::mesh_generator {

struct BodyPart {
  glm::dvec3 from, to;  // the two poles
  glm::dvec3 seam_side;  // the uv seam runs along the side this direction points to
  double radius_seam_side = 0.0;  // half-widths at the widest: toward the seam side,
  double radius_sideways = 0.0;   // and perpendicular to it
  double roundness = 1.0;         // exponent of the outline: |cos|^e along, |sin|^e across
  double taper = 1.0;             // radius near `to` relative to near `from`
  int rings = 8;                  // between the poles
  int segments = 12;              // around
  double texture_size = 1.0;      // world length one texture repeat covers
  double v_offset = 0.0;          // v at `from`
};

// rings * segments + 2 positions, 2 * rings * segments triangles; u repeats a whole
// number of times around (at least once), v grows with the length along the surface.
IndexedMesh body_part(const BodyPart& part);

}  // namespace spanlight::mesh_generator
