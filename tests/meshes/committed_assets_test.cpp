// The generator is the source of truth: every model and texture it writes is in
// scenes/ as it writes it. On a failure, regenerate and commit:
//   cmake --build build --target regenerate_mesh_assets
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "assets.hpp"
#include "obj_text.hpp"
#include "scene/image_file.hpp"
#include "source_tree.hpp"

namespace mg = spanlight::mesh_generator;
using spanlight::mesh_generator::test::scenes_folder;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> words_of(const std::string& line) {
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

bool is_number(const std::string& word, double& value) {
  char* end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return !word.empty() && end == word.c_str() + word.size();
}

// The same words, numbers allowed one unit of the last printed decimal apart: a value
// computed with sin, cos or pow can land on the other side of a rounding boundary when
// the C library's last bit differs. Two printed values one unit apart differ by 1e-6
// up to the representation error of decimals (< 1e-15), well under 1.5 units.
bool same_obj_line(const std::string& committed, const std::string& generated) {
  if (committed == generated) return true;
  const std::vector<std::string> a = words_of(committed), b = words_of(generated);
  if (a.size() != b.size()) return false;
  const double tolerance = 1.5 * std::pow(10.0, -mg::obj_decimals);
  for (std::size_t i = 0; i < a.size(); ++i) {
    double x = 0.0, y = 0.0;
    if (a[i] == b[i]) continue;
    if (!is_number(a[i], x) || !is_number(b[i], y) || std::abs(x - y) > tolerance) return false;
  }
  return true;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("every committed OBJ is the generator's, line for line", "[meshes]") {
  for (const mg::MeshAsset& asset : mg::generated_assets().meshes) {
    const std::filesystem::path file = scenes_folder() / asset.path;
    INFO("scenes/" << asset.path.string() << ": regenerate with `cmake --build build --target regenerate_mesh_assets`");
    REQUIRE(std::filesystem::is_regular_file(file));
    const std::vector<std::string> committed = lines_of(read_text(file)), generated = lines_of(asset.obj);
    REQUIRE(committed.size() == generated.size());
    for (std::size_t i = 0; i < committed.size(); ++i) {
      if (same_obj_line(committed[i], generated[i])) continue;
      FAIL("line " << i + 1 << ": committed '" << committed[i] << "', generated '" << generated[i] << "'");
    }
  }
}

TEST_CASE("every committed texture is the generator's, texel for texel", "[meshes]") {
  for (const mg::TextureAsset& asset : mg::generated_assets().textures) {
    const std::filesystem::path file = scenes_folder() / asset.path;
    INFO("scenes/" << asset.path.string() << ": regenerate with `cmake --build build --target regenerate_mesh_assets`");
    const spanlight::scene::Image committed = spanlight::scene::detail::load_image(file, "image");
    REQUIRE(committed.width == asset.image.width);
    REQUIRE(committed.height == asset.image.height);
    CHECK(committed.rgb == asset.image.rgb);  // the textures use exactly rounded arithmetic only (rgb_image.hpp)
  }
}

TEST_CASE("the OBJ comparison tells a changed model from a last-digit difference", "[meshes]") {
  CHECK(same_obj_line("v 0.123456 1.000000 -2.500000", "v 0.123457 1.000000 -2.500000"));
  CHECK_FALSE(same_obj_line("v 0.123456 1.000000 -2.500000", "v 0.123458 1.000000 -2.500000"));
  CHECK_FALSE(same_obj_line("f 1/1 2/2 3/3", "f 1/1 3/3 2/2"));
  CHECK_FALSE(same_obj_line("v 0.1 0.2 0.3", "v 0.1 0.2"));
}
