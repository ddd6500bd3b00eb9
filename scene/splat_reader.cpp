// antimatter15 .splat (antimatter15/splat convert.py; docs/rendering.md "Scene formats"): 32 bytes
// per Gaussian, no header: float32 position, float32 linear scale, RGBA bytes (DC colour, activated
// opacity), and a (w, x, y, z) quaternion as bytes decoded by (b - 128) / 128.
#include <cstring>

#include "scene/scene_checks.hpp"
#include "scene/scene_parsers.hpp"
#include "scene/sh_basis.hpp"
#include "util/error.hpp"

namespace lfd::scene {

namespace {
constexpr size_t kSplatRecordBytes = 32;
}

GaussianScene read_splat(std::string_view bytes, const std::string& name) {
  if (bytes.empty()) throw_input_error("{}: empty .splat file", name);
  if (bytes.size() % kSplatRecordBytes != 0)
    throw_input_error("{}: .splat size {} bytes is not a multiple of {} (truncated?)", name,
                      bytes.size(), kSplatRecordBytes);
  const size_t n = bytes.size() / kSplatRecordBytes;
  GaussianScene scene;
  resize_scene(scene, n, 0);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  for (size_t i = 0; i < n; ++i) {
    const unsigned char* r = data + i * kSplatRecordBytes;
    std::memcpy(scene.positions[i].data(), r, 12);
    std::memcpy(scene.scales[i].data(), r + 12, 12);
    float* sh = scene.sh.data() + i * 3;
    for (int c = 0; c < 3; ++c) sh[c] = color_to_sh_dc(float(r[24 + c]) / 255.0f);
    scene.opacities[i] = float(r[27]) / 255.0f;
    for (int k = 0; k < 4; ++k) scene.rotations[i][k] = (float(r[28 + k]) - 128.0f) / 128.0f;
  }
  finalize_scene(scene, name);
  return scene;
}

}  // namespace lfd::scene
