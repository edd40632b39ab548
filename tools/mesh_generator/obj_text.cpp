#include "obj_text.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace spanlight::mesh_generator {

namespace {

// "%.6f" of the value, with -0.000000 written as 0.000000 (a value that rounds to zero
// from below would otherwise print a sign that depends on the last bit of sin or cos).
std::string number(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", obj_decimals, value);
  const std::string printed = text;
  return printed.find_first_not_of("-0.") == std::string::npos ? printed.substr(printed[0] == '-' ? 1 : 0) : printed;
}

}  // namespace

std::string obj_text(const IndexedMesh& mesh, const std::string& comment) {
  std::ostringstream out;
  std::istringstream comment_lines(comment);
  for (std::string line; std::getline(comment_lines, line);) out << "# " << line << '\n';
  for (const glm::dvec3& p : mesh.positions) out << "v " << number(p.x) << ' ' << number(p.y) << ' ' << number(p.z) << '\n';
  for (const glm::dvec2& uv : mesh.uvs) out << "vt " << number(uv.x) << ' ' << number(uv.y) << '\n';
  for (const Face& face : mesh.faces) {
    out << 'f';
    for (const Corner& corner : face) out << ' ' << corner.position + 1 << '/' << corner.uv + 1;
    out << '\n';
  }
  return out.str();
}

}  // namespace spanlight::mesh_generator
