// Every malformed scene under tests/scene/bad/ is refused with a SceneError
// naming the right file and field (bad/README.md says what each one breaks).
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "scene/scene.hpp"
#include "source_paths.hpp"

using namespace spanlight::scene;
using spanlight::scene::test::bad_scene_dir;

namespace {

struct BadScene {
  const char* file;        // under tests/scene/bad/
  const char* field;       // SceneError::field(), exactly
  const char* named_file;  // what what() must name: the scene itself, or the asset at fault (and the scene)
};

constexpr const char* itself = nullptr;

// clang-format off
const std::vector<BadScene> bad_scenes = {
  // the document
  {"invalid_json.json",                    "(root)",                          itself},
  {"root_not_object.json",                 "(root)",                          itself},
  {"number_overflow.json",                 "camera.fovy_deg",                 itself},
  {"number_overflow_in_array.json",        "camera.eye[1]",                   itself},
  {"duplicate_key.json",                   "camera.near",                     itself},
  // version
  {"version_3.json",                       "spanlight_scene",                 itself},
  {"version_missing.json",                 "spanlight_scene",                 itself},
  {"version_string.json",                  "spanlight_scene",                 itself},
  // unknown fields
  {"unknown_top_level_field.json",         "lights",                          itself},
  {"unknown_camera_field.json",            "camera.fov",                      itself},
  {"unknown_object_field.json",            "objects[0].colour",               itself},
  {"unknown_texture_field.json",           "textures.checker.mipmap",         itself},
  {"unknown_transform_field.json",         "objects[0].transform.shear",      itself},
  {"unknown_shadows_field.json",           "projectors[0].shadows.size",      itself},
  // wrong types
  {"name_not_string.json",                 "name",                            itself},
  {"width_string.json",                    "output.width",                    itself},
  {"eye_string.json",                      "camera.eye",                      itself},
  {"eye_two_numbers.json",                 "camera.eye",                      itself},
  {"color_element_string.json",            "objects[0].color[1]",             itself},
  {"objects_not_array.json",               "objects",                         itself},
  {"textures_not_object.json",             "textures",                        itself},
  {"position_two_numbers.json",            "objects[0].positions[1]",         itself},
  // required fields missing
  {"output_missing.json",                  "output",                          itself},
  {"camera_missing.json",                  "camera",                          itself},
  {"camera_far_missing.json",              "camera.far",                      itself},
  {"texture_image_missing.json",           "textures.checker.image",          itself},
  {"projector_image_missing.json",         "projectors[0].image",             itself},
  {"map_size_missing.json",                "projectors[0].shadows.map_size",  itself},
  {"bias_missing.json",                    "projectors[0].shadows.bias",      itself},
  // values out of range
  {"width_0.json",                         "output.width",                    itself},
  {"width_5000.json",                      "output.width",                    itself},
  {"height_fractional.json",               "output.height",                   itself},
  {"fovy_0.json",                          "camera.fovy_deg",                 itself},
  {"fovy_180.json",                        "camera.fovy_deg",                 itself},
  {"near_0.json",                          "camera.near",                     itself},
  {"near_negative.json",                   "camera.near",                     itself},
  {"far_equals_near.json",                 "camera.far",                      itself},
  {"ambient_above_1.json",                 "ambient[1]",                      itself},
  {"object_color_negative.json",           "objects[0].color[2]",             itself},
  {"projector_fovy_190.json",              "projectors[0].fovy_deg",          itself},
  {"projector_near_negative.json",         "projectors[0].near",              itself},
  {"projector_far_below_near.json",        "projectors[0].far",               itself},
  {"projector_aspect_0.json",              "projectors[0].aspect",            itself},
  {"projector_color_negative.json",        "projectors[0].color[2]",          itself},
  {"map_size_4.json",                      "projectors[0].shadows.map_size",  itself},
  {"map_size_8192.json",                   "projectors[0].shadows.map_size",  itself},
  {"bias_negative.json",                   "projectors[0].shadows.bias",      itself},
  // names from a fixed set
  {"texture_filter_unknown.json",          "textures.checker.filter",         itself},
  {"texture_wrap_unknown.json",            "textures.checker.wrap",           itself},
  {"cull_unknown.json",                    "objects[0].cull",                 itself},
  {"shadow_filter_unknown.json",           "projectors[0].shadows.filter",    itself},
  // texture names
  {"object_texture_unknown.json",          "objects[0].texture",              itself},
  {"object_texture_without_textures.json", "objects[0].texture",              itself},
  {"projector_image_unknown.json",         "projectors[0].image",             itself},
  // files the scene names
  {"mesh_file_missing.json",               "objects[0].mesh",                 "no_such_mesh.obj"},
  {"mesh_is_directory.json",               "objects[0].mesh",                 "assets"},
  {"image_file_missing.json",              "textures.checker.image",          "no_such_image.png"},
  {"image_corrupt.json",                   "textures.checker.image",          "corrupt.png"},
  {"image_too_wide.json",                  "textures.checker.image",          "wide_4097x1.png"},
  {"image_is_directory.json",              "textures.checker.image",          "assets"},
  {"npot_texture_repeat.json",             "textures.checker.wrap",           itself},
  {"npot_texture_default_wrap.json",       "textures.checker.wrap",           itself},
  {"obj_vertex_index_out_of_range.json",   "objects[0].mesh",                 "out_of_range_vertex.obj"},
  {"obj_texcoord_index_out_of_range.json", "objects[0].mesh",                 "out_of_range_texcoord.obj"},
  {"obj_zero_index.json",                  "objects[0].mesh",                 "zero_index.obj"},
  {"obj_two_corner_face.json",             "objects[0].mesh",                 "two_corner_face.obj"},
  // inline geometry
  {"mesh_and_positions.json",              "objects[0].positions",            itself},
  {"mesh_and_uvs.json",                    "objects[0].uvs",                  itself},
  {"neither_mesh_nor_positions.json",      "objects[0]",                      itself},
  {"positions_without_triangles.json",     "objects[0].triangles",            itself},
  {"uvs_count_mismatch.json",              "objects[0].uvs",                  itself},
  {"triangle_two_indices.json",            "objects[0].triangles[1]",         itself},
  {"triangle_index_out_of_range.json",     "objects[0].triangles[0][2]",      itself},
  {"triangle_index_negative.json",         "objects[0].triangles[0][0]",      itself},
  {"triangle_index_fractional.json",       "objects[0].triangles[0][1]",      itself},
  // transforms
  {"transform_matrix_and_translate.json",  "objects[0].transform.translate",  itself},
  {"transform_matrix_15_numbers.json",     "objects[0].transform.matrix",     itself},
  {"transform_scale_two_numbers.json",     "objects[0].transform.scale",      itself},
  // degenerate views
  {"camera_eye_equals_target.json",        "camera.target",                   itself},
  {"camera_up_parallel.json",              "camera.up",                       itself},
  {"camera_up_zero.json",                  "camera.up",                       itself},
  {"projector_eye_equals_target.json",     "projectors[0].target",            itself},
  {"projector_up_parallel.json",           "projectors[0].up",                itself},
  // version-2 fields in a version-1 file
  {"v1_texgen.json",                      "objects[0].texgen",                itself},
  {"v1_trilinear.json",                   "textures.checker.filter",          itself},
  {"v1_falloff.json",                     "projectors[0].falloff",            itself},
  {"v1_facing_only.json",                 "projectors[0].facing_only",        itself},
  {"v1_projector_space.json",             "projectors[0].space",              itself},
  // version-2 values
  {"trilinear_npot.json",                 "textures.checker.filter",          itself},
  {"texgen_and_uvs.json",                 "objects[0].texgen",                itself},
  {"texgen_not_object.json",              "objects[0].texgen",                itself},
  {"texgen_s_missing.json",               "objects[0].texgen.s",              itself},
  {"texgen_s_three_numbers.json",         "objects[0].texgen.s",              itself},
  {"texgen_t_string.json",                "objects[0].texgen.t[1]",           itself},
  {"texgen_space_unknown.json",           "objects[0].texgen.space",          itself},
  {"texgen_unknown_field.json",           "objects[0].texgen.r",              itself},
  {"falloff_unknown.json",                "projectors[0].falloff",            itself},
  {"falloff_not_string.json",             "projectors[0].falloff",            itself},
  {"facing_only_string.json",             "projectors[0].facing_only",        itself},
  {"projector_space_unknown.json",        "projectors[0].space",              itself},
};
// clang-format on

}  // namespace

TEST_CASE("every malformed scene is refused with its file and field", "[scene][bad]") {
  for (const BadScene& bad : bad_scenes) {
    DYNAMIC_SECTION(bad.file) {
      const auto file = bad_scene_dir() / bad.file;
      const std::string named_file = bad.named_file ? bad.named_file : bad.file;
      try {
        load_scene(file);
        FAIL(bad.file << " loaded without an error");
      } catch (const SceneError& error) {
        INFO(error.what());
        CHECK(error.field() == bad.field);
        CHECK_THAT(error.what(), Catch::Contains(named_file));
        CHECK_THAT(error.what(), Catch::Contains(bad.field));
        CHECK_THAT(error.expected(), Catch::StartsWith("expected "));
        // The scene is named first even when the fault is in an asset: FILE: FIELD: [ASSET: ]EXPECTED.
        CHECK(error.file() == file.string());
        if (bad.named_file) {
          CHECK_THAT(error.asset(), Catch::Contains(bad.named_file));
        } else {
          CHECK(error.asset().empty());
        }
        const std::string asset_part = error.asset().empty() ? "" : error.asset() + ": ";
        CHECK(std::string(error.what()) == error.file() + ": " + error.field() + ": " + asset_part + error.expected());
      }
    }
  }
}

TEST_CASE("the bad-scene table lists every file of the corpus", "[scene][bad]") {
  std::set<std::string> in_table;
  for (const BadScene& bad : bad_scenes) in_table.insert(bad.file);
  CHECK(in_table.size() == bad_scenes.size());  // no file listed twice
  for (const auto& entry : std::filesystem::directory_iterator(bad_scene_dir())) {
    if (entry.path().extension() != ".json") continue;
    INFO(entry.path().filename().string());
    CHECK(in_table.count(entry.path().filename().string()) == 1);
  }
}

TEST_CASE("a scene file that does not exist is an error naming it", "[scene][bad]") {
  const auto missing = bad_scene_dir() / "no_such_scene.json";
  try {
    load_scene(missing);
    FAIL("loaded a file that does not exist");
  } catch (const SceneError& error) {
    CHECK(error.file() == missing.string());
    CHECK(error.field() == "(root)");
    CHECK_THAT(error.what(), Catch::Contains("no_such_scene.json") && Catch::Contains("no such file"));
  }
}

TEST_CASE("invalid JSON is reported with the parser's line and column", "[scene][bad]") {
  try {
    load_scene(bad_scene_dir() / "invalid_json.json");
    FAIL("loaded invalid JSON");
  } catch (const SceneError& error) {
    CHECK_THAT(error.expected(), Catch::Contains("line 4, column"));
  }
}

TEST_CASE("a number too large for a double is refused, not read as infinity", "[scene][bad]") {
  try {
    load_scene(bad_scene_dir() / "number_overflow.json");
    FAIL("loaded 1e999");
  } catch (const SceneError& error) {
    CHECK_THAT(error.expected(), Catch::Contains("1e999"));
  }
}

TEST_CASE("messages say what was expected and what was found", "[scene][bad]") {
  try {
    load_scene(bad_scene_dir() / "projector_fovy_190.json");
    FAIL("loaded fovy 190");
  } catch (const SceneError& error) {
    CHECK(error.expected() == "expected a number in (0, 180), got 190");
    CHECK(std::string(error.what()) ==
          (bad_scene_dir() / "projector_fovy_190.json").string() + ": projectors[0].fovy_deg: " + error.expected());
  }
}
