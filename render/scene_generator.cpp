// Procedural scenes (scene_generator.hpp). Metres-like units, objects within ~3 units of the
// origin on a ground plane, a far background (dome or end wall). Layouts are built y-up and
// then turned 180 degrees about x into the frame of trained 3DGS scenes (COLMAP: y down, camera
// looking along +z), so the same default camera suits generated and real scenes: ground at
// y = +1, "up" is -y, the front row of objects at z < 0 faces a camera at z ~ -5. Every
// Gaussian lies on a surface: flat along the surface normal, anisotropic in the tangent plane,
// with per-object colours and small view-dependent SH terms (degree >= 1) so renderers see
// realistic occlusion, depth layers and colour that varies per view.
//
// Determinism: Gaussian i belongs to a fixed component (ranges from the counts) and block
// i / kBlock draws from its own std::mt19937_64 seeded from (seed, block), so the result does
// not depend on the number of threads.
#include "render/scene_generator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "scene/scene_checks.hpp"
#include "render/spherical_harmonics.hpp"
#include "util/error.hpp"

namespace lfd::render {

namespace {

using Vec3 = std::array<float, 3>;
constexpr float kPi = std::numbers::pi_v<float>;
constexpr size_t kBlock = 1 << 14;
constexpr size_t kMaxCount = size_t(1) << 28;

Vec3 operator+(Vec3 a, Vec3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 operator*(float s, Vec3 a) { return {s * a[0], s * a[1], s * a[2]}; }
Vec3 cross(Vec3 a, Vec3 b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 normalized(Vec3 a) {
  const float n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return n > 0 ? (1.0f / n) * a : Vec3{0, 0, 1};
}

enum class Shape { Plane, Sphere, Box, Torus, Dome };

// Pattern painted on a surface: a base colour, a second colour, a checker/stripe period.
struct Paint {
  Vec3 base{0.5f, 0.5f, 0.5f};
  Vec3 alt{0.5f, 0.5f, 0.5f};
  float period = 0;         // 0 = plain
  Vec3 specular{0, 0, 0};   // SH degree-1 tint: brighter towards +normal views
  float opacity = 0.85f;
};

struct Component {
  Shape shape = Shape::Sphere;
  Vec3 center{0, 0, 0};
  Vec3 size{1, 1, 1};   // plane: half extents along its two axes (x, z) ; box: half extents;
                        // sphere: radius in size[0]; torus: R, r; dome: radius
  Vec3 plane_u{1, 0, 0}, plane_v{0, 0, 1};  // plane axes (normal = u x v... oriented below)
  Vec3 plane_normal{0, 1, 0};
  Paint paint;
  double weight = 1;    // share of the Gaussian budget
  double area = 1;      // surface area, sets the Gaussian spacing
  size_t first = 0, count = 0;
};

struct Sample {
  Vec3 position, normal, tangent;
  float u = 0, v = 0;  // surface coordinates for the paint pattern, in scene units
};

Vec3 hsv(float h, float s, float v) {
  const float c = v * s, hp = std::fmod(h, 1.0f) * 6.0f;
  const float x = c * (1 - std::fabs(std::fmod(hp, 2.0f) - 1));
  Vec3 rgb{};
  switch (int(hp)) {
    case 0: rgb = {c, x, 0}; break;
    case 1: rgb = {x, c, 0}; break;
    case 2: rgb = {0, c, x}; break;
    case 3: rgb = {0, x, c}; break;
    case 4: rgb = {x, 0, c}; break;
    default: rgb = {c, 0, x}; break;
  }
  return rgb + Vec3{v - c, v - c, v - c};
}

Sample sample(const Component& c, std::mt19937_64& rng) {
  std::uniform_real_distribution<float> U(0.0f, 1.0f);
  Sample s;
  switch (c.shape) {
    case Shape::Plane: {
      const float a = (2 * U(rng) - 1) * c.size[0], b = (2 * U(rng) - 1) * c.size[1];
      s.position = c.center + a * c.plane_u + b * c.plane_v;
      s.normal = c.plane_normal;
      s.tangent = c.plane_u;
      s.u = a, s.v = b;
      break;
    }
    case Shape::Sphere:
    case Shape::Dome: {
      const float z = c.shape == Shape::Dome ? -0.25f + 1.25f * U(rng) : 2 * U(rng) - 1;
      const float phi = 2 * kPi * U(rng), r = std::sqrt(std::max(0.0f, 1 - z * z));
      // Dome: z is the elevation along +y; the shell faces inwards.
      const Vec3 d = c.shape == Shape::Dome ? Vec3{r * std::cos(phi), z, r * std::sin(phi)}
                                            : Vec3{r * std::cos(phi), r * std::sin(phi), z};
      s.position = c.center + c.size[0] * d;
      s.normal = c.shape == Shape::Dome ? -1.0f * d : d;
      s.tangent = normalized(cross(Vec3{0, 1, 0.01f}, d));
      s.u = phi * c.size[0] / (2 * kPi) * 4, s.v = z * c.size[0];
      break;
    }
    case Shape::Box: {
      const Vec3& h = c.size;
      const float areas[3] = {h[1] * h[2], h[0] * h[2], h[0] * h[1]};  // faces normal to x, y, z
      float pick = U(rng) * (areas[0] + areas[1] + areas[2]);
      int axis = 0;
      while (axis < 2 && pick > areas[axis]) pick -= areas[axis++];
      const float sign = U(rng) < 0.5f ? -1.0f : 1.0f;
      Vec3 local{(2 * U(rng) - 1) * h[0], (2 * U(rng) - 1) * h[1], (2 * U(rng) - 1) * h[2]};
      local[axis] = sign * h[axis];
      s.position = c.center + local;
      s.normal = {0, 0, 0};
      s.normal[axis] = sign;
      s.tangent = {0, 0, 0};
      s.tangent[(axis + 1) % 3] = 1;
      s.u = local[(axis + 1) % 3], s.v = local[(axis + 2) % 3];
      break;
    }
    case Shape::Torus: {
      const float R = c.size[0], r = c.size[1];
      float theta = 0, phi = 0;
      // Area element ~ (R + r cos(phi)): rejection sampling keeps the density uniform.
      do {
        theta = 2 * kPi * U(rng);
        phi = 2 * kPi * U(rng);
      } while (U(rng) * (R + r) > R + r * std::cos(phi));
      // The torus stands upright (axis along z), like a ring facing the camera.
      const Vec3 ring{std::cos(theta), std::sin(theta), 0};
      const Vec3 n = std::cos(phi) * ring + Vec3{0, 0, std::sin(phi)};
      s.position = c.center + R * ring + r * n;
      s.normal = n;
      s.tangent = {-std::sin(theta), std::cos(theta), 0};
      s.u = theta * R, s.v = phi * r;
      break;
    }
  }
  return s;
}

// Quaternion (w, x, y, z) of the rotation whose columns are (t1, t2, n).
std::array<float, 4> quaternion_from_frame(Vec3 t1, Vec3 t2, Vec3 n) {
  const float m00 = t1[0], m11 = t2[1], m22 = n[2];
  const float m21 = t2[2], m12 = n[1], m02 = n[0], m20 = t1[2], m10 = t1[1], m01 = t2[0];
  const float trace = m00 + m11 + m22;
  std::array<float, 4> q{};
  if (trace > 0) {
    const float s = 0.5f / std::sqrt(trace + 1);
    q = {0.25f / s, (m21 - m12) * s, (m02 - m20) * s, (m10 - m01) * s};
  } else if (m00 > m11 && m00 > m22) {
    const float s = 2 * std::sqrt(1 + m00 - m11 - m22);
    q = {(m21 - m12) / s, 0.25f * s, (m01 + m10) / s, (m02 + m20) / s};
  } else if (m11 > m22) {
    const float s = 2 * std::sqrt(1 + m11 - m00 - m22);
    q = {(m02 - m20) / s, (m01 + m10) / s, 0.25f * s, (m12 + m21) / s};
  } else {
    const float s = 2 * std::sqrt(1 + m22 - m00 - m11);
    q = {(m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, 0.25f * s};
  }
  const float len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (float& c : q) c /= len;
  return q;
}

Paint random_paint(std::mt19937_64& rng, float period) {
  std::uniform_real_distribution<float> U(0.0f, 1.0f);
  Paint p;
  const float hue = U(rng);
  p.base = hsv(hue, 0.45f + 0.45f * U(rng), 0.55f + 0.4f * U(rng));
  p.alt = hsv(hue + 0.08f + 0.2f * U(rng), 0.3f + 0.5f * U(rng), 0.3f + 0.4f * U(rng));
  p.period = period;
  const float shine = 0.1f + 0.25f * U(rng);
  p.specular = {shine, shine, shine};
  p.opacity = 0.7f + 0.25f * U(rng);
  return p;
}

Component plane(Vec3 center, Vec3 u, Vec3 v, float half_u, float half_v, Vec3 normal,
                Paint paint, double weight) {
  Component c;
  c.shape = Shape::Plane;
  c.center = center, c.plane_u = u, c.plane_v = v, c.plane_normal = normal;
  c.size = {half_u, half_v, 0};
  c.area = 4.0 * half_u * half_v;
  c.paint = paint, c.weight = weight;
  return c;
}

Component object(Shape shape, Vec3 center, Vec3 size, Paint paint) {
  Component c;
  c.shape = shape, c.center = center, c.size = size, c.paint = paint;
  switch (shape) {
    case Shape::Sphere: c.area = 4 * kPi * size[0] * size[0]; break;
    case Shape::Box:
      c.area = 8.0 * (size[0] * size[1] + size[1] * size[2] + size[0] * size[2]);
      break;
    case Shape::Torus: c.area = 4 * kPi * kPi * size[0] * size[1]; break;
    default: break;
  }
  c.weight = c.area;
  return c;
}

// Objects resting on the ground at y = -1, arranged in depth rows so the scene has distinct
// depth layers in front of, at and behind the origin.
void add_objects(std::vector<Component>& out, std::mt19937_64& rng,
                 const std::vector<float>& row_depths, float spread_x, int per_row) {
  std::uniform_real_distribution<float> U(0.0f, 1.0f);
  for (float z : row_depths) {
    for (int k = 0; k < per_row; ++k) {
      const float x = -spread_x + 2 * spread_x * (float(k) + 0.5f) / float(per_row) +
                      (U(rng) - 0.5f) * 0.3f;
      const float zz = z + (U(rng) - 0.5f) * 0.4f;
      const Shape shape = std::array{Shape::Sphere, Shape::Box, Shape::Torus}[rng() % 3];
      const Paint paint = random_paint(rng, U(rng) < 0.5f ? 0.0f : 0.1f + 0.1f * U(rng));
      if (shape == Shape::Sphere) {
        const float r = 0.25f + 0.3f * U(rng);
        out.push_back(object(shape, {x, -1 + r, zz}, {r, r, r}, paint));
      } else if (shape == Shape::Box) {
        const Vec3 h{0.2f + 0.25f * U(rng), 0.2f + 0.4f * U(rng), 0.2f + 0.25f * U(rng)};
        out.push_back(object(shape, {x, -1 + h[1], zz}, h, paint));
      } else {
        const float R = 0.3f + 0.2f * U(rng), r = 0.07f + 0.08f * U(rng);
        out.push_back(object(shape, {x, -1 + R + r, zz}, {R, r, 0}, paint));
      }
    }
  }
}

std::vector<Component> tabletop(std::mt19937_64& rng) {
  std::vector<Component> c;
  Paint ground{{0.55f, 0.5f, 0.45f}, {0.35f, 0.32f, 0.3f}, 0.5f, {0.05f, 0.05f, 0.05f}, 0.9f};
  // The table top just holds the three rows of objects (x within 2.5 of 0, z from -3.25 to
  // 2.25), so a framing of the content (render/default_camera.hpp) is filled by the objects.
  c.push_back(plane({0, -1, -0.5f}, {1, 0, 0}, {0, 0, 1}, 3.0f, 2.75f, {0, 1, 0}, ground, 0));
  add_objects(c, rng, {-2.5f, -0.5f, 1.5f}, 2.2f, 3);
  Paint sky{{0.55f, 0.7f, 0.9f}, {0.85f, 0.85f, 0.9f}, 3.0f, {0, 0, 0}, 0.95f};
  Component dome;
  dome.shape = Shape::Dome, dome.center = {0, -1, 0}, dome.size = {12, 0, 0}, dome.paint = sky;
  dome.area = 4 * kPi * 12 * 12 * (1.25 / 2);  // the band of elevations sample() covers
  c.push_back(dome);
  return c;
}

std::vector<Component> corridor(std::mt19937_64& rng) {
  std::vector<Component> c;
  const float near_z = 3, far_z = -12, half_w = 1.6f, top = 1.6f;
  const float mid_z = 0.5f * (near_z + far_z), half_len = 0.5f * (near_z - far_z);
  Paint floor{{0.5f, 0.45f, 0.4f}, {0.3f, 0.27f, 0.25f}, 0.5f, {0.05f, 0.05f, 0.05f}, 0.9f};
  Paint wall = random_paint(rng, 1.0f);
  wall.opacity = 0.9f;
  c.push_back(plane({0, -1, mid_z}, {1, 0, 0}, {0, 0, 1}, half_w, half_len, {0, 1, 0}, floor, 0));
  c.push_back(plane({0, top, mid_z}, {1, 0, 0}, {0, 0, 1}, half_w, half_len, {0, -1, 0}, wall, 0));
  const float wall_half_h = 0.5f * (top + 1), wall_y = 0.5f * (top - 1);
  c.push_back(plane({-half_w, wall_y, mid_z}, {0, 1, 0}, {0, 0, 1}, wall_half_h, half_len,
                    {1, 0, 0}, wall, 0));
  c.push_back(plane({half_w, wall_y, mid_z}, {0, 1, 0}, {0, 0, 1}, wall_half_h, half_len,
                    {-1, 0, 0}, wall, 0));
  add_objects(c, rng, {1.5f, -1.5f, -4.5f, -7.5f}, 0.9f, 2);
  Paint end = random_paint(rng, 0.4f);
  end.opacity = 0.95f;
  c.push_back(plane({0, wall_y, far_z}, {1, 0, 0}, {0, 1, 0}, half_w, wall_half_h, {0, 0, 1},
                    end, 0));
  return c;
}

// Splits `total` Gaussians over the components: ground/walls and objects by area, the far
// dome a fixed 2% (a smooth backdrop of large splats needs little detail). Keeping it under
// the 1% tails per side of scene::robust_bounds() lets the default framing follow the objects.
void assign_counts(std::vector<Component>& comps, size_t total) {
  const bool has_dome =
      std::any_of(comps.begin(), comps.end(), [](const auto& c) { return c.shape == Shape::Dome; });
  const double surface_share = has_dome ? 0.98 : 1.0;
  size_t assigned = 0;
  for (auto& c : comps) {
    // Objects get 3x their area share: they carry the detail a viewer looks at.
    const double boost = c.shape == Shape::Plane ? 1.0 : 3.0;
    c.weight = c.shape == Shape::Dome ? 1.0 - surface_share : surface_share * boost * c.area;
  }
  double weight_sum = 0;
  for (const auto& c : comps) weight_sum += c.shape == Shape::Dome ? 0 : c.weight;
  for (auto& c : comps) {
    const double share =
        c.shape == Shape::Dome ? c.weight : surface_share * c.weight / weight_sum;
    c.count = size_t(std::floor(share * double(total)));
    assigned += c.count;
  }
  comps.front().count += total - assigned;  // rounding remainder to the ground
  size_t first = 0;
  for (auto& c : comps) {
    c.first = first;
    first += c.count;
  }
}

uint64_t splitmix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

void fill_gaussian(scene::GaussianScene& scene, size_t i, const Component& c, std::mt19937_64& rng) {
  std::uniform_real_distribution<float> U(0.0f, 1.0f);
  std::normal_distribution<float> N(0.0f, 1.0f);
  Sample s = sample(c, rng);
  // y-up layout -> COLMAP frame: a proper rotation (180 degrees about x), handedness kept.
  for (Vec3* v : {&s.position, &s.normal, &s.tangent}) *v = {(*v)[0], -(*v)[1], -(*v)[2]};
  // Spacing of a uniform cover of the surface by c.count discs; tangent scales slightly larger
  // so neighbours overlap (no holes), normal scale thin (surfaces, not blobs).
  const float spacing = float(std::sqrt(c.area / double(std::max<size_t>(c.count, 1))));
  const float angle = 2 * kPi * U(rng);
  const Vec3 n = normalized(s.normal);
  const Vec3 b0 = normalized(s.tangent), b1 = cross(n, b0);
  const Vec3 t1 = std::cos(angle) * b0 + std::sin(angle) * b1, t2 = cross(n, t1);
  scene.positions[i] = s.position;
  scene.rotations[i] = quaternion_from_frame(t1, t2, n);
  const float base = 0.7f * spacing;
  scene.scales[i] = {base * (0.6f + 0.9f * U(rng)), base * (0.6f + 0.6f * U(rng)),
                     base * (0.05f + 0.1f * U(rng))};
  scene.opacities[i] = std::clamp(c.paint.opacity + 0.05f * N(rng), 0.05f, 0.99f);

  const Paint& p = c.paint;
  bool alt = false;
  if (p.period > 0)
    alt = (int(std::floor(s.u / p.period)) + int(std::floor(s.v / p.period))) % 2 != 0;
  const Vec3 rgb = alt ? p.alt : p.base;
  float* sh = scene.sh.data() + i * size_t(scene.sh_coeffs()) * 3;
  for (int ch = 0; ch < 3; ++ch) {
    const float v = std::clamp(rgb[ch] + 0.03f * N(rng), 0.0f, 1.0f);
    sh[ch] = scene::color_to_sh_dc(v);
  }
  if (scene.sh_degree >= 1) {
    // Degree 1 adds -C1 y sh1 + C1 z sh2 - C1 x sh3, (x, y, z) the direction from the camera
    // to the Gaussian (computeColorFromSH). sh1..3 = k (n_y, -n_z, n_x) adds C1 k when the
    // view is head-on (direction = -n) and less at grazing views: a broad sheen that differs
    // between the views of a quilt.
    const float dir[3] = {n[1], -n[2], n[0]};
    for (int k = 0; k < 3; ++k)
      for (int ch = 0; ch < 3; ++ch)
        sh[(k + 1) * 3 + ch] = p.specular[ch] * dir[k] + 0.02f * N(rng);
  }
  for (int k = 4; k < scene.sh_coeffs(); ++k)
    for (int ch = 0; ch < 3; ++ch) sh[k * 3 + ch] = 0.03f * N(rng);
}

}  // namespace

void SceneGeneratorOptions::check() const {
  const auto kinds = generator_kinds();
  if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
    throw_input_error("scene generator options: kind: unknown scene kind '{}' (one of: {})", kind,
                      fmt::join(kinds, ", "));
  if (count == 0 || count > kMaxCount)
    throw_input_error("scene generator options: count: {} Gaussians is out of range (1..{})", count, kMaxCount);
  if (sh_degree < 0 || sh_degree > 3)
    throw_input_error("scene generator options: sh_degree: {} is not in 0..3", sh_degree);
}

std::vector<std::string> generator_kinds() { return {"tabletop", "corridor"}; }

scene::GaussianScene generate_scene(const SceneGeneratorOptions& options) {
  options.check();
  std::mt19937_64 layout_rng(splitmix64(options.seed));
  std::vector<Component> comps =
      options.kind == "corridor" ? corridor(layout_rng) : tabletop(layout_rng);
  assign_counts(comps, options.count);

  scene::GaussianScene scene;
  scene::resize_scene(scene, options.count, options.sh_degree);
  const size_t blocks = (options.count + kBlock - 1) / kBlock;
#pragma omp parallel for schedule(dynamic)
  for (long long b = 0; b < (long long)blocks; ++b) {
    std::mt19937_64 rng(splitmix64(options.seed ^ splitmix64(uint64_t(b) + 1)));
    const size_t begin = size_t(b) * kBlock, end = std::min(options.count, begin + kBlock);
    auto comp = std::upper_bound(comps.begin(), comps.end(), begin,
                                 [](size_t i, const Component& c) { return i < c.first; }) - 1;
    for (size_t i = begin; i < end; ++i) {
      while (i >= comp->first + comp->count) ++comp;
      fill_gaussian(scene, i, *comp, rng);
    }
  }
  return scene;
}

}  // namespace lfd::render
