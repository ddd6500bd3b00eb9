#pragma once
// In-memory entry points of the scene loaders, one per format. Each takes the whole file's
// bytes and a name used in error messages (the path, or "<fuzz>"), so the fuzz targets and
// tests can drive them without touching the file system. All throw lfd::InputError.
#include <string>
#include <string_view>

#include "scene/gaussian_scene.hpp"

namespace lfd::scene {

struct PlyFile;

// The readers follow the files listed in docs/rendering.md "What each reader follows".
// Standard 3DGS PLY, binary little-endian or ASCII (gaussian_model.py load_ply).
GaussianScene read_standard_ply(std::string_view bytes, const std::string& name);
// PlayCanvas / SuperSplat compressed PLY (splat-transform decompress-ply.ts).
GaussianScene read_compressed_ply(std::string_view bytes, const std::string& name);
// antimatter15 .splat, 32 bytes per Gaussian (antimatter15/splat convert.py).
GaussianScene read_splat(std::string_view bytes, const std::string& name);
// Niantic SPZ: v1-v3 gzip container, v4 zstd multi-stream container (nianticlabs/spz load-spz.cc).
GaussianScene read_spz(std::string_view bytes, const std::string& name);
// PlayCanvas SOG, versions 1 and 2 (splat-transform read-sog.ts): a `.sog` ZIP archive, or the
// meta.json of the unpacked layout with its WebP images in the same folder as `name`.
GaussianScene read_sog(std::string_view bytes, const std::string& name);
GaussianScene read_sog_meta(std::string_view meta_bytes, const std::string& name);
// glTF 2.0 (.glb, or .gltf with embedded or neighbouring buffers) with KHR_gaussian_splatting.
GaussianScene read_gltf(std::string_view bytes, const std::string& name);
// mkkellogg/GaussianSplats3D .ksplat, compression levels 0-2.
GaussianScene read_ksplat(std::string_view bytes, const std::string& name);

// The same two readers on an already parsed PLY container (parse_ply), so dispatch parses once.
GaussianScene standard_ply_to_scene(const PlyFile& ply, const std::string& name);
GaussianScene compressed_ply_to_scene(const PlyFile& ply, const std::string& name);

// Recognises the format by content (PLY header, gzip/NGSP magic, ZIP magic for SOG, glTF
// magic); by the name's extension where the format has no magic: `.splat` (a size that is a
// multiple of 32), `.ksplat`, `.gltf`, and a SOG `meta.json` (any `.json`).
GaussianScene read_scene_bytes(std::string_view bytes, const std::string& name);

}  // namespace lfd::scene
