#include "obj_mesh.hpp"

#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include <tiny_obj_loader.h>

#include "file_checks.hpp"
#include "obj_numbers.hpp"

namespace spanlight::scene::detail {
namespace {

// Builds the Mesh from tinyobjloader's arrays, checking every index the faces use.
class MeshBuilder {
 public:
  MeshBuilder(const tinyobj::attrib_t& attrib, const std::filesystem::path& obj_file, const std::string& field_path)
      : attrib_(attrib), obj_file_(obj_file), field_path_(field_path) {}

  void add_face(const tinyobj::index_t* corners, std::size_t corner_count) {
    ++face_number_;
    std::vector<std::uint32_t> vertices;
    for (std::size_t i = 0; i < corner_count; ++i) vertices.push_back(vertex_for(corners[i]));
    for (std::size_t i = 1; i + 1 < corner_count; ++i) {
      mesh_.triangles.push_back({vertices[0], vertices[i], vertices[i + 1]});
    }
  }

  Mesh take() { return std::move(mesh_); }

 private:
  std::uint32_t vertex_for(const tinyobj::index_t& corner) {
    check_index(corner.vertex_index, attrib_.vertices.size() / 3, "vertex (v)");
    // tinyobjloader gives -1 for a corner without vt.
    if (corner.texcoord_index != -1) check_index(corner.texcoord_index, attrib_.texcoords.size() / 2, "texture coordinate (vt)");
    const auto key = std::make_pair(corner.vertex_index, corner.texcoord_index);
    const auto [found, is_new] = vertex_of_pair_.try_emplace(key, static_cast<std::uint32_t>(mesh_.positions.size()));
    if (is_new) add_vertex(corner);
    return found->second;
  }

  void add_vertex(const tinyobj::index_t& corner) {
    const auto v = static_cast<std::size_t>(corner.vertex_index) * 3;
    const glm::dvec3 position(attrib_.vertices[v], attrib_.vertices[v + 1], attrib_.vertices[v + 2]);
    if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z)) {
      fail("expected finite vertex coordinates, got a non-finite v number " + std::to_string(corner.vertex_index + 1));
    }
    glm::dvec2 uv(0.0);  // spec: missing vt means uv 0
    if (corner.texcoord_index != -1) {
      const auto t = static_cast<std::size_t>(corner.texcoord_index) * 2;
      uv = {attrib_.texcoords[t], attrib_.texcoords[t + 1]};
      if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
        fail("expected finite texture coordinates, got a non-finite vt number " +
             std::to_string(corner.texcoord_index + 1));
      }
    }
    mesh_.positions.push_back(position);
    mesh_.uvs.push_back(uv);
  }

  // index is 0-based here; messages use the file's 1-based numbers.
  void check_index(int index, std::size_t count, const char* what) const {
    if (index >= 0 && static_cast<std::size_t>(index) < count) return;
    fail("expected " + std::string(what) + " indices in 1.." + std::to_string(count) + ", got " +
         std::to_string(static_cast<long long>(index) + 1) + " in face " + std::to_string(face_number_));
  }

  [[noreturn]] void fail(const std::string& message) const { throw SceneError(obj_file_.string(), field_path_, message); }

  const tinyobj::attrib_t& attrib_;
  const std::filesystem::path& obj_file_;
  const std::string& field_path_;
  Mesh mesh_;
  std::map<std::pair<int, int>, std::uint32_t> vertex_of_pair_;
  std::size_t face_number_ = 0;
};

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

// 10^6 triangles over prepare's limit of 65535 vertices, every corner written
// "v/vt", are about 40 MB of OBJ text.
constexpr std::uintmax_t max_obj_file_bytes = 64 * io::mebibyte;

}  // namespace

Mesh load_obj_mesh(const std::filesystem::path& obj_file, const std::string& field_path) {
  const auto fail = [&](const std::string& message) { throw SceneError(obj_file.string(), field_path, message); };
  const std::string text =
      read_for_field(obj_file, field_path, [&] { return io::read_regular_file(obj_file, "OBJ file", max_obj_file_bytes); });
  check_obj_numbers(text, obj_file, field_path);

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // we fan-triangulate ourselves, keeping the file's corner order
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // From memory, with no material text: an `mtllib` line opens no other file
  // (`mtllib /dev/zero` would otherwise be read for ever).
  if (!reader.ParseFromString(text, "", config)) fail("expected a valid OBJ file, got: " + first_line(reader.Error()));
  // tinyobjloader drops faces of fewer than 3 corners with only a warning.
  if (reader.Warning().find("Degenerated face") != std::string::npos) {
    fail("expected faces of 3 or more vertices, got a face with fewer");
  }

  MeshBuilder builder(reader.GetAttrib(), obj_file, field_path);
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& face_sizes = shape.mesh.num_face_vertices;
    // Corner counts are stored in an unsigned char: bigger polygons would be misread.
    if (std::accumulate(face_sizes.begin(), face_sizes.end(), std::size_t{0}) != shape.mesh.indices.size()) {
      fail("expected polygons of at most 255 vertices (tinyobjloader's limit), got a bigger one");
    }
    std::size_t first_corner = 0;
    for (const unsigned char corner_count : face_sizes) {
      builder.add_face(&shape.mesh.indices[first_corner], corner_count);
      first_corner += corner_count;
    }
  }
  Mesh mesh = builder.take();
  mesh.file = obj_file;
  return mesh;
}

}  // namespace spanlight::scene::detail
