// The walk every pass of the model makes over the scene's geometry: objects in
// file order, each transformed by the pass's own matrices, its triangles in mesh
// order. The eye's depth pass, the shadow maps, the sweep's coordinates and the
// analyzer's ranges all draw the same triangles in the same order this way.
#pragma once

#include <cstddef>
#include <functional>

#include "float_model/raster.hpp"
#include "float_model/transform.hpp"
#include "scene/scene.hpp"

namespace spanlight::float_model {

// Which mesh triangle: scene.objects[object].mesh.triangles[index].
struct MeshTriangle {
  std::size_t object;
  std::size_t index;
};

// The pass's matrices for an object (eye_transform, projector_depth_transform).
using TransformOf = std::function<ObjectTransform(const scene::Object&)>;

// The eye pass's: eye_transform(scene, object). Keeps a reference to `scene`.
TransformOf eye_transforms(const scene::Scene& scene);

using TriangleVisitor = std::function<void(MeshTriangle, const ClipTriangle&)>;
using SceneFragmentVisitor = std::function<void(MeshTriangle, const ClipTriangle&, const Fragment&)>;

// Every triangle transformed, before clipping.
void for_each_triangle(const scene::Scene& scene, const TransformOf& transform_of, const TriangleVisitor& visit);

// Every covered pixel of every triangle (draw_triangle with the object's cull),
// with the mesh triangle and the clipped piece it came from.
void for_each_fragment(const scene::Scene& scene, Viewport viewport, const TransformOf& transform_of,
                       const SceneFragmentVisitor& visit);

}  // namespace spanlight::float_model
