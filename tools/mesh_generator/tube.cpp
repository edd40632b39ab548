#include "tube.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>

namespace spanlight::mesh_generator {

namespace {

using Index = std::uint32_t;

Index next_index(std::size_t size) { return static_cast<Index>(size); }

// Adds the ring's positions; returns the index of the first.
Index add_ring(IndexedMesh& mesh, const Ring& ring, int segments) {
  const Index first = next_index(mesh.positions.size());
  for (int j = 0; j < segments; ++j) {
    const double angle = 2.0 * std::numbers::pi * j / segments;
    mesh.positions.push_back(ring.centre + std::cos(angle) * ring.radius_across * ring.across +
                             std::sin(angle) * ring.radius_around * ring.around);
  }
  return first;
}

// segments + 1 uvs at height v, u from 0 to u_repeats; returns the index of the first.
Index add_uv_row(IndexedMesh& mesh, double v, int segments, int u_repeats) {
  const Index first = next_index(mesh.uvs.size());
  for (int j = 0; j <= segments; ++j) mesh.uvs.push_back({static_cast<double>(u_repeats) * j / segments, v});
  return first;
}

// Two triangles per segment between ring `a` (uv row `ua`) and the next ring `b` (uv row `ub`).
// Outward and counter-clockwise: from a_j the corners step around first (a_j+1), then along.
void add_band(IndexedMesh& mesh, Index a, Index ua, Index b, Index ub, int segments) {
  const auto n = static_cast<Index>(segments);
  for (Index j = 0; j < n; ++j) {
    const Index k = (j + 1) % n;  // the position after j around the ring; its uv is j + 1, past the seam
    const Corner a0{a + j, ua + j}, a1{a + k, ua + j + 1}, b0{b + j, ub + j}, b1{b + k, ub + j + 1};
    mesh.faces.push_back({a0, a1, b1});
    mesh.faces.push_back({a0, b1, b0});
  }
}

}  // namespace

IndexedMesh capped_tube(const std::vector<Ring>& rings, Pole start, Pole end, int segments, int u_repeats) {
  IndexedMesh mesh;
  const auto n = static_cast<Index>(segments);
  const Index start_position = next_index(mesh.positions.size());
  mesh.positions.push_back(start.position);
  const Index start_uvs = next_index(mesh.uvs.size());
  for (Index j = 0; j < n; ++j) mesh.uvs.push_back({u_repeats * (j + 0.5) / segments, start.v});

  Index previous = 0, previous_uvs = 0;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    const Index ring = add_ring(mesh, rings[i], segments);
    const Index ring_uvs = add_uv_row(mesh, rings[i].v, segments, u_repeats);
    if (i == 0) {
      for (Index j = 0; j < n; ++j) {
        mesh.faces.push_back({Corner{start_position, start_uvs + j}, Corner{ring + (j + 1) % n, ring_uvs + j + 1},
                              Corner{ring + j, ring_uvs + j}});
      }
    } else {
      add_band(mesh, previous, previous_uvs, ring, ring_uvs, segments);
    }
    previous = ring;
    previous_uvs = ring_uvs;
  }

  const Index end_position = next_index(mesh.positions.size());
  mesh.positions.push_back(end.position);
  const Index end_uvs = next_index(mesh.uvs.size());
  for (Index j = 0; j < n; ++j) mesh.uvs.push_back({u_repeats * (j + 0.5) / segments, end.v});
  for (Index j = 0; j < n; ++j) {
    mesh.faces.push_back({Corner{previous + j, previous_uvs + j}, Corner{previous + (j + 1) % n, previous_uvs + j + 1},
                          Corner{end_position, end_uvs + j}});
  }
  return mesh;
}

IndexedMesh looped_tube(const std::vector<Ring>& rings, double v_closing, int segments, int u_repeats) {
  IndexedMesh mesh;
  std::vector<Index> ring_positions, ring_uvs;
  for (const Ring& ring : rings) {
    ring_positions.push_back(add_ring(mesh, ring, segments));
    ring_uvs.push_back(add_uv_row(mesh, ring.v, segments, u_repeats));
  }
  const Index closing_uvs = add_uv_row(mesh, v_closing, segments, u_repeats);
  for (std::size_t i = 0; i < rings.size(); ++i) {
    const bool last = i + 1 == rings.size();
    add_band(mesh, ring_positions[i], ring_uvs[i], ring_positions[last ? 0 : i + 1], last ? closing_uvs : ring_uvs[i + 1],
             segments);
  }
  return mesh;
}

}  // namespace spanlight::mesh_generator
