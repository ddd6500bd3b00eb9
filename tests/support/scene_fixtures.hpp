#pragma once
// The scenes and the display the renderer and viewer tests share: the Looking Glass Portrait's
// calibration (a real unit's fixture, tests/data/calibrations) and small generated Gaussian scenes.
#include <cstddef>

#include "display/calibration_file.hpp"
#include "render/scene_generator.hpp"
#include "scene/gaussian_scene.hpp"
#include "tests/test_data.hpp"

namespace lfd::test {

// LKG-PORT-portrait.visual.json: a 1536x2048 panel (the viewer window tests' Xvfb screen).
inline display::Calibration portrait_calibration() {
  return display::read_calibration(fixture_calibration("LKG-PORT-portrait.visual.json"));
}

// The generator's default scene (render/scene_generator.hpp) with `count` Gaussians of SH degree
// `sh_degree`.
inline scene::GaussianScene generated_gaussians(size_t count, int sh_degree) {
  render::SceneGeneratorOptions o;
  o.count = count;
  o.sh_degree = sh_degree;
  return render::generate_scene(o);
}

}  // namespace lfd::test
