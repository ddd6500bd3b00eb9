#pragma once
// In-memory entry points of the scene loaders, one per format. Each takes the whole file's
// bytes and a name used in error messages (the path, or "<fuzz>"), so the fuzz targets and
// tests can drive them without touching the file system. All throw lfd::InputError.
#include <string>
#include <string_view>

#include "render/gaussian_scene.hpp"

namespace lfd::render {

struct PlyFile;

// Standard 3DGS PLY, binary little-endian or ASCII (reference/gaussian-splatting.md 7.1).
GaussianScene read_standard_ply(std::string_view bytes, const std::string& name);
// PlayCanvas / SuperSplat compressed PLY (reference 7.4).
GaussianScene read_compressed_ply(std::string_view bytes, const std::string& name);
// antimatter15 .splat, 32 bytes per Gaussian (reference 7.2).
GaussianScene read_splat(std::string_view bytes, const std::string& name);
// Niantic SPZ: v1-v3 gzip container, v4 zstd multi-stream container (reference 7.3).
GaussianScene read_spz(std::string_view bytes, const std::string& name);

// The same two readers on an already parsed PLY container (parse_ply), so dispatch parses once.
GaussianScene standard_ply_to_scene(const PlyFile& ply, const std::string& name);
GaussianScene compressed_ply_to_scene(const PlyFile& ply, const std::string& name);

// Recognises the format by content (PLY header, gzip/NGSP magic); `.splat` by the name's
// extension and a size that is a multiple of 32, since that format has no header.
GaussianScene read_scene_bytes(std::string_view bytes, const std::string& name);

}  // namespace lfd::render
