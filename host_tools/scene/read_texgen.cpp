// objects[].texgen (v2): the planes that generate an object's uvs.
#include "scene_readers.hpp"

namespace spanlight::scene::detail {

Texgen read_texgen(const JsonField& texgen) {
  texgen.expect_object_with_fields({"s", "t", "space"});
  Texgen loaded;
  loaded.s = texgen.required("s").vec4();
  if (const auto t = texgen.optional("t")) loaded.t = t->vec4();  // default: the plane 0, so v = 0
  if (const auto space = texgen.optional("space")) {
    loaded.space = space->choice<TexgenSpace>({{"object", TexgenSpace::object}, {"eye", TexgenSpace::eye}});
  }
  return loaded;
}

}  // namespace spanlight::scene::detail
