#pragma once
// lfd.Scene and its two kinds, lfd.Gaussians and lfd.Voxels: an immutable scene::Scene shared
// with the renders that use it (a render holds it while the GIL is released).
#include <memory>
#include <string>

#include "scene/scene.hpp"

namespace lfd::python {

struct PyScene {
  std::shared_ptr<const scene::Scene> scene;
  std::string name;  // the file, or "the Gaussians" for arrays: for messages
};

}  // namespace lfd::python
