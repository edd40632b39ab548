// falloff: along a corridor wall the light follows its ramp texture texel for texel.
// The camera looks head-on at the wall (so a pixel's point is known exactly); a
// projector 0.5 in front of the wall shines along it, so its depth r/q grows along
// the wall and the light steps through the ramp's texels.
#include <algorithm>
#include <cmath>
#include <set>

#include <catch2/catch.hpp>

#include "effect_scenes.hpp"
#include "picture_check.hpp"

using namespace spanlight;
using namespace spanlight::effects;

TEST_CASE("falloff follows its ramp texel for texel along a corridor wall", "[effects][falloff]") {
  constexpr int ramp_texels = 16;
  std::vector<int> ramp;  // 255 down to 15 in steps of 16: distinct bytes
  for (int i = 0; i < ramp_texels; ++i) ramp.push_back(255 - 16 * i);

  scene::Scene s = head_on_scene();
  // Ambient 0 and a white surface: a lit pixel is colour * image * falloff = the ramp's byte.
  const int white = add_texture(s, "white", grey_image(4, 4, std::vector<int>(16, 255)), scene::Filter::bilinear,
                                scene::Wrap::clamp);
  const int falloff = add_texture(s, "ramp", grey_image(ramp_texels, 1, ramp), scene::Filter::nearest, scene::Wrap::repeat);
  const double x0 = -4.0, x1 = 3.0, y0 = -0.25, y1 = 0.25;  // pixels 0..55 x 30..33
  s.objects.push_back(rectangle("wall", x0, y0, x1, y1));
  // Along +x from x = -4.6, 0.25 in front of the wall: wall points are 0.6 .. 7.6 ahead, 0.25
  // aside and at most 0.25 up, so s/q and t/q are in [0.29, 0.71] (fovy 90): inside [1/8, 7/8]
  // of the white image, image = 1, and the ramp alone sets the light.
  scene::Projector torch = projector({-4.6, 0, 0.25}, {10, 0, 0.25}, 90, 0.5, 10.0, white);
  torch.falloff = falloff;  // its repeat wrap is ignored: falloff is clamped
  s.projectors.push_back(torch);
  const glm::dmat4 texture_matrix = scene::projector_texture_matrix(s.camera, torch);

  for (const EffectRenderer& renderer : effect_renderers()) {
    const Picture picture = renderer.render(s);
    std::set<int> texels_seen;
    const Mismatches m = compare_grey(picture, [&](int x, int y) {
      if (!inside(x, y, x0, y0, x1, y1)) return 0;
      const glm::dvec2 p = plane_point(x, y);
      const glm::dvec4 strq = texture_matrix * glm::dvec4(p.x, p.y, 0.0, 1.0);
      const double texel_position = strq.z / strq.w * ramp_texels;  // the ramp's texel coordinate at r/q
      const double nearest_boundary = std::round(texel_position);
      if (std::abs(texel_position - nearest_boundary) <= renderer.texel_coordinate_error) return -1;
      const int texel = std::clamp(static_cast<int>(std::floor(texel_position)), 0, ramp_texels - 1);
      texels_seen.insert(texel);
      return ramp[static_cast<std::size_t>(texel)];
    }, renderer.value_lsb);
    INFO(renderer.name << ": " << m.first);
    CHECK(m.count == 0);
    // r/q = (10/9.5)(1 - 0.5/d) runs from 0.26 (first pixel, d = 0.66) to 0.98: texels 4..15 light pixels.
    CHECK(texels_seen.size() >= 10);
  }
}
