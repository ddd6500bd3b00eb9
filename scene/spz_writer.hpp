#pragma once
// Encodes a scene as Niantic SPZ version 3 (docs/rendering.md "Scene formats"; the layout
// scene/spz_reader.cpp reads, after nianticlabs/spz load-spz.cc): a gzip stream holding a
// 16-byte header and the attribute arrays. Positions are 24-bit fixed point with 12 fraction
// bits, scales and colours and SH 8-bit, rotations "smallest three" in 32 bits; the axes are
// turned from the PLY's RDF to SPZ's RUB (the reader's inverse).
#include <string>

#include "scene/gaussian_scene.hpp"

namespace lfd::scene {

std::string encode_spz(const GaussianScene& scene);

}  // namespace lfd::scene
