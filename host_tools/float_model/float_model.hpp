// The float model: the reference picture the fixed-point pipeline is measured
// against. Double precision, GLM, the exact divide at every pixel, no tables.
// Files mirror the fixed pipeline's stages in the order a pixel meets them:
//   transform.hpp   object -> clip space, projectors' (s, t, r, q)
//   clip.hpp        near/far planes in clip space, fan triangulation
//   setup.hpp       window coordinates, snap to 1/256 px, edge functions, top-left rule
//   raster.hpp      covered pixels, depth and perspective-correct weights
//   scene_geometry.hpp  every object's triangles or fragments, in file order, for any pass
//   sample.hpp      nearest/bilinear/trilinear texels, wrap modes, t = 0 at the bottom, falloff
//   shadow_map.hpp  depth maps from the projectors, nearest and pcf2x2 compares
//   facing.hpp      facing_only: which projectors a triangle faces
//   shade.hpp       light * surface
//   visibility.hpp  the eye's depth pass: the nearest surface per pixel
//   render.cpp      the frame: shadow passes, visibility, shading
#pragma once

#include <cstdint>
#include <vector>

#include "float_model/raster.hpp"  // covered_pixels
#include "float_model/setup.hpp"   // SnappedVertex, pixel_covered
#include "scene/scene.hpp"

namespace spanlight::float_model {

struct FloatFrame {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // 8-bit RGB, top row first: the output image
  std::vector<double> depth;      // window depth of the visible surface; 1 where nothing was drawn
  std::vector<float> light_rgb;   // the light term per pixel (before the surface), 0 on background
  std::vector<int> object;        // index of the visible object per pixel, -1 on background
};

// Renders the scene as the spec defines it.
FloatFrame render_float(const scene::Scene& scene);

}  // namespace spanlight::float_model
