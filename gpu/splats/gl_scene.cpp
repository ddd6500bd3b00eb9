#include "gpu/splats/gl_scene.hpp"

#include <algorithm>
#include <vector>

#include "util/error.hpp"

namespace lfd::gpu {
namespace {

constexpr size_t kRecordBytes = 64;            // SplatRecord (gpu/splats/shaders/splat_record_io.h)

double mib(double bytes) { return bytes / 1048576.0; }

}  // namespace

int sh_vec4_stride(int sh_degree) {
  const int floats = 3 * (sh_degree + 1) * (sh_degree + 1);
  return (floats + 3) / 4;
}

size_t scene_bytes_per_gaussian(int sh_degree) {
  return 3 * 16 + size_t(sh_vec4_stride(sh_degree)) * 16;
}

size_t per_view_scratch_bytes_per_gaussian() {
  return kRecordBytes + 2 * 4 /* keys, values */ + 2 * 4 /* their sort copies */;
}

void check_scene_fits(size_t gaussians, int sh_degree, const GlInfo& info) {
  if (gaussians > 0xFFFFFFFFull)
    throw_input_error("scene of {} Gaussians is beyond the GL renderer's 32-bit indices (at most {})",
                      gaussians, 0xFFFFFFFFull);
  const double sh_bytes = double(gaussians) * sh_vec4_stride(sh_degree) * 16;
  const double record_bytes = double(gaussians) * kRecordBytes;
  const double limit = double(info.max_ssbo_bytes);
  if (info.max_ssbo_bytes > 0 && std::max(sh_bytes, record_bytes) > limit) {
    if (sh_bytes >= record_bytes && sh_degree > 0)
      throw_input_error(
          "scene of {} Gaussians at SH degree {} needs a {:.0f} MiB SH buffer, above this GPU's "
          "limit of {:.0f} MiB per storage buffer (GL_MAX_SHADER_STORAGE_BLOCK_SIZE); lower "
          "--sh-degree (degree 0 needs {:.0f} MiB) or use a smaller scene",
          gaussians, sh_degree, mib(sh_bytes), mib(limit), mib(double(gaussians) * 16));
    throw_input_error(
        "scene of {} Gaussians needs a {:.0f} MiB buffer, above this GPU's limit of {:.0f} MiB per "
        "storage buffer (GL_MAX_SHADER_STORAGE_BLOCK_SIZE); at most {} Gaussians fit: use a smaller scene",
        gaussians, mib(std::max(sh_bytes, record_bytes)), mib(limit),
        size_t(limit / std::max<double>(kRecordBytes, sh_vec4_stride(sh_degree) * 16.0)));
  }
  if (info.free_memory_bytes) {
    const double scene = double(gaussians) * scene_bytes_per_gaussian(sh_degree);
    const double scratch = double(gaussians) * per_view_scratch_bytes_per_gaussian();
    if (scene + scratch > double(*info.free_memory_bytes) && sh_degree == 0)
      throw_input_error(
          "scene of {} Gaussians at SH degree 0 needs {:.0f} MiB of GPU memory (scene {:.0f} + "
          "render buffers {:.0f}) but {:.0f} MiB are free; use a smaller scene",
          gaussians, mib(scene + scratch), mib(scene), mib(scratch), mib(double(*info.free_memory_bytes)));
    if (scene + scratch > double(*info.free_memory_bytes))
      throw_input_error(
          "scene of {} Gaussians at SH degree {} needs {:.0f} MiB of GPU memory (scene {:.0f} + "
          "render buffers {:.0f}) but {:.0f} MiB are free; lower --sh-degree (degree 0: {:.0f} MiB) "
          "or use a smaller scene",
          gaussians, sh_degree, mib(scene + scratch), mib(scene), mib(scratch),
          mib(double(*info.free_memory_bytes)),
          mib(double(gaussians) * (scene_bytes_per_gaussian(0) + per_view_scratch_bytes_per_gaussian())));
  }
}

int fitting_sh_degree(size_t gaussians, int scene_degree, const GlInfo& info) {
  for (int degree = std::max(scene_degree, 0); degree > 0; --degree) {
    try {
      check_scene_fits(gaussians, degree, info);
      return degree;
    } catch (const InputError&) {
      // the next lower degree stores fewer coefficients per Gaussian
    }
  }
  check_scene_fits(gaussians, 0, info);
  return 0;
}

GlScene::GlScene(const scene::GaussianScene& scene, const GlInfo& info, const GlSceneOptions& options)
    : count_(scene.size()),
      sh_degree_(options.max_sh_degree < 0 ? scene.sh_degree
                                           : std::min(options.max_sh_degree, scene.sh_degree)) {
  check_scene_fits(count_, sh_degree_, info);
  if (options.chunk_gaussians == 0) throw_input_error("scene upload: chunk_gaussians: 0 (expected > 0)");
  const size_t chunk = options.chunk_gaussians;
  const int stride = gpu::sh_vec4_stride(sh_degree_);
  const int scene_coeffs = scene.sh_coeffs(), coeffs = (sh_degree_ + 1) * (sh_degree_ + 1);
  positions_ = Buffer(count_ * 16);
  scales_ = Buffer(count_ * 16);
  rotations_ = Buffer(count_ * 16);
  sh_ = Buffer(count_ * size_t(stride) * 16);

  // Packed on the CPU a chunk at a time so a large scene never holds a second full copy.
  std::vector<float> pos, scl, rot, shc;
  for (size_t begin = 0; begin < count_; begin += chunk) {
    const size_t n = std::min(chunk, count_ - begin);
    pos.assign(n * 4, 0.0f);
    scl.assign(n * 4, 0.0f);
    rot.assign(n * 4, 0.0f);
    shc.assign(n * size_t(stride) * 4, 0.0f);
    for (size_t k = 0; k < n; ++k) {
      const size_t i = begin + k;
      for (int c = 0; c < 3; ++c) {
        pos[4 * k + c] = scene.positions[i][c];
        scl[4 * k + c] = scene.scales[i][c];
      }
      pos[4 * k + 3] = scene.opacities[i];
      for (int c = 0; c < 4; ++c) rot[4 * k + c] = scene.rotations[i][c];
      const float* src = scene.sh.data() + i * size_t(scene_coeffs) * 3;
      std::copy(src, src + coeffs * 3, shc.begin() + ptrdiff_t(k * size_t(stride) * 4));
    }
    positions_.upload(pos.data(), n * 16, begin * 16);
    scales_.upload(scl.data(), n * 16, begin * 16);
    rotations_.upload(rot.data(), n * 16, begin * 16);
    sh_.upload(shc.data(), n * size_t(stride) * 16, begin * size_t(stride) * 16);
    if (options.progress) options.progress(begin + n, count_);
  }
  check_gl("uploading the scene");
}

size_t GlScene::bytes() const {
  return positions_.bytes() + scales_.bytes() + rotations_.bytes() + sh_.bytes();
}

}  // namespace lfd::gpu
