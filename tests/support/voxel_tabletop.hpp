#pragma once
// The voxel scene fixture V2LF's tests share: the generated level-6 tabletop seen in 5 views of
// 128x96, with its per-view quilt (the ground truth, as SVR quilts are in the paper's Table 1).
#include <cmath>
#include <functional>

#include "render/camera.hpp"
#include "render/per_view_quilt.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "scene/voxel_scene.hpp"
#include "util/image.hpp"
#include "voxel/voxel_generator.hpp"
#include "voxel/voxel_quilt.hpp"

namespace lfd::test {

struct VoxelTabletop {
  scene::VoxelScene scene;
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
  ImageF truth;  // the per-view quilt of `scene`
};

// SH degree 0: V2LF's planes are view-independent; leave that trade-off out of the bars.
// `adjust` sets what a test compares at (supersampling, samples per voxel) before the truth is
// rendered.
inline VoxelTabletop make_voxel_tabletop(const std::function<void(scene::VoxelScene&)>& adjust) {
  VoxelTabletop f;
  voxel::VoxelGeneratorOptions o;
  o.detail_level = 6;
  o.sh_degree = 0;
  f.scene = voxel::generate_voxel_scene(o);
  adjust(f.scene);
  const render::Camera base =
      render::make_look_at_camera({0, -1.5f, -5.5f}, {0, 0.5f, 0}, {0, -1, 0}, 0.8f, 128, 96);
  f.geometry = render::make_quilt_geometry(base, std::sqrt(2.0f * 2.0f + 6.0f * 6.0f), 40.0f, 5);
  f.layout = render::make_quilt_layout(f.geometry, 5, 1);
  f.truth = voxel::render_voxel_quilt_per_view(f.scene, f.geometry, f.layout);
  return f;
}

}  // namespace lfd::test
