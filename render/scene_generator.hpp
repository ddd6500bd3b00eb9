#pragma once
// Procedural Gaussian scenes with realistic depth structure (ground, objects at several
// depths, background), of any size, for tests, benchmarks and the demo.
// Frame: that of trained 3DGS scenes (COLMAP): y down, so the ground is the plane y = +1 and
// "up" is -y; objects lie within ~3 units of the origin (tabletop: rows at z = -1.5, 0.5, 2.5;
// corridor: from z = -3 to the end wall at z = +12). A look-at camera at (0, -1, -5) aimed at the
// origin with up = (0, -1, 0) frames the tabletop; scene::robust_bounds() frames either kind.
#include <cstdint>
#include <string>

#include "scene/gaussian_scene.hpp"

namespace lfd::render {

struct SceneGeneratorOptions {
  std::string kind = "tabletop";  // see generator_kinds()
  size_t count = 100000;          // number of Gaussians
  uint64_t seed = 1;
  int sh_degree = 1;
  void check() const;             // InputError "scene generator options: <field>: ..."
};

std::vector<std::string> generator_kinds();
scene::GaussianScene generate_scene(const SceneGeneratorOptions& options);

}  // namespace lfd::render
