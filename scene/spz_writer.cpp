#include "scene/spz_writer.hpp"

#include <zlib.h>

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace lfd::scene {

namespace {

constexpr int kFractionalBits = 12;
constexpr float kColourScale = 0.15f;  // load-spz.cc colorScale
// RDF -> RUB: a half turn about x flips y and z, and each SH basis function odd in (y, z)
// (the same parities as the reader's kRubToRdfSh, its own inverse).
constexpr float kRdfToRubSh[15] = {-1, -1, 1, -1, 1, 1, -1, 1, -1, 1, -1, -1, 1, -1, 1};

uint8_t to_byte(float v) { return uint8_t(std::clamp(std::lround(v), 0L, 255L)); }

void put_u32(std::string& out, uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(char((v >> (8 * k)) & 255));
}

// Smallest three, v3: bits 30-31 the index of the largest |component| in (x, y, z, w), made
// positive; the other three as sign + 9-bit magnitude of |q| / sqrt(1/2), the last in the
// lowest bits.
uint32_t pack_rotation(const std::array<float, 4>& wxyz) {
  std::array<float, 4> q{wxyz[1], -wxyz[2], -wxyz[3], wxyz[0]};  // (x, y, z, w), RDF -> RUB
  int largest = 0;
  for (int i = 1; i < 4; ++i)
    if (std::fabs(q[size_t(i)]) > std::fabs(q[size_t(largest)])) largest = i;
  if (q[size_t(largest)] < 0)
    for (float& v : q) v = -v;
  uint32_t comp = uint32_t(largest);
  for (int i = 0; i < 4; ++i) {
    if (i == largest) continue;
    const float v = q[size_t(i)];
    const uint32_t mag =
        uint32_t(std::clamp(std::lround(std::fabs(v) / float(M_SQRT1_2) * 511.0f), 0L, 511L));
    comp = comp << 10 | uint32_t(v < 0) << 9 | mag;
  }
  return comp;
}

std::string payload(const GaussianScene& s) {
  const size_t n = s.size(), coeffs = size_t(s.sh_coeffs());
  std::string out = "NGSP";
  put_u32(out, 3);
  put_u32(out, uint32_t(n));
  out += {char(s.sh_degree), char(kFractionalBits), char(0), char(0)};
  const float fixed = float(1 << kFractionalBits);
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      const float v = (a == 0 ? 1.0f : -1.0f) * s.positions[i][size_t(a)] * fixed;
      if (!(std::fabs(v) < float(1 << 23)))
        throw_input_error("SPZ: Gaussian {} lies at {} on axis {}, beyond the 24-bit range (+-2048)",
                          i, s.positions[i][size_t(a)], a);
      const int32_t q = int32_t(std::lround(v));
      for (int k = 0; k < 3; ++k) out.push_back(char((uint32_t(q) >> (8 * k)) & 255));
    }
  for (size_t i = 0; i < n; ++i) out.push_back(char(to_byte(s.opacities[i] * 255.0f)));
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      out.push_back(char(to_byte((s.sh_of(i)[c] * kColourScale + 0.5f) * 255.0f)));
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a)
      out.push_back(char(to_byte((std::log(s.scales[i][size_t(a)]) + 10.0f) * 16.0f)));
  for (size_t i = 0; i < n; ++i) put_u32(out, pack_rotation(s.rotations[i]));
  for (size_t i = 0; i < n; ++i)
    for (size_t k = 0; k + 1 < coeffs; ++k)
      for (int c = 0; c < 3; ++c)
        out.push_back(char(to_byte(kRdfToRubSh[k] * s.sh_of(i)[(k + 1) * 3 + size_t(c)] * 128.0f + 128.0f)));
  return out;
}

std::string gzip(const std::string& data) {
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("SPZ: cannot initialise gzip compression");
  std::string out(deflateBound(&z, uLong(data.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = uInt(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(out.size());
  const int rc = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw std::runtime_error("SPZ: gzip compression failed");
  return out;
}

}  // namespace

std::string encode_spz(const GaussianScene& scene) {
  if (scene.size() > (size_t(1) << 28))
    throw_input_error("SPZ: {} Gaussians, more than a file holds here", scene.size());
  return gzip(payload(scene));
}

}  // namespace lfd::scene
