// The numbers of an OBJ file, checked as written before tinyobjloader reads
// them: it takes "nan", "inf", "0x10" and "1,5" as 0, 0, 16 and 1 without a
// word, fills a missing coordinate with 0, and reads face indices with atoi,
// so an index beyond int overflows (undefined behaviour) into some other
// vertex. Each line the spec's subset uses is checked:
//   v  x y z [w]   three or four finite numbers (six or seven: with a colour)
//   vt u [v [w]]   one to three finite numbers
//   f  a b c ...   corners v, v/vt, v//vn or v/vt/vn; every index a non-zero
//                  integer, a negative one (relative) reaching no further back
//                  than the vertices before it, a positive one fitting int32
// Lines of other kinds (vn, o, g, s, usemtl, mtllib, comments) are left to
// tinyobjloader, which reads no other file (scene/obj_mesh.cpp).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace spanlight::scene::detail {

// Throws SceneError(obj_file, field_path, "expected ... on line N, got ...").
void check_obj_numbers(std::string_view text, const std::filesystem::path& obj_file, const std::string& field_path);

}  // namespace spanlight::scene::detail
