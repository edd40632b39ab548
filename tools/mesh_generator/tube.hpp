// A tube: rings of vertices along a path, each ring joined to the next by two
// triangles per segment. Every model here is made of tubes: a body part is a
// tube closed by a pole at each end, a torus knot a tube whose last ring joins
// its first. Faces are counter-clockwise seen from outside the tube.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "indexed_mesh.hpp"

namespace spanlight::mesh_generator {

// Position j of `segments` is centre + cos(a) radius_across across + sin(a) radius_around around,
// a = 360 degrees * j / segments: an ellipse. The tube runs along across x around.
struct Ring {
  glm::dvec3 centre;
  glm::dvec3 across;  // unit, perpendicular to the path
  glm::dvec3 around;  // unit, perpendicular to the path and to `across`
  double radius_across = 0.0;
  double radius_around = 0.0;
  double v = 0.0;  // texture coordinate along the tube
};

// The single position that closes a tube's end.
struct Pole {
  glm::dvec3 position;
  double v = 0.0;
};

// Texture coordinate u runs from 0 to u_repeats around every ring, so a ring's first
// position has two uvs (u = 0 and u = u_repeats): the seam. A pole has one uv per
// triangle around it, u at the triangle's middle, as an exported UV sphere has.
IndexedMesh capped_tube(const std::vector<Ring>& rings, Pole start, Pole end, int segments, int u_repeats);

// The last ring joins the first; that last band's far uvs have v = v_closing (the
// seam along the tube: a whole number of texture repeats away from the first ring's v
// keeps a repeating texture continuous across it).
IndexedMesh looped_tube(const std::vector<Ring>& rings, double v_closing, int segments, int u_repeats);

}  // namespace spanlight::mesh_generator
