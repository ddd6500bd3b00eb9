#pragma once
// Tiny scenes and quilts for the light-field renderer tests: a generated tabletop of Gaussians
// and a generated voxel tabletop, 4 views of 32x24 in a 2x2 quilt (seconds on llvmpipe).
#include "lightfield/renderer_options.hpp"
#include "lightfield/scene_framing.hpp"
#include "scene/scene.hpp"
#include "render/default_camera.hpp"
#include "render/per_view_quilt.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "render/scene_generator.hpp"
#include "voxel/voxel_generator.hpp"

namespace lfd::lightfield {

inline const scene::Scene& test_gaussians() {
  static const scene::Scene scene = [] {
    render::SceneGeneratorOptions g;
    g.count = 2000;
    return scene::Scene(render::generate_scene(g));
  }();
  return scene;
}

inline const scene::Scene& test_voxels() {
  static const scene::Scene scene = [] {
    voxel::VoxelGeneratorOptions g;
    g.detail_level = 5;
    return scene::Scene(voxel::generate_voxel_scene(g));
  }();
  return scene;
}

inline render::QuiltGeometry test_geometry(const scene::Scene& scene) {
  const render::CameraSpec spec = lightfield::scene_framing(scene);
  return render::make_quilt_geometry(render::camera_from_spec(spec, 32, 24), glm::length(spec.look_at - spec.position),
                                     40.0f, 4);
}

inline render::QuiltLayout test_layout(const render::QuiltGeometry& geometry) {
  return render::make_quilt_layout(geometry, 2, 2);
}

inline RendererOptions test_options(Backend backend, Method method) {
  RendererOptions o;
  o.backend = backend;
  o.method = method;
  o.planes.chunks = 16;
  o.background = glm::vec3(0.1f, 0.2f, 0.3f);
  return o;
}

}  // namespace lfd::lightfield
