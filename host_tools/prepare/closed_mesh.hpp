// Whether a mesh is a closed solid, the property that lets draw_pass leave out
// the back faces of an object drawn without culling (5_frame/draw.hpp): from an
// eye outside it, a ray meets a closed surface first where it enters, so a face
// turned away is never the nearest surface.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace spanlight::prepare {

// True when, with vertices of equal position taken as one (a uv seam repeats
// positions), every edge a -> b of a triangle meets exactly one edge b -> a of
// another and no second a -> b (a closed surface, consistently wound, no edge
// shared by more than two faces), and every connected part encloses a positive
// volume: counter-clockwise seen from outside, the winding cull "back" keeps.
// Triangles with two corners at one position take no part (they cover nothing).
// `xyz` holds x, y, z per vertex, as the pipeline transforms them.
bool closed_solid(const std::vector<std::int32_t>& xyz, const std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace spanlight::prepare
