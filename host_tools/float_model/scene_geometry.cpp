#include "float_model/scene_geometry.hpp"

namespace spanlight::float_model {

TransformOf eye_transforms(const scene::Scene& scene) {
  return [&scene](const scene::Object& object) { return eye_transform(scene, object); };
}

void for_each_triangle(const scene::Scene& scene, const TransformOf& transform_of, const TriangleVisitor& visit) {
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const scene::Object& object = scene.objects[o];
    const ObjectTransform transform = transform_of(object);
    for (std::size_t i = 0; i < object.mesh.triangles.size(); ++i) {
      visit(MeshTriangle{o, i}, transform_triangle(transform, object.mesh, i));
    }
  }
}

void for_each_fragment(const scene::Scene& scene, Viewport viewport, const TransformOf& transform_of,
                       const SceneFragmentVisitor& visit) {
  for_each_triangle(scene, transform_of, [&](MeshTriangle which, const ClipTriangle& triangle) {
    draw_triangle(triangle, viewport, scene.objects[which.object].cull,
                  [&](const ClipTriangle& piece, const Fragment& fragment) { visit(which, piece, fragment); });
  });
}

}  // namespace spanlight::float_model
