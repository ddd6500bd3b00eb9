#pragma once
// Shared post-processing of every loader: the activated scene must be finite and its
// quaternions unit length (docs/rendering.md, "Stored parameters": files store raw
// quaternions; only the Python side normalises, so a standalone loader must).
#include <cstddef>
#include <string>

#include "scene/gaussian_scene.hpp"

namespace lfd::scene {

float sigmoid(float logit);

// Sizes every array of `scene` for `count` Gaussians at `sh_degree` (zero-filled).
void resize_scene(GaussianScene& scene, size_t count, int sh_degree);

// Normalises quaternions and rejects NaN/Inf values, zero quaternions and inconsistent array
// sizes with InputError("<name>: ..."). Every loader calls it last.
void finalize_scene(GaussianScene& scene, const std::string& name);

}  // namespace lfd::scene
