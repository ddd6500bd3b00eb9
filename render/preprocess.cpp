// Stage 1 of the reference forward pass (forward.cu preprocessCUDA, computeCov3D,
// computeCov2D; docs/rendering.md "The CPU reference rasterizer"), in float32 as the CUDA code.
#include <algorithm>
#include <cmath>

#include "render/preprocess.hpp"
#include "render/spherical_harmonics.hpp"

namespace lfd::render {

// Section 3.2: Sigma = R S S^T R^T of the unit quaternion (w, x, y, z).
glm::mat3 covariance_3d(const std::array<float, 3>& scale, float modifier,
                        const std::array<float, 4>& q) {
  const float r = q[0], x = q[1], y = q[2], z = q[3];
  // glm is column-major: R[col][row]; this is R (row-major text) transposed into glm order.
  glm::mat3 R;
  R[0] = glm::vec3(1.f - 2.f * (y * y + z * z), 2.f * (x * y + r * z), 2.f * (x * z - r * y));
  R[1] = glm::vec3(2.f * (x * y - r * z), 1.f - 2.f * (x * x + z * z), 2.f * (y * z + r * x));
  R[2] = glm::vec3(2.f * (x * z + r * y), 2.f * (y * z - r * x), 1.f - 2.f * (x * x + y * y));
  glm::mat3 S(0.0f);
  S[0][0] = modifier * scale[0];
  S[1][1] = modifier * scale[1];
  S[2][2] = modifier * scale[2];
  const glm::mat3 M = R * S;
  return M * glm::transpose(M);
}

namespace {

// Section 3.3 with the principal-point shift: the 1.3 tan(fov/2) clamp window becomes
// [-(1 + p) tan - 0.3 tan, (1 - p) tan + 0.3 tan], i.e. the visible NDC range widened by 0.3 tan
// on each side (gsplat's form; identical to the reference when p = 0).
glm::vec3 covariance_2d(const glm::vec3& t_in, const Camera& cam, const glm::mat3& cov3d,
                        float dilation) {
  glm::vec3 t = t_in;
  const float tan_x = cam.tan_half_fov_x(), tan_y = cam.tan_half_fov_y();
  const float lim_x_pos = (1.0f - cam.shift_x_ndc) * tan_x + 0.3f * tan_x;
  const float lim_x_neg = (1.0f + cam.shift_x_ndc) * tan_x + 0.3f * tan_x;
  const float lim_y_pos = (1.0f - cam.shift_y_ndc) * tan_y + 0.3f * tan_y;
  const float lim_y_neg = (1.0f + cam.shift_y_ndc) * tan_y + 0.3f * tan_y;
  const float txtz = t.x / t.z, tytz = t.y / t.z;
  t.x = std::min(lim_x_pos, std::max(-lim_x_neg, txtz)) * t.z;
  t.y = std::min(lim_y_pos, std::max(-lim_y_neg, tytz)) * t.z;
  const float fx = cam.focal_x_px(), fy = cam.focal_y_px();
  // J rows: (fx/z, 0, -fx x/z^2), (0, fy/z, -fy y/z^2); only the upper 2x3 matters.
  glm::mat3 J(0.0f);  // J[col][row]
  J[0][0] = fx / t.z;
  J[2][0] = -(fx * t.x) / (t.z * t.z);
  J[1][1] = fy / t.z;
  J[2][1] = -(fy * t.y) / (t.z * t.z);
  const glm::mat3 T = J * cam.world_to_camera;
  const glm::mat3 cov = T * cov3d * glm::transpose(T);
  return {cov[0][0] + dilation, cov[1][0], cov[1][1] + dilation};
}

}  // namespace

std::vector<ProjectedGaussian> preprocess(const scene::GaussianScene& scene, const Camera& camera,
                                          const RasterSettings& settings,
                                          std::span<const uint32_t> subset) {
  const size_t n = subset.empty() ? scene.size() : subset.size();
  std::vector<ProjectedGaussian> out(n);
  const int grid_x = (camera.width + kTileSize - 1) / kTileSize;
  const int grid_y = (camera.height + kTileSize - 1) / kTileSize;
  const int degree = settings.sh_degree < 0 ? scene.sh_degree : std::min(settings.sh_degree, scene.sh_degree);
  const glm::vec3 sh_origin = settings.sh_origin.value_or(camera.position_world);
  const float W = float(camera.width), H = float(camera.height);

#pragma omp parallel for schedule(static, 4096)
  for (long long ii = 0; ii < (long long)n; ++ii) {
    const size_t i = subset.empty() ? size_t(ii) : subset[size_t(ii)];
    ProjectedGaussian& g = out[size_t(ii)];
    const auto& p = scene.positions[i];
    const glm::vec3 mean(p[0], p[1], p[2]);
    const glm::vec3 t = camera.to_camera(mean);
    if (t.z <= 0.2f) continue;  // in_frustum: near cull only (auxiliary.h)

    const glm::mat3 cov3d = covariance_3d(scene.scales[i], settings.scale_modifier, scene.rotations[i]);
    const glm::vec3 cov = covariance_2d(t, camera, cov3d, settings.dilation_px2);
    const float det = cov.x * cov.z - cov.y * cov.y;
    if (det == 0.0f) continue;
    const float det_inv = 1.0f / det;
    const glm::vec3 conic(cov.z * det_inv, -cov.y * det_inv, cov.x * det_inv);

    const float mid = 0.5f * (cov.x + cov.z);
    const float lambda1 = mid + std::sqrt(std::max(0.1f, mid * mid - det));
    const float lambda2 = mid - std::sqrt(std::max(0.1f, mid * mid - det));
    const float radius = std::ceil(3.0f * std::sqrt(std::max(lambda1, lambda2)));
    const glm::vec2 ndc = camera.project_ndc(mean);
    const glm::vec2 px(((ndc.x + 1.0f) * W - 1.0f) * 0.5f, ((ndc.y + 1.0f) * H - 1.0f) * 0.5f);
    // getRect (auxiliary.h): int() truncates toward zero, as in CUDA.
    const glm::ivec2 rmin(std::min(grid_x, std::max(0, int((px.x - radius) / kTileSize))),
                          std::min(grid_y, std::max(0, int((px.y - radius) / kTileSize))));
    const glm::ivec2 rmax(std::min(grid_x, std::max(0, int((px.x + radius + kTileSize - 1) / kTileSize))),
                          std::min(grid_y, std::max(0, int((px.y + radius + kTileSize - 1) / kTileSize))));
    if ((rmax.x - rmin.x) * (rmax.y - rmin.y) == 0) continue;

    const glm::vec3 dir = glm::normalize(mean - sh_origin);
    g.color = eval_sh_color(degree, scene.sh_of(i), dir);
    g.mean_px = px;
    g.conic = conic;
    g.opacity = scene.opacities[i];
    g.depth = t.z;
    g.radius_px = int(radius);
    g.rect_min = rmin;
    g.rect_max = rmax;
  }
  return out;
}

}  // namespace lfd::render
