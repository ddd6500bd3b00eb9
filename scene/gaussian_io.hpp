#pragma once
// Loading and saving Gaussian scenes. Formats are recognised by content and extension:
// standard 3DGS PLY (binary little-endian or ASCII, SH degree 0-3), PlayCanvas compressed PLY,
// antimatter15 .splat, Niantic SPZ v1-v4 (gzip or zstd), PlayCanvas SOG v1-v2 (.sog or
// meta.json), glTF/GLB with KHR_gaussian_splatting, .ksplat. Properties are found by name.
// Bad files throw lfd::InputError("<file>: <problem>"), never crash or exhaust memory.
#include <filesystem>

#include "scene/gaussian_scene.hpp"

namespace lfd::scene {

GaussianScene load_gaussian_scene(const std::filesystem::path& path);

// Writes a standard 3DGS binary little-endian PLY (stored, pre-activation values), atomically.
void save_ply(const std::filesystem::path& path, const GaussianScene& scene);

// Writes the scene in the format its extension names: `.ply` (save_ply) or `.spz` (SPZ v3,
// scene/spz_writer.hpp), atomically; InputError for another extension. What `lfd scene
// convert` calls.
void save_gaussian_scene(const std::filesystem::path& path, const GaussianScene& scene);

}  // namespace lfd::scene
