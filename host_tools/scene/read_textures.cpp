// textures: name -> {image, filter, wrap}; loads each image.
#include <bit>
#include <string>

#include "file_checks.hpp"
#include "image_file.hpp"
#include "scene_readers.hpp"

namespace spanlight::scene::detail {
namespace {

bool is_power_of_two(int size) { return size > 0 && std::has_single_bit(static_cast<unsigned>(size)); }

// Spec: repeat only for power-of-two sizes (so a texel index wraps with a mask).
void check_repeat_sizes(const JsonField& texture, const Texture& loaded) {
  if (loaded.wrap != Wrap::repeat || (is_power_of_two(loaded.image.width) && is_power_of_two(loaded.image.height))) {
    return;
  }
  const std::string size = std::to_string(loaded.image.width) + "x" + std::to_string(loaded.image.height);
  texture.fail_member("wrap", "expected clamp or border for the " + size + " image " + loaded.path.string() +
                                  " (repeat needs power-of-two sizes), got " +
                                  (texture.has("wrap") ? "repeat" : "repeat (the default)"));
}

// Spec: trilinear (v2) only for power-of-two sizes (every level halves each side exactly).
void check_trilinear_sizes(const JsonField& texture, const Texture& loaded) {
  if (loaded.filter != Filter::trilinear || (is_power_of_two(loaded.image.width) && is_power_of_two(loaded.image.height))) {
    return;
  }
  const std::string size = std::to_string(loaded.image.width) + "x" + std::to_string(loaded.image.height);
  texture.fail_member("filter", "expected nearest or bilinear for the " + size + " image " + loaded.path.string() +
                                    " (trilinear needs power-of-two sizes), got trilinear");
}

Filter read_filter(const JsonField& filter, int version) {
  // The string compared as a string, not json == "...": on that GCC 12 warns falsely in the ASan
  // build (-Warray-bounds).
  if (version < 2 && filter.json().is_string() && filter.json().get_ref<const std::string&>() == "trilinear") {
    filter.fail_with("expected nearest or bilinear in a version-1 file, got trilinear, which is new in version 2 "
                     "(set \"spanlight_scene\": 2)");
  }
  if (version < 2) return filter.choice<Filter>({{"nearest", Filter::nearest}, {"bilinear", Filter::bilinear}});
  return filter.choice<Filter>(
      {{"nearest", Filter::nearest}, {"bilinear", Filter::bilinear}, {"trilinear", Filter::trilinear}});
}

Texture read_texture(const std::string& name, const JsonField& texture, int version) {
  texture.expect_object_with_fields({"image", "filter", "wrap"});
  Texture loaded;
  loaded.name = name;
  const JsonField image = texture.required("image");
  loaded.path = resolve_against_scene(texture.file(), image.string());
  if (const auto filter = texture.optional("filter")) loaded.filter = read_filter(*filter, version);
  if (const auto wrap = texture.optional("wrap")) {
    loaded.wrap = wrap->choice<Wrap>({{"repeat", Wrap::repeat}, {"clamp", Wrap::clamp}, {"border", Wrap::border}});
  }
  loaded.image = load_asset(texture.file(), [&] { return load_image(loaded.path, image.path()); });
  check_repeat_sizes(texture, loaded);
  check_trilinear_sizes(texture, loaded);
  return loaded;
}

std::string texture_names(const std::vector<Texture>& textures) {
  std::string names;
  for (const Texture& texture : textures) names += (names.empty() ? "" : ", ") + texture.name;
  return names;
}

}  // namespace

std::vector<Texture> read_textures(const JsonField& textures, int version) {
  std::vector<Texture> loaded;
  for (const auto& [name, texture] : textures.members()) loaded.push_back(read_texture(name, texture, version));
  return loaded;
}

int find_texture(const JsonField& name, const std::vector<Texture>& textures) {
  const std::string wanted = name.string();
  for (std::size_t i = 0; i < textures.size(); ++i) {
    if (textures[i].name == wanted) return static_cast<int>(i);
  }
  name.fail("expected the name of a texture (" + (textures.empty() ? "the scene defines none" : texture_names(textures)) + ")");
}

}  // namespace spanlight::scene::detail
