#pragma once
// Voxel scene files (docs/file-formats.md, "Sparse-voxel scenes"):
//   - lfd's own little-endian `.voxels` file (read and written), and
//   - the PLY the public svraster-webgl converter writes (read): one `vertex` per voxel with
//     its centre, `octlevel`, a 32-bit `octpath`, f_dc_*, f_rest_* (coefficient-major, RGB
//     innermost, unlike 3DGS PLYs) and grid0..7_value, plus header comments scene_center and
//     scene_extent.
// A PLY with `octlevel` and `grid0_value` is a voxel scene, never Gaussians (the Gaussian
// loader refuses it with a pointer here). Bad files throw InputError("<file>: <field>: ...").
#include <filesystem>
#include <string>
#include <string_view>

#include "scene/voxel_scene.hpp"

namespace lfd::scene {
struct PlyFile;
}

namespace lfd::scene {

// The `.voxels` file's first 8 bytes.
inline constexpr std::string_view kVoxelFileMagic{"LFDVOXEL", 8};
inline constexpr uint32_t kVoxelFileVersion = 1;

// In-memory readers (name = the path, or "<fuzz>", for messages).
VoxelScene read_voxel_file(std::string_view bytes, const std::string& name);
VoxelScene read_voxel_ply(std::string_view bytes, const std::string& name);
VoxelScene voxel_ply_to_scene(const scene::PlyFile& ply, const std::string& name);
// Either of the two, by content.
VoxelScene read_voxel_scene_bytes(std::string_view bytes, const std::string& name);

// The `.voxels` encoding of a scene (checked first).
std::string encode_voxel_file(const VoxelScene& scene);

// True if the file's first bytes say it is a voxel scene: the `.voxels` magic, or a PLY
// header that declares `octlevel` and `grid0_value` (reads only the header).
bool is_voxel_scene_file(const std::filesystem::path& path);

VoxelScene load_voxel_scene(const std::filesystem::path& path);
// Writes a `.voxels` file atomically.
void save_voxel_scene(const std::filesystem::path& path, const VoxelScene& scene);

}  // namespace lfd::scene
