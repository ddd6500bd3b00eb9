// Dispatch between the two voxel formats, and the file-system side of reading and writing.
#include <fstream>

#include "scene/ply_header.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"
#include "scene/voxel_io.hpp"

namespace lfd::scene {

VoxelScene read_voxel_scene_bytes(std::string_view bytes, const std::string& name) {
  if (bytes.empty()) throw_input_error("{}: empty file", name);
  if (bytes.substr(0, std::min(bytes.size(), kVoxelFileMagic.size())) == kVoxelFileMagic)
    return read_voxel_file(bytes, name);
  if (scene::looks_like_ply(bytes)) return read_voxel_ply(bytes, name);
  throw_input_error("{}: not a voxel scene (expected a .voxels file or an svraster-webgl PLY)", name);
}

bool is_voxel_scene_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  // A PLY header is text up to "end_header"; 64 KiB holds any real one.
  std::string head(65536, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(size_t(in.gcount()));
  if (head.rfind(kVoxelFileMagic, 0) == 0) return true;
  if (!scene::looks_like_ply(head)) return false;
  const size_t end = head.find("end_header");
  const std::string_view header = std::string_view(head).substr(0, end);
  return header.find(" octlevel") != std::string_view::npos &&
         header.find(" grid0_value") != std::string_view::npos;
}

VoxelScene load_voxel_scene(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw_input_error("{}: no such file", path.string());
  return read_voxel_scene_bytes(read_text_file(path), path.string());
}

void save_voxel_scene(const std::filesystem::path& path, const VoxelScene& scene) {
  const std::string bytes = encode_voxel_file(scene);
  write_file_atomic(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    if (!out) throw_input_error("{}: cannot write", path.string());
  });
}

}  // namespace lfd::scene
