// Standard 3DGS PLY (gaussian_model.py load_ply; docs/rendering.md "Scene formats"): element
// `vertex`, properties found by name, SH degree inferred from the number of f_rest_* properties
// (0, 9, 24, 45), f_rest stored channel-major and converted to our coefficient-major layout.
#include <cmath>
#include <string>

#include "scene/ply_header.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_parsers.hpp"
#include "util/error.hpp"

namespace lfd::scene {

namespace {

int require(const PlyElement& e, const std::string& property, const std::string& name) {
  const int index = e.find(property);
  if (index < 0)
    throw_input_error("{}: PLY element '{}' has no property '{}'", name, e.name, property);
  return index;
}

int degree_for_rest_count(size_t rest, const std::string& name) {
  switch (rest) {
    case 0: return 0;
    case 9: return 1;
    case 24: return 2;
    case 45: return 3;
  }
  throw_input_error("{}: {} f_rest_* properties match no SH degree (0, 9, 24 or 45)", name, rest);
}

}  // namespace

GaussianScene read_standard_ply(std::string_view bytes, const std::string& name) {
  return standard_ply_to_scene(parse_ply(bytes, name), name);
}

GaussianScene standard_ply_to_scene(const PlyFile& ply, const std::string& name) {
  if (ply.find("chunk"))
    throw_input_error("{}: this is a compressed PLY (has a 'chunk' element)", name);
  const PlyElement* vertex = ply.find("vertex");
  if (!vertex) throw_input_error("{}: PLY has no 'vertex' element", name);
  const PlyElement& v = *vertex;
  // svraster-webgl's sparse-voxel PLY also has a vertex element with f_dc/f_rest (voxel/).
  if (v.find("octlevel") >= 0 && v.find("grid0_value") >= 0)
    throw_input_error("{}: a sparse-voxel PLY (octlevel, grid0..7_value), not Gaussians: "
                      "read it as a voxel scene (lfd render --scene takes either)", name);

  size_t rest_count = 0;
  for (const auto& p : v.properties)
    if (p.name.rfind("f_rest_", 0) == 0) ++rest_count;
  const int degree = degree_for_rest_count(rest_count, name);
  const size_t rest_per_channel = rest_count / 3;

  const int xyz[3] = {require(v, "x", name), require(v, "y", name), require(v, "z", name)};
  const int dc[3] = {require(v, "f_dc_0", name), require(v, "f_dc_1", name),
                     require(v, "f_dc_2", name)};
  const int opacity = require(v, "opacity", name);
  const int scale[3] = {require(v, "scale_0", name), require(v, "scale_1", name),
                        require(v, "scale_2", name)};
  const int rot[4] = {require(v, "rot_0", name), require(v, "rot_1", name),
                      require(v, "rot_2", name), require(v, "rot_3", name)};
  std::vector<int> rest(rest_count);
  for (size_t k = 0; k < rest_count; ++k) rest[k] = require(v, "f_rest_" + std::to_string(k), name);

  GaussianScene scene;
  resize_scene(scene, v.count, degree);
  const size_t coeffs = size_t(scene.sh_coeffs());
  for (size_t i = 0; i < v.count; ++i) {
    for (int a = 0; a < 3; ++a) {
      scene.positions[i][a] = v.value_float(i, xyz[a]);
      scene.scales[i][a] = std::exp(v.value_float(i, scale[a]));
    }
    for (int a = 0; a < 4; ++a) scene.rotations[i][a] = v.value_float(i, rot[a]);
    scene.opacities[i] = sigmoid(v.value_float(i, opacity));
    float* sh = scene.sh.data() + i * coeffs * 3;
    for (int c = 0; c < 3; ++c) sh[c] = v.value_float(i, dc[c]);
    // f_rest[ch * K + k] is coefficient k + 1 of channel ch (gaussian_model.py save_ply).
    for (size_t ch = 0; ch < 3; ++ch)
      for (size_t k = 0; k < rest_per_channel; ++k)
        sh[(k + 1) * 3 + ch] = v.value_float(i, rest[ch * rest_per_channel + k]);
  }
  finalize_scene(scene, name);
  return scene;
}

}  // namespace lfd::scene
