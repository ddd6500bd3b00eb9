#include "scene/ply_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

namespace lfd::scene {

namespace {

// The logit of an opacity that may be exactly 0 or 1 (e.g. from an 8-bit format); clamped so
// the stored value stays finite and round-trips to within 1e-6.
float logit(float opacity) {
  const float o = std::clamp(opacity, 1e-7f, 1.0f - 1e-7f);
  return std::log(o / (1.0f - o));
}

// One Gaussian's row in file order: x y z nx ny nz f_dc_0..2 f_rest_* opacity scale_0..2 rot_0..3.
void stored_row(const GaussianScene& scene, size_t i, std::vector<float>& row) {
  row.clear();
  for (float p : scene.positions[i]) row.push_back(p);
  row.insert(row.end(), {0.0f, 0.0f, 0.0f});
  const float* sh = scene.sh_of(i);
  for (int c = 0; c < 3; ++c) row.push_back(sh[c]);
  const int rest = scene.sh_coeffs() - 1;
  for (int ch = 0; ch < 3; ++ch)
    for (int k = 0; k < rest; ++k) row.push_back(sh[(k + 1) * 3 + ch]);
  row.push_back(logit(scene.opacities[i]));
  for (float s : scene.scales[i]) row.push_back(std::log(s));
  for (float q : scene.rotations[i]) row.push_back(q);
}

}  // namespace

std::string encode_ply(const GaussianScene& scene, PlyEncoding encoding) {
  const bool ascii = encoding == PlyEncoding::Ascii;
  std::string out = fmt::format("ply\nformat {} 1.0\nelement vertex {}\n",
                                ascii ? "ascii" : "binary_little_endian", scene.size());
  auto property = [&](const std::string& n) { out += "property float " + n + "\n"; };
  for (const char* n : {"x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2"})
    property(n);
  const int rest = 3 * (scene.sh_coeffs() - 1);
  for (int k = 0; k < rest; ++k) property(fmt::format("f_rest_{}", k));
  for (const char* n : {"opacity", "scale_0", "scale_1", "scale_2", "rot_0", "rot_1", "rot_2",
                        "rot_3"})
    property(n);
  out += "end_header\n";

  const size_t floats = size_t(9 + rest + 8);
  std::vector<float> row;
  row.reserve(floats);
  if (!ascii) out.reserve(out.size() + scene.size() * floats * sizeof(float));
  for (size_t i = 0; i < scene.size(); ++i) {
    stored_row(scene, i, row);
    if (ascii) {
      // {} prints the shortest representation that reads back to the same float.
      out += fmt::format("{}\n", fmt::join(row, " "));
    } else {
      out.append(reinterpret_cast<const char*>(row.data()), row.size() * sizeof(float));
    }
  }
  return out;
}

}  // namespace lfd::scene
