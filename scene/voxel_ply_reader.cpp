// The PLY of the public svraster-webgl converter. Its `octpath` is cut to 32 bits, which drops
// the coarsest levels of SVRaster's 48-bit path, so the integer octree position comes from the
// voxel centre, its level and the header comments scene_center / scene_extent instead.
#include <cmath>
#include <sstream>

#include "scene/ply_header.hpp"
#include "util/error.hpp"
#include "scene/voxel_io.hpp"

namespace lfd::scene {

namespace {

int require(const scene::PlyElement& v, const std::string& property, const std::string& name) {
  const int index = v.find(property);
  if (index < 0) throw_input_error("{}: {}: missing property of the voxel PLY", name, property);
  return index;
}

// The numbers after `key` in a header comment such as "scene_center 0.1 -0.2 1.5" (a ':', '=',
// ',' or brackets between them are accepted too).
std::vector<double> comment_numbers(const scene::PlyFile& ply, const std::string& key,
                                    size_t expected, const std::string& name) {
  for (const std::string& comment : ply.comments) {
    if (comment.rfind(key, 0) != 0) continue;
    std::string rest = comment.substr(key.size());
    for (char& c : rest)
      if (c == ':' || c == '=' || c == ',' || c == '[' || c == ']' || c == '(' || c == ')') c = ' ';
    std::istringstream in(rest);
    std::vector<double> values;
    double x;
    while (in >> x) values.push_back(x);
    if (values.size() != expected || !in.eof())
      throw_input_error("{}: comment {}: expected {} number(s), got '{}'", name, key, expected, comment);
    return values;
  }
  throw_input_error("{}: comment {}: missing from the PLY header (the voxel PLY needs it to place voxels)",
                    name, key);
}

int degree_for_rest(size_t rest_count, const std::string& name) {
  for (int d = 0; d <= 3; ++d)
    if (rest_count == size_t(3 * ((d + 1) * (d + 1) - 1))) return d;
  throw_input_error("{}: f_rest_*: {} coefficients match no SH degree 0-3", name, rest_count);
}

}  // namespace

VoxelScene voxel_ply_to_scene(const scene::PlyFile& ply, const std::string& name) {
  const scene::PlyElement* vertex = ply.find("vertex");
  if (!vertex) throw_input_error("{}: vertex: the voxel PLY has no 'vertex' element", name);
  const scene::PlyElement& v = *vertex;
  VoxelScene s;
  const auto center = comment_numbers(ply, "scene_center", 3, name);
  s.scene_center = glm::vec3(float(center[0]), float(center[1]), float(center[2]));
  s.scene_extent = float(comment_numbers(ply, "scene_extent", 1, name)[0]);
  if (!(std::isfinite(s.scene_extent) && s.scene_extent > 0.0f))
    throw_input_error("{}: comment scene_extent: {} must be positive", name, s.scene_extent);

  size_t rest_count = 0;
  for (const auto& p : v.properties)
    if (p.name.rfind("f_rest_", 0) == 0) ++rest_count;
  s.sh_degree = degree_for_rest(rest_count, name);
  const int xyz[3] = {require(v, "x", name), require(v, "y", name), require(v, "z", name)};
  const int level_property = require(v, "octlevel", name);
  int dc[3], grid[8];
  for (int c = 0; c < 3; ++c) dc[c] = require(v, "f_dc_" + std::to_string(c), name);
  for (int k = 0; k < 8; ++k) grid[k] = require(v, "grid" + std::to_string(k) + "_value", name);
  std::vector<int> rest(rest_count);
  for (size_t k = 0; k < rest_count; ++k) rest[k] = require(v, "f_rest_" + std::to_string(k), name);

  s.resize(v.count);
  const glm::vec3 root_min = s.scene_center - 0.5f * s.scene_extent;
  const size_t sh_floats = size_t(s.sh_coeffs()) * 3;
  for (size_t i = 0; i < v.count; ++i) {
    const double level = v.value(i, level_property);
    if (!(level >= 0.0 && level <= kMaxOctreeLevel && level == std::floor(level)))
      throw_input_error("{}: voxel {}: octlevel {} is not an integer in 0..{}", name, i, level, kMaxOctreeLevel);
    s.level[i] = uint8_t(level);
    const double size = std::ldexp(double(s.scene_extent), -int(level));
    const double cells = std::ldexp(1.0, int(level));
    for (int a = 0; a < 3; ++a) {
      const double c = v.value(i, xyz[a]);
      const double cell = (c - double(root_min[a])) / size - 0.5;  // integer at a voxel centre
      const double index = std::round(cell);
      // A centre more than a quarter voxel off the grid means the comments do not fit the file.
      if (!(std::abs(cell - index) < 0.25 && index >= 0.0 && index < cells))
        throw_input_error("{}: voxel {}: centre {} ({}) is not on the level-{} grid of scene_center/scene_extent",
                          name, i, "xyz"[a], c, int(level));
      s.octree_index[i][a] = uint32_t(index);
    }
    for (int k = 0; k < 8; ++k) s.corner_density[i][size_t(k)] = v.value_float(i, grid[k]);
    float* sh = s.voxel_sh(i);
    for (int c = 0; c < 3; ++c) sh[c] = v.value_float(i, dc[c]);
    // f_rest_* are coefficient-major with RGB innermost: the same layout as ours after f_dc.
    for (size_t k = 3; k < sh_floats; ++k) sh[k] = v.value_float(i, rest[k - 3]);
  }
  check_voxel_scene(s, name);
  return s;
}

VoxelScene read_voxel_ply(std::string_view bytes, const std::string& name) {
  return voxel_ply_to_scene(scene::parse_ply(bytes, name), name);
}

}  // namespace lfd::scene
