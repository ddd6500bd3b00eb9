#pragma once
// Encodes a scene as a standard 3DGS PLY (reference/gaussian-splatting.md 7.1): the Inria
// property order, stored (pre-activation) values, f_rest channel-major, zero normals.
#include <string>

#include "scene/gaussian_scene.hpp"

namespace lfd::scene {

enum class PlyEncoding { BinaryLittleEndian, Ascii };

std::string encode_ply(const GaussianScene& scene,
                       PlyEncoding encoding = PlyEncoding::BinaryLittleEndian);

}  // namespace lfd::scene
