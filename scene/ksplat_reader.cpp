// .ksplat, the format of mkkellogg/GaussianSplats3D (docs/rendering.md "Scene formats";
// layout after its src/loaders/SplatBuffer.js and playcanvas/splat-transform
// src/lib/readers/read-ksplat.ts). A 4096-byte header (version 0.x, section count, Gaussian
// count, compression level 0-2, 8-bit SH range), one 1024-byte header per section, then per
// section: the sizes of its partly filled buckets (u32), the bucket centres (3 x f32), and the
// Gaussians. Level 0 stores float32 centres, linear scales, (w, x, y, z) rotations and SH;
// levels 1 and 2 store centres as 16-bit offsets from their bucket's centre and the rest as
// half floats, except SH at level 2: bytes lerped over the header's range. Colour and opacity
// are RGBA bytes (activated). Coordinates are those of the 3DGS PLY.
#include <cmath>
#include <cstring>

#include "scene/scene_checks.hpp"
#include "scene/scene_parsers.hpp"
#include "scene/sh_basis.hpp"
#include "util/error.hpp"

namespace lfd::scene {

namespace {

constexpr size_t kHeaderBytes = 4096;
constexpr size_t kSectionHeaderBytes = 1024;
constexpr size_t kBucketCentreBytes = 12;
constexpr uint32_t kDefaultQuantRange = 32767;
constexpr float kDefaultShHalfRange = 1.5f;  // SplatBuffer.js, 8-bit SH without a stored range
// SH components per Gaussian for degrees 0-3 (all channels), as the reference reader.
constexpr size_t kShComponents[4] = {0, 9, 24, 45};

struct Level {
  size_t center, scale, rotation, color, sh_component;
};
constexpr Level kLevels[3] = {{12, 12, 16, 4, 4}, {6, 6, 8, 4, 2}, {6, 6, 8, 4, 1}};

uint16_t u16(const unsigned char* p) { return uint16_t(p[0] | p[1] << 8); }
uint32_t u32(const unsigned char* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}
float f32(const unsigned char* p) {
  float f;
  std::memcpy(&f, p, 4);
  return f;
}
float half(const unsigned char* p) {
  const uint16_t h = u16(p);
  const int exponent = (h >> 10) & 31, mantissa = h & 1023;
  const float sign = (h & 0x8000) ? -1.0f : 1.0f;
  if (exponent == 0) return sign * std::ldexp(float(mantissa), -24);
  if (exponent == 31) return mantissa ? NAN : sign * INFINITY;
  return sign * std::ldexp(float(mantissa + 1024), exponent - 25);
}

struct Section {
  uint32_t count = 0, capacity = 0, bucket_size = 0, buckets = 0, full_buckets = 0,
           partial_buckets = 0, quant_range = 0;
  uint32_t bucket_bytes = 0;  // 12 (one centre) when compressed
  float block_size = 0;
  int sh_degree = 0;
  size_t bytes_per_gaussian = 0;
  uint64_t data_offset = 0;  // bucket sizes, then centres, then Gaussians
  uint64_t size = 0;
};

struct Header {
  uint32_t sections = 0, count = 0;
  int level = 0;
  float sh_min = -kDefaultShHalfRange, sh_max = kDefaultShHalfRange;
};

Header parse_header(const unsigned char* p, size_t file_bytes, const std::string& name) {
  if (p[0] != 0 || p[1] < 1)
    throw_input_error("{}: .ksplat version {}.{} is not supported (0.1 or later)", name, p[0], p[1]);
  Header h;
  h.sections = u32(p + 4);
  h.count = u32(p + 16);
  h.level = u16(p + 20);
  if (h.level > 2) throw_input_error("{}: .ksplat compression level {} is not 0-2", name, h.level);
  if (h.sections > (file_bytes - kHeaderBytes) / kSectionHeaderBytes)
    throw_input_error("{}: .ksplat claims {} sections, the file holds at most {}", name,
                      h.sections, (file_bytes - kHeaderBytes) / kSectionHeaderBytes);
  if (f32(p + 36) != 0.0f) h.sh_min = f32(p + 36);
  if (f32(p + 40) != 0.0f) h.sh_max = f32(p + 40);
  if (!std::isfinite(h.sh_min) || !std::isfinite(h.sh_max))
    throw_input_error("{}: .ksplat SH range is not finite", name);
  return h;
}

Section parse_section(const unsigned char* p, const Header& h, uint64_t offset, size_t file_bytes,
                      size_t index, const std::string& name) {
  Section s;
  s.count = u32(p);
  s.capacity = u32(p + 4);
  s.bucket_size = u32(p + 8);
  s.buckets = u32(p + 12);
  s.block_size = f32(p + 16);
  s.bucket_bytes = u16(p + 20);
  s.quant_range = u32(p + 24) ? u32(p + 24) : (h.level == 0 ? 1 : kDefaultQuantRange);
  s.full_buckets = u32(p + 32);
  s.partial_buckets = u32(p + 36);
  s.sh_degree = u16(p + 40);
  if (s.sh_degree > 3)
    throw_input_error("{}: .ksplat section {}: SH degree {} is not 0-3", name, index, s.sh_degree);
  if (s.count > s.capacity)
    throw_input_error("{}: .ksplat section {}: {} Gaussians exceed its capacity {}", name, index,
                      s.count, s.capacity);
  const Level& l = kLevels[h.level];
  s.bytes_per_gaussian = l.center + l.scale + l.rotation + l.color +
                         kShComponents[s.sh_degree] * l.sh_component;
  const uint64_t bucket_storage = uint64_t(s.bucket_bytes) * s.buckets + uint64_t(s.partial_buckets) * 4;
  s.data_offset = offset;
  s.size = bucket_storage + uint64_t(s.bytes_per_gaussian) * s.capacity;
  if (s.size > file_bytes || offset > file_bytes - s.size)
    throw_input_error("{}: truncated .ksplat: section {} needs {} bytes at offset {}, the file has {}",
                      name, index, s.size, offset, file_bytes);
  if (h.level > 0 && s.count > 0 &&
      (s.bucket_bytes != kBucketCentreBytes || s.partial_buckets > s.buckets ||
       s.full_buckets > s.buckets - s.partial_buckets || !std::isfinite(s.block_size)))
    throw_input_error("{}: .ksplat section {}: inconsistent bucket table", name, index);
  return s;
}

// The bucket of every Gaussian of a compressed section: full buckets first, then the partly
// filled ones in order, whose sizes the section lists.
std::vector<uint32_t> bucket_of_each(const unsigned char* base, const Section& s,
                                     const std::string& name) {
  std::vector<uint32_t> bucket(s.count);
  const uint64_t in_full = uint64_t(s.full_buckets) * s.bucket_size;
  uint64_t i = 0;
  for (; i < std::min<uint64_t>(in_full, s.count); ++i) bucket[i] = uint32_t(i / s.bucket_size);
  for (uint32_t b = 0; b < s.partial_buckets && i < s.count; ++b) {
    const uint32_t size = u32(base + size_t(b) * 4);
    for (uint32_t k = 0; k < size && i < s.count; ++k) bucket[i++] = s.full_buckets + b;
  }
  if (i < s.count)
    throw_input_error("{}: .ksplat: buckets hold {} Gaussians, the section claims {}", name, i,
                      s.count);
  return bucket;
}

void decode_section(const unsigned char* file, const Section& s, const Header& h,
                    GaussianScene& scene, size_t first, const std::string& name) {
  const Level& l = kLevels[h.level];
  const unsigned char* base = file + s.data_offset;
  const unsigned char* centres = base + size_t(s.partial_buckets) * 4;
  const unsigned char* data = centres + size_t(s.buckets) * s.bucket_bytes;
  const std::vector<uint32_t> bucket = h.level > 0 ? bucket_of_each(base, s, name) : std::vector<uint32_t>();
  const float step = s.block_size / 2.0f / float(s.quant_range);
  const size_t coeffs = size_t(scene.sh_coeffs());
  const size_t components = kShComponents[s.sh_degree];
  for (size_t i = 0; i < s.count; ++i) {
    const unsigned char* g = data + i * s.bytes_per_gaussian;
    const size_t out = first + i;
    for (int a = 0; a < 3; ++a) {
      scene.positions[out][a] =
          h.level == 0 ? f32(g + a * 4)
                       : (float(u16(g + a * 2)) - float(s.quant_range)) * step +
                             f32(centres + size_t(bucket[i]) * kBucketCentreBytes + size_t(a) * 4);
      const float sc = h.level == 0 ? f32(g + l.center + size_t(a) * 4) : half(g + l.center + size_t(a) * 2);
      scene.scales[out][a] = sc > 0 ? sc : std::exp(-10.0f);  // as the reference reader
    }
    const unsigned char* r = g + l.center + l.scale;
    for (int k = 0; k < 4; ++k) scene.rotations[out][k] = h.level == 0 ? f32(r + k * 4) : half(r + k * 2);
    const unsigned char* c = r + l.rotation;
    float* sh = scene.sh.data() + out * coeffs * 3;
    for (int ch = 0; ch < 3; ++ch) sh[ch] = color_to_sh_dc(float(c[ch]) / 255.0f);
    scene.opacities[out] = float(c[3]) / 255.0f;
    // SH per band, channel-major within the band: R0..R(2l), G.., B.. (read-ksplat.ts).
    const unsigned char* shp = c + l.color;
    for (size_t k = 0; k < components && coeffs > 1; ++k) {
      const size_t band_start = k < 9 ? 0 : (k < 24 ? 9 : 24), band_size = k < 9 ? 3 : (k < 24 ? 5 : 7);
      const size_t channel = (k - band_start) / band_size;
      const size_t coefficient = (k - band_start) % band_size + (band_start == 0 ? 0 : band_start == 9 ? 3 : 8);
      if (coefficient + 1 >= coeffs) continue;  // a band beyond the scene's degree
      const unsigned char* v = shp + k * l.sh_component;
      const float value = h.level == 0 ? f32(v)
                          : h.level == 1 ? half(v)
                                         : h.sh_min + float(*v) / 255.0f * (h.sh_max - h.sh_min);
      sh[(coefficient + 1) * 3 + channel] = value;
    }
  }
}

}  // namespace

GaussianScene read_ksplat(std::string_view bytes, const std::string& name) {
  if (bytes.size() < kHeaderBytes)
    throw_input_error("{}: truncated .ksplat: {} bytes, the header alone is {}", name,
                      bytes.size(), kHeaderBytes);
  const auto* file = reinterpret_cast<const unsigned char*>(bytes.data());
  const Header h = parse_header(file, bytes.size(), name);
  std::vector<Section> sections;
  uint64_t offset = kHeaderBytes + uint64_t(h.sections) * kSectionHeaderBytes;
  uint64_t total = 0;
  int degree = 0;
  for (size_t k = 0; k < h.sections; ++k) {
    const Section s = parse_section(file + kHeaderBytes + k * kSectionHeaderBytes, h, offset,
                                    bytes.size(), k, name);
    offset += s.size;
    total += s.count;
    if (s.count > 0) degree = std::max(degree, s.sh_degree);
    sections.push_back(s);
  }
  if (total != h.count)
    throw_input_error("{}: .ksplat header claims {} Gaussians, its sections hold {}", name,
                      h.count, total);
  GaussianScene scene;
  resize_scene(scene, size_t(total), degree);
  size_t first = 0;
  for (const Section& s : sections) {
    decode_section(file, s, h, scene, first, name);
    first += s.count;
  }
  finalize_scene(scene, name);
  return scene;
}

}  // namespace lfd::scene
