#include "float_model/sample.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/mip_chain.hpp"

namespace spanlight::float_model {

namespace {

long long positive_mod(long long value, long long size) {
  const long long r = value % size;
  return r < 0 ? r + size : r;
}

// floor() as a texel index. The limit only keeps the cast defined for absurd
// coordinates (uv = 1e30); below it every double is still an exact integer step.
long long floor_index(double x) {
  constexpr double limit = 4.0e15;  // < 2^53 / 2: still an exact integer
  return static_cast<long long>(std::floor(std::clamp(x, -limit, limit)));
}

}  // namespace

glm::dvec3 texel(const scene::Image& image, scene::Wrap wrap, long long column, long long row_from_bottom) {
  const long long width = image.width;
  const long long height = image.height;
  switch (wrap) {
    case scene::Wrap::repeat:
      column = positive_mod(column, width);
      row_from_bottom = positive_mod(row_from_bottom, height);
      break;
    case scene::Wrap::clamp:
      column = std::clamp(column, 0LL, width - 1);
      row_from_bottom = std::clamp(row_from_bottom, 0LL, height - 1);
      break;
    case scene::Wrap::border:
      if (column < 0 || column >= width || row_from_bottom < 0 || row_from_bottom >= height) return glm::dvec3(0.0);
      break;
  }
  const long long row_from_top = height - 1 - row_from_bottom;  // images are stored top row first
  const auto rgb = image.texel(static_cast<int>(column), static_cast<int>(row_from_top));
  return glm::dvec3(rgb[0], rgb[1], rgb[2]) / 255.0;
}

glm::dvec3 sample_nearest(const scene::Image& image, scene::Wrap wrap, glm::dvec2 uv) {
  return texel(image, wrap, floor_index(uv.x * image.width), floor_index(uv.y * image.height));
}

glm::dvec3 sample_bilinear(const scene::Image& image, scene::Wrap wrap, glm::dvec2 uv) {
  const double x = uv.x * image.width - 0.5;
  const double y = uv.y * image.height - 0.5;  // from the bottom
  const long long x0 = floor_index(x);
  const long long y0 = floor_index(y);
  const double fx = x - static_cast<double>(x0);
  const double fy = y - static_cast<double>(y0);
  return (1.0 - fx) * (1.0 - fy) * texel(image, wrap, x0, y0) +  //
         fx * (1.0 - fy) * texel(image, wrap, x0 + 1, y0) +      //
         (1.0 - fx) * fy * texel(image, wrap, x0, y0 + 1) +      //
         fx * fy * texel(image, wrap, x0 + 1, y0 + 1);
}

glm::dvec3 sample(const scene::Image& image, scene::Filter filter, scene::Wrap wrap, glm::dvec2 uv) {
  return filter == scene::Filter::nearest ? sample_nearest(image, wrap, uv) : sample_bilinear(image, wrap, uv);
}

double level_of_detail(glm::dvec2 duv_dx, glm::dvec2 duv_dy, int width, int height) {
  const glm::dvec2 size(width, height);
  const double rho = std::max(glm::length(duv_dx * size), glm::length(duv_dy * size));
  return rho > 0.0 ? std::log2(rho) : -std::numeric_limits<double>::infinity();
}

glm::dvec3 sample_trilinear(const std::vector<scene::Image>& chain, scene::Wrap wrap, glm::dvec2 uv, double lambda) {
  if (!(lambda > 0.0)) return sample_bilinear(chain.front(), wrap, uv);  // also for NaN
  const auto last = static_cast<double>(chain.size() - 1);
  const double d = std::min(lambda, last);
  const double level = std::floor(d);
  const double f = d - level;
  const auto lower = static_cast<std::size_t>(level);
  const std::size_t upper = std::min(lower + 1, chain.size() - 1);
  return (1.0 - f) * sample_bilinear(chain[lower], wrap, uv) + f * sample_bilinear(chain[upper], wrap, uv);
}

MipChains mip_chains(const scene::Scene& scene) {
  MipChains chains;
  for (const scene::Texture& texture : scene.textures) {
    chains.push_back(texture.filter == scene::Filter::trilinear ? scene::mip_chain(texture.image)
                                                                : std::vector<scene::Image>{});
  }
  return chains;
}

glm::dvec3 sample_texture(const scene::Texture& texture, glm::dvec2 uv) {
  return sample(texture.image, texture.filter, texture.wrap, uv);
}

glm::dvec3 sample_texture(const scene::Texture& texture, const std::vector<scene::Image>& chain, glm::dvec2 uv,
                          double lambda) {
  if (texture.filter == scene::Filter::trilinear) return sample_trilinear(chain, texture.wrap, uv, lambda);
  return sample(texture.image, texture.filter, texture.wrap, uv);
}

glm::dvec3 sample_falloff(const scene::Texture& texture, double depth) {
  return sample(texture.image, texture.filter, scene::Wrap::clamp, {depth, 0.5});
}

glm::dvec3 sample_projector_image(const scene::Texture& texture, glm::dvec2 st) {
  return sample(texture.image, texture.filter, scene::Wrap::border, st);
}

}  // namespace spanlight::float_model
