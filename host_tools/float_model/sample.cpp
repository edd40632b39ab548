#include "float_model/sample.hpp"

#include <algorithm>
#include <cmath>

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

glm::dvec3 sample_texture(const scene::Texture& texture, glm::dvec2 uv) {
  return sample(texture.image, texture.filter, texture.wrap, uv);
}

glm::dvec3 sample_projector_image(const scene::Texture& texture, glm::dvec2 st) {
  return sample(texture.image, texture.filter, scene::Wrap::border, st);
}

}  // namespace spanlight::float_model
