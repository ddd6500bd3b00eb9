#pragma once
// Procedural Gaussian scenes with realistic depth structure (ground, objects at several
// depths, background), of any size, for tests, benchmarks and the demo.
#include <cstdint>
#include <string>

#include "render/gaussian_scene.hpp"

namespace lfd::render {

struct SceneGeneratorOptions {
  std::string kind = "tabletop";  // see generator_kinds()
  size_t count = 100000;          // number of Gaussians
  uint64_t seed = 1;
  int sh_degree = 1;
  void check() const;             // throws InputError for an unknown kind or absurd count
};

std::vector<std::string> generator_kinds();
GaussianScene generate_scene(const SceneGeneratorOptions& options);

}  // namespace lfd::render
