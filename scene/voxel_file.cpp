// The `.voxels` file: a fixed little-endian header, then one fixed-size record per voxel
// (docs/file-formats.md). Counts are checked against the bytes present before allocating.
#include <bit>
#include <cstring>

#include "util/error.hpp"
#include "scene/voxel_io.hpp"

namespace lfd::scene {

static_assert(std::endian::native == std::endian::little, "the .voxels reader assumes a little-endian host");

namespace {

// magic[8] u32 version u32 sh_degree u64 count f32 center[3] f32 extent f32 ss u32 samples
// f32 background[3]
constexpr size_t kHeaderBytes = 8 + 4 + 4 + 8 + 12 + 4 + 4 + 4 + 12;

size_t record_bytes(int sh_degree) {
  // u32 index[3] u32 level f32 density[8] f32 sh[coeffs * 3]
  return 16 + 32 + size_t((sh_degree + 1) * (sh_degree + 1)) * 12;
}

class Reader {
 public:
  Reader(std::string_view bytes) : bytes_(bytes) {}
  template <typename T>
  T get() {
    T value;
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }

 private:
  std::string_view bytes_;
  size_t pos_ = 0;
};

template <typename T>
void put(std::string& out, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  out.append(raw, sizeof(T));
}

}  // namespace

VoxelScene read_voxel_file(std::string_view bytes, const std::string& name) {
  if (bytes.size() < kHeaderBytes) throw_input_error("{}: header: truncated ({} bytes)", name, bytes.size());
  if (bytes.substr(0, 8) != kVoxelFileMagic) throw_input_error("{}: magic: not a .voxels file", name);
  Reader r(bytes.substr(8));
  const auto version = r.get<uint32_t>();
  if (version != kVoxelFileVersion)
    throw_input_error("{}: version: {} is not supported (this reader knows {})", name, version, kVoxelFileVersion);
  VoxelScene s;
  const auto degree = r.get<uint32_t>();
  if (degree > 3) throw_input_error("{}: sh_degree: {} is not 0-3", name, degree);
  s.sh_degree = int(degree);
  const auto count = r.get<uint64_t>();
  const size_t record = record_bytes(s.sh_degree);
  if (count > (bytes.size() - kHeaderBytes) / record || bytes.size() - kHeaderBytes != count * record)
    throw_input_error("{}: count: {} voxels of {} bytes do not match the {} bytes after the header",
                      name, count, record, bytes.size() - kHeaderBytes);
  for (int a = 0; a < 3; ++a) s.scene_center[a] = r.get<float>();
  s.scene_extent = r.get<float>();
  s.supersampling = r.get<float>();
  const auto samples = r.get<uint32_t>();
  s.samples_per_voxel = samples > 64 ? 0 : int(samples);  // check_voxel_scene names it
  for (int a = 0; a < 3; ++a) s.background[a] = r.get<float>();
  s.resize(size_t(count));
  Reader v(bytes.substr(kHeaderBytes));
  const size_t sh_floats = size_t(s.sh_coeffs()) * 3;
  for (size_t i = 0; i < count; ++i) {
    for (int a = 0; a < 3; ++a) s.octree_index[i][a] = v.get<uint32_t>();
    const auto level = v.get<uint32_t>();
    if (level > uint32_t(kMaxOctreeLevel))
      throw_input_error("{}: voxel {}: level {} is above {}", name, i, level, kMaxOctreeLevel);
    s.level[i] = uint8_t(level);
    for (float& d : s.corner_density[i]) d = v.get<float>();
    float* sh = s.voxel_sh(i);
    for (size_t k = 0; k < sh_floats; ++k) sh[k] = v.get<float>();
  }
  check_voxel_scene(s, name);
  return s;
}

std::string encode_voxel_file(const VoxelScene& s) {
  check_voxel_scene(s, "voxel scene");
  std::string out;
  out.reserve(kHeaderBytes + s.size() * record_bytes(s.sh_degree));
  out.append(kVoxelFileMagic);
  put(out, kVoxelFileVersion);
  put(out, uint32_t(s.sh_degree));
  put(out, uint64_t(s.size()));
  for (int a = 0; a < 3; ++a) put(out, s.scene_center[a]);
  put(out, s.scene_extent);
  put(out, s.supersampling);
  put(out, uint32_t(s.samples_per_voxel));
  for (int a = 0; a < 3; ++a) put(out, s.background[a]);
  const size_t sh_floats = size_t(s.sh_coeffs()) * 3;
  for (size_t i = 0; i < s.size(); ++i) {
    for (int a = 0; a < 3; ++a) put(out, s.octree_index[i][a]);
    put(out, uint32_t(s.level[i]));
    for (float d : s.corner_density[i]) put(out, d);
    const float* sh = s.voxel_sh(i);
    for (size_t k = 0; k < sh_floats; ++k) put(out, sh[k]);
  }
  return out;
}

}  // namespace lfd::scene
