#include "analyze/scene_ranges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "float_model/clip.hpp"
#include "float_model/scene_geometry.hpp"
#include "float_model/setup.hpp"

namespace spanlight::analyze {

void Interval::add(double v) {
  if (empty) {
    lo = hi = v;
    empty = false;
    return;
  }
  lo = std::min(lo, v);
  hi = std::max(hi, v);
}

std::size_t DepthRanges::at_risk(int bits) const {
  const double step = std::ldexp(1.0, -bits);
  return static_cast<std::size_t>(std::count_if(gaps.begin(), gaps.end(), [&](double g) { return g < step; }));
}

namespace {

ObjectRanges object_ranges(const scene::Scene& s, const scene::Object& o) {
  ObjectRanges r;
  r.name = o.name;
  for (const glm::dvec3& p : o.mesh.positions)
    for (int c = 0; c < 3; ++c) r.largest_coordinate = std::max(r.largest_coordinate, std::fabs(p[c]));
  if (o.texture >= 0) {
    const scene::Image& image = s.textures[static_cast<std::size_t>(o.texture)].image;
    r.textured = true;
    r.texture_width = image.width;
    r.texture_height = image.height;
    for (const glm::dvec2& uv : scene::vertex_uvs(s.camera, o))
      r.largest_texel = std::max({r.largest_texel, std::fabs(uv.x * image.width), std::fabs(uv.y * image.height)});
  }
  return r;
}

ProjectorRanges projector_ranges(const scene::Scene& s, const scene::Projector& p) {
  ProjectorRanges r;
  r.name = p.name;
  r.shadows = p.shadows.has_value();
  if (p.shadows) {
    r.bias = p.shadows->bias;
    r.map_size = p.shadows->map_size;
  }
  const glm::dmat4 texture = scene::projector_texture_matrix(s.camera, p);
  for (const scene::Object& o : s.objects) {
    for (const glm::dvec3& position : o.mesh.positions) {
      const glm::dvec4 strq = texture * o.model * glm::dvec4(position, 1.0);
      r.q.add(strq.w);
      if (strq.w <= 0.0) {
        ++r.vertices_behind;
        continue;
      }
      r.window_depth.add(strq.z / strq.w);
    }
  }
  return r;
}

// The eye's geometry after near/far clipping: w and window extents.
void clip_space_ranges(const scene::Scene& s, SceneRanges& r) {
  float_model::for_each_triangle(s, float_model::eye_transforms(s), [&](float_model::MeshTriangle, const float_model::ClipTriangle& triangle) {
    for (const float_model::ClipTriangle& piece : float_model::clip_triangle(triangle)) {
      for (const float_model::ClipVertex& v : piece) {
        r.clip_w.add(v.position.w);
        if (v.position.w <= 0.0) continue;
        const float_model::WindowPoint w = float_model::to_window(v.position, s.width, s.height);
        r.window_x.add(w.x);
        r.window_y.add(w.y);
      }
    }
  });
}

// The nearest fragment per pixel and the nearest one of any other object.
void depth_ranges(const scene::Scene& s, SceneRanges& r) {
  const std::size_t pixels = static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height);
  constexpr double none = std::numeric_limits<double>::infinity();
  std::vector<double> first(pixels, none), second(pixels, none);
  std::vector<int> first_object(pixels, -1), second_object(pixels, -1);
  const auto keep_two = [&](float_model::MeshTriangle which, const float_model::ClipTriangle&,
                            const float_model::Fragment& f) {
    const int id = static_cast<int>(which.object);
    const std::size_t p = static_cast<std::size_t>(f.y) * static_cast<std::size_t>(s.width) + static_cast<std::size_t>(f.x);
    const double d = f.depth;
    if (first_object[p] == id) {
      first[p] = std::min(first[p], d);
    } else if (d < first[p]) {
      second[p] = first[p];
      second_object[p] = first_object[p];
      first[p] = d;
      first_object[p] = id;
    } else if (second_object[p] == id || d < second[p]) {
      second[p] = std::min(second_object[p] == id ? second[p] : none, d);
      second_object[p] = id;
    }
  };
  float_model::for_each_fragment(s, float_model::Viewport{s.width, s.height}, float_model::eye_transforms(s), keep_two);
  for (std::size_t p = 0; p < pixels; ++p) {
    if (first_object[p] < 0) continue;
    ++r.depth.covered;
    r.depth.visible.add(first[p]);
    if (second_object[p] >= 0) r.depth.gaps.push_back(second[p] - first[p]);
  }
}

}  // namespace

SceneRanges measure_ranges(const scene::Scene& s) {
  SceneRanges r;
  for (const scene::Object& o : s.objects) {
    r.objects.push_back(object_ranges(s, o));
    r.largest_coordinate = std::max(r.largest_coordinate, r.objects.back().largest_coordinate);
    r.largest_texel = std::max(r.largest_texel, r.objects.back().largest_texel);
  }
  for (const scene::Projector& p : s.projectors) r.projectors.push_back(projector_ranges(s, p));
  clip_space_ranges(s, r);
  depth_ranges(s, r);
  return r;
}

}  // namespace spanlight::analyze
