#pragma once
// Encodes a scene as a standard 3DGS PLY (gaussian_model.py save_ply; docs/rendering.md
// "What each reader follows"): the Inria property order, stored (pre-activation) values, f_rest
// channel-major, zero normals.
#include <string>

#include "scene/gaussian_scene.hpp"

namespace lfd::scene {

enum class PlyEncoding { BinaryLittleEndian, Ascii };

std::string encode_ply(const GaussianScene& scene,
                       PlyEncoding encoding = PlyEncoding::BinaryLittleEndian);

}  // namespace lfd::scene
