#include "prepare/closed_mesh.hpp"

#include <map>
#include <numeric>
#include <utility>

namespace spanlight::prepare {

namespace {

__extension__ typedef __int128 Wide;  // a triple product of coordinates below 2^31: under 2^95

struct Parts {  // union-find over welded vertices
  std::vector<std::uint32_t> parent;
  explicit Parts(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t root(std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[root(a)] = root(b); }
};

}  // namespace

bool closed_solid(const std::vector<std::int32_t>& xyz, const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  using Position = std::array<std::int32_t, 3>;
  std::map<Position, std::uint32_t> welded;
  std::vector<std::uint32_t> id(xyz.size() / 3);
  std::vector<Position> where;
  for (std::size_t v = 0; v < id.size(); ++v) {
    const Position p{xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
    const auto [it, added] = welded.try_emplace(p, static_cast<std::uint32_t>(where.size()));
    if (added) where.push_back(p);
    id[v] = it->second;
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  Parts parts(where.size());
  std::vector<std::array<std::uint32_t, 3>> faces;
  for (const auto& t : triangles) {
    const std::array<std::uint32_t, 3> f{id[t[0]], id[t[1]], id[t[2]]};
    if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) continue;
    for (std::size_t k = 0; k < 3; ++k) ++edges[{f[k], f[(k + 1) % 3]}];
    parts.join(f[0], f[1]);
    parts.join(f[1], f[2]);
    faces.push_back(f);
  }
  if (faces.empty()) return false;
  for (const auto& [edge, count] : edges) {
    const auto back = edges.find({edge.second, edge.first});
    if (count != 1 || back == edges.end() || back->second != 1) return false;
  }
  // Six times each part's signed volume, exactly: the sum of a . (b x c) over its faces (the
  // same from any origin, as the surface is closed).
  std::map<std::uint32_t, Wide> volume;
  for (const auto& f : faces) {
    const Position &a = where[f[0]], &b = where[f[1]], &c = where[f[2]];
    auto cross = [&](std::size_t i, std::size_t j) { return std::int64_t{b[i]} * c[j] - std::int64_t{b[j]} * c[i]; };  // < 2^63
    volume[parts.root(f[0])] += Wide{a[0]} * cross(1, 2) + Wide{a[1]} * cross(2, 0) + Wide{a[2]} * cross(0, 1);
  }
  for (const auto& [part, six_v] : volume)
    if (six_v <= 0) return false;
  return true;
}

}  // namespace spanlight::prepare
