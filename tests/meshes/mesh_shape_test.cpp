// The generated models are built as exported models are: indexed (each position
// shared by the triangles around it), closed where they should be, every face
// counter-clockwise seen from outside, and uv seams where the texture wraps.
#include <catch2/catch.hpp>

#include <map>
#include <vector>
#include <string>
#include <utility>

#include "assets.hpp"

namespace mg = spanlight::mesh_generator;

namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;  // from, to: position indices in a face's order

std::map<Edge, int> directed_edges(const mg::IndexedMesh& mesh) {
  std::map<Edge, int> edges;
  for (const mg::Face& face : mesh.faces) {
    for (std::size_t k = 0; k < 3; ++k) ++edges[{face[k].position, face[(k + 1) % 3].position}];
  }
  return edges;
}

// Closed and consistently oriented: every edge is walked once each way, by two faces.
bool closed_and_consistent(const mg::IndexedMesh& mesh) {
  const std::map<Edge, int> edges = directed_edges(mesh);
  for (const auto& [edge, count] : edges) {
    const auto reverse = edges.find({edge.second, edge.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1) return false;
  }
  return true;
}

// The connected pieces of a mesh (faces joined through shared positions): the root
// position of each face's piece, by union-find.
std::vector<std::uint32_t> piece_of_each_face(const mg::IndexedMesh& mesh) {
  std::vector<std::uint32_t> parent(mesh.positions.size());
  for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  const auto root = [&](std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const mg::Face& face : mesh.faces) {
    parent[root(face[1].position)] = root(face[0].position);
    parent[root(face[2].position)] = root(face[0].position);
  }
  std::vector<std::uint32_t> pieces;
  for (const mg::Face& face : mesh.faces) pieces.push_back(root(face[0].position));
  return pieces;
}

// Six times the volume each closed piece encloses (divergence theorem): positive when
// its faces turn counter-clockwise seen from outside, the front faces facing out.
// Per piece, so one part turned inside out cannot hide behind the others' volume.
std::map<std::uint32_t, double> six_volume_of_each_piece(const mg::IndexedMesh& mesh) {
  const std::vector<std::uint32_t> pieces = piece_of_each_face(mesh);
  std::map<std::uint32_t, double> volumes;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const mg::Face& face = mesh.faces[f];
    volumes[pieces[f]] += glm::dot(mesh.positions[face[0].position],
                                   glm::cross(mesh.positions[face[1].position], mesh.positions[face[2].position]));
  }
  return volumes;
}

glm::dvec3 face_normal(const mg::IndexedMesh& mesh, const mg::Face& face) {
  const glm::dvec3 a = mesh.positions[face[0].position];
  return glm::cross(mesh.positions[face[1].position] - a, mesh.positions[face[2].position] - a);
}

const mg::MeshAsset& mesh_named(const std::string& file_name) {
  static const mg::Assets assets = mg::generated_assets();
  for (const mg::MeshAsset& asset : assets.meshes) {
    if (asset.path.filename() == file_name) return asset;
  }
  FAIL("no generated mesh " << file_name);
  throw std::logic_error("unreachable");
}

}  // namespace

TEST_CASE("every generated mesh is indexed: a position serves four or more triangle corners on average", "[meshes]") {
  for (const mg::MeshAsset& asset : mg::generated_assets().meshes) {
    INFO(asset.path.string());
    const mg::IndexedMesh& mesh = asset.mesh;
    CHECK(3 * mesh.faces.size() >= 4 * mesh.positions.size());
    for (const mg::Face& face : mesh.faces) {
      for (const mg::Corner& corner : face) {
        REQUIRE(corner.position < mesh.positions.size());
        REQUIRE(corner.uv < mesh.uvs.size());
      }
    }
  }
}

TEST_CASE("the bear's parts, its buttons and the torus knot are closed, with front faces outside", "[meshes]") {
  // body, head, snout, 2 ears, 2 arms, 2 legs; 2 eyes and a nose; one knot
  for (const auto& [name, expected_pieces] : {std::pair{"bear.obj", 9u}, {"bear_buttons.obj", 3u}, {"torus_knot.obj", 1u}}) {
    INFO(name);
    const mg::IndexedMesh& mesh = mesh_named(name).mesh;
    CHECK(closed_and_consistent(mesh));
    const std::map<std::uint32_t, double> volumes = six_volume_of_each_piece(mesh);
    CHECK(volumes.size() == expected_pieces);
    for (const auto& [piece, volume] : volumes) CHECK(volume > 0.0);
    CHECK(mesh.uvs.size() > mesh.positions.size());  // seams: positions with two or more uvs
  }
}

TEST_CASE("the terrain is open at its border only, every face turned up", "[meshes]") {
  const mg::IndexedMesh& mesh = mesh_named("terrain.obj").mesh;
  const std::map<Edge, int> edges = directed_edges(mesh);
  const auto on_border = [&](std::uint32_t p) {
    const glm::dvec3 v = mesh.positions[p];
    return std::abs(std::abs(v.x) - 1.5) < 1e-9 || std::abs(std::abs(v.z) - 1.0) < 1e-9;
  };
  int border_edges = 0;
  for (const auto& [edge, count] : edges) {
    REQUIRE(count == 1);
    if (edges.count({edge.second, edge.first}) == 0) {
      ++border_edges;
      CHECK((on_border(edge.first) && on_border(edge.second)));
    }
  }
  CHECK(border_edges == 2 * (48 + 32));
  for (const mg::Face& face : mesh.faces) CHECK(face_normal(mesh, face).y > 0.0);
}
