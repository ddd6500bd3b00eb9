// Niantic SPZ (after nianticlabs/spz load-spz.cc; docs/rendering.md "Scene formats").
// v1-v3: the whole file is gzip; inside, a 16-byte header and the attribute arrays in the
// order positions, alphas, colours, scales, rotations, SH. v2 and v3 are also read raw (the
// same bytes without the gzip layer, as PlayCanvas splat-transform reads and its fixtures hold
// them; told apart by the first bytes: gzip's 1f 8b or the header's 'NGSP'). v4: a 32-byte
// plain header, a table of contents and one zstd stream per attribute in the same order.
// Decompression is bounded: the expected size follows from the header's point count, and it
// must be reachable from the compressed bytes present (deflate cannot exceed 1032:1), so a tiny
// file claiming billions of points fails before any allocation.
#include <zlib.h>
#include <zstd.h>

#include <array>
#include <cmath>
#include <cstring>
#include <memory>

#include "scene/scene_checks.hpp"
#include "scene/scene_parsers.hpp"
#include "util/error.hpp"

namespace lfd::scene {

namespace {

constexpr uint32_t kSpzMagic = 0x5053474e;  // "NGSP"
constexpr size_t kLegacyHeaderBytes = 16;
constexpr size_t kV4HeaderBytes = 32;
constexpr uint8_t kFlagHasExtensions = 0x2;
// Largest expansion ratio deflate can reach (RFC 1951: 258-byte matches from ~2 bits).
constexpr uint64_t kMaxDeflateRatio = 1032;
// Upper bound on what we decompress at all: ~4 GiB of attributes is ~60M SH3 Gaussians.
constexpr uint64_t kMaxDecompressedBytes = uint64_t(4) << 30;
constexpr uint64_t kMaxPoints = uint64_t(1) << 28;
constexpr float kColourScale = 0.15f;  // load-spz.cc colorScale

// SPZ stores the RUB axes (x right, y up, z back); 3DGS PLY, .splat and compressed PLY use
// COLMAP's RDF. RUB -> RDF is a 180-degree turn about x: position (x, -y, -z), quaternion
// vector part (x, -y, -z), and each SH basis function odd in (y, z) changes sign. The signs
// below are those basis functions' parities in computeColorFromSH's order:
// y, z, x | xy, yz, 2z^2-x^2-y^2, xz, x^2-y^2 | y(3x^2-y^2), xyz, y(4z^2-..), z(2z^2-..),
// x(4z^2-..), z(x^2-y^2), x(x^2-3y^2). This makes all formats agree (three-points fixture).
constexpr float kRubToRdfSh[15] = {-1, -1, 1, -1, 1, 1, -1, 1, -1, 1, -1, -1, 1, -1, 1};

struct SpzHeader {
  uint32_t version = 0;
  uint32_t num_points = 0;
  int sh_degree = 0;
  int fractional_bits = 0;
  uint8_t flags = 0;
};

uint32_t u32_at(const unsigned char* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}
uint64_t u64_at(const unsigned char* p) {
  return uint64_t(u32_at(p)) | uint64_t(u32_at(p + 4)) << 32;
}

// Byte sizes of the six attribute arrays, in file order.
std::array<uint64_t, 6> stream_sizes(const SpzHeader& h) {
  const uint64_t n = h.num_points;
  const uint64_t sh_dim = uint64_t((h.sh_degree + 1) * (h.sh_degree + 1) - 1);
  return {n * (h.version == 1 ? 6 : 9), n, n * 3, n * 3, n * (h.version >= 3 ? 4 : 3),
          n * sh_dim * 3};
}

void check_header(const SpzHeader& h, const std::string& name) {
  if (h.version < 1 || h.version > 4)
    throw_input_error("{}: SPZ version {} is not supported (1-4)", name, h.version);
  if (h.sh_degree > 4) throw_input_error("{}: SPZ SH degree {} is not in 0..4", name, h.sh_degree);
  if (h.num_points > kMaxPoints)
    throw_input_error("{}: SPZ claims {} points, more than the limit {}", name, h.num_points,
                      kMaxPoints);
  if (h.fractional_bits > 24)
    throw_input_error("{}: SPZ fractional bits {} out of range", name, h.fractional_bits);
}

SpzHeader parse_header(const unsigned char* p, const std::string& name) {
  if (u32_at(p) != kSpzMagic) throw_input_error("{}: no SPZ magic 'NGSP' in the header", name);
  SpzHeader h;
  h.version = u32_at(p + 4);
  h.num_points = u32_at(p + 8);
  h.sh_degree = p[12];
  h.fractional_bits = p[13];
  h.flags = p[14];
  check_header(h, name);
  return h;
}

// Inflates a gzip stream into `out` until it holds `want` bytes (more data is ignored:
// trailing extension records) or the stream ends.
class GzipReader {
 public:
  GzipReader(std::string_view bytes, const std::string& name) : name_(name) {
    stream_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    stream_.avail_in = uInt(std::min<size_t>(bytes.size(), UINT32_MAX));
    if (inflateInit2(&stream_, 16 + MAX_WBITS) != Z_OK)
      throw_input_error("{}: cannot initialise gzip decompression", name);
  }
  ~GzipReader() { inflateEnd(&stream_); }
  GzipReader(const GzipReader&) = delete;
  GzipReader& operator=(const GzipReader&) = delete;

  void read_to(std::string& out, size_t want) {
    size_t have = out.size();
    out.resize(want);
    while (have < want && !ended_) {
      stream_.next_out = reinterpret_cast<Bytef*>(out.data() + have);
      stream_.avail_out = uInt(std::min<size_t>(want - have, 1u << 30));
      const int rc = inflate(&stream_, Z_NO_FLUSH);
      have = size_t(reinterpret_cast<char*>(stream_.next_out) - out.data());
      if (rc == Z_STREAM_END) {
        ended_ = true;
      } else if (rc != Z_OK) {
        throw_input_error("{}: corrupt or truncated gzip data ({})", name_,
                          stream_.msg ? stream_.msg : "inflate error");
      }
    }
    if (have < want)
      throw_input_error("{}: truncated SPZ: {} bytes decompressed, {} expected", name_, have,
                        want);
  }

 private:
  z_stream stream_{};
  std::string name_;
  bool ended_ = false;
};

struct Arrays {
  std::array<std::string_view, 6> streams;  // positions, alphas, colours, scales, rotations, SH
};

// v3/v4 "smallest three": bits 30-31 index the largest of (x, y, z, w); the other three are
// 10 bits each (sign + 9-bit magnitude of |q_i| / sqrt(1/2)), the last one in the lowest bits.
std::array<float, 4> unpack_smallest_three(const unsigned char* r) {
  uint32_t comp = u32_at(r);
  const int largest = int(comp >> 30);
  std::array<float, 4> xyzw{};
  float sum = 0;
  for (int i = 3; i >= 0; --i) {
    if (i == largest) continue;
    const uint32_t mag = comp & 511u;
    const bool negative = (comp >> 9) & 1u;
    comp >>= 10;
    xyzw[i] = float(M_SQRT1_2) * float(mag) / 511.0f * (negative ? -1.0f : 1.0f);
    sum += xyzw[i] * xyzw[i];
  }
  xyzw[largest] = std::sqrt(std::max(0.0f, 1.0f - sum));
  return {xyzw[3], xyzw[0], xyzw[1], xyzw[2]};
}

float half_to_float(uint16_t h) {
  const int exponent = (h >> 10) & 31, mantissa = h & 1023;
  const float sign = (h & 0x8000) ? -1.0f : 1.0f;
  if (exponent == 0) return sign * std::ldexp(float(mantissa), -24);
  if (exponent == 31) return mantissa ? NAN : sign * INFINITY;
  return sign * std::ldexp(float(mantissa + 1024), exponent - 25);
}

GaussianScene decode(const SpzHeader& h, const Arrays& a, const std::string& name) {
  const size_t n = h.num_points;
  // Our scene holds degree <= 3; SH is coefficient-major, so degree 4 truncates cleanly.
  const int degree = std::min(h.sh_degree, 3);
  const size_t file_sh_dim = size_t((h.sh_degree + 1) * (h.sh_degree + 1) - 1);
  GaussianScene scene;
  resize_scene(scene, n, degree);
  const size_t coeffs = size_t(scene.sh_coeffs());
  const auto* pos = reinterpret_cast<const unsigned char*>(a.streams[0].data());
  const auto* alpha = reinterpret_cast<const unsigned char*>(a.streams[1].data());
  const auto* colour = reinterpret_cast<const unsigned char*>(a.streams[2].data());
  const auto* scale = reinterpret_cast<const unsigned char*>(a.streams[3].data());
  const auto* rot = reinterpret_cast<const unsigned char*>(a.streams[4].data());
  const auto* shb = reinterpret_cast<const unsigned char*>(a.streams[5].data());
  const float fixed_scale = 1.0f / float(1u << h.fractional_bits);
  for (size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      if (h.version == 1) {
        const unsigned char* p = pos + (i * 3 + k) * 2;
        scene.positions[i][k] = half_to_float(uint16_t(p[0] | p[1] << 8));
      } else {
        const unsigned char* p = pos + (i * 3 + k) * 3;
        int32_t fixed = int32_t(uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16);
        if (fixed & 0x800000) fixed -= 0x1000000;  // sign-extend the 24-bit value
        scene.positions[i][k] = float(fixed) * fixed_scale;
      }
      if (k > 0) scene.positions[i][k] = -scene.positions[i][k];  // RUB -> RDF
      scene.scales[i][k] = std::exp(float(scale[i * 3 + k]) / 16.0f - 10.0f);
    }
    // Alpha bytes are round(sigmoid(logit) * 255): keep the activated value, which stays
    // finite at 0 and 255 where the logit would not.
    scene.opacities[i] = float(alpha[i]) / 255.0f;
    if (h.version >= 3) {
      scene.rotations[i] = unpack_smallest_three(rot + i * 4);
    } else {
      const unsigned char* r = rot + i * 3;
      const float x = r[0] / 127.5f - 1.0f, y = r[1] / 127.5f - 1.0f, z = r[2] / 127.5f - 1.0f;
      scene.rotations[i] = {std::sqrt(std::max(0.0f, 1.0f - x * x - y * y - z * z)), x, y, z};
    }
    scene.rotations[i][2] = -scene.rotations[i][2];  // RUB -> RDF
    scene.rotations[i][3] = -scene.rotations[i][3];
    float* sh = scene.sh.data() + i * coeffs * 3;
    for (int c = 0; c < 3; ++c) sh[c] = (float(colour[i * 3 + c]) / 255.0f - 0.5f) / kColourScale;
    // SPZ SH is coefficient-major with RGB innermost, like ours; (b - 128) / 128.
    const unsigned char* src = shb + i * file_sh_dim * 3;
    for (size_t k = 0; k + 1 < coeffs; ++k)
      for (int c = 0; c < 3; ++c)
        sh[(k + 1) * 3 + c] = kRubToRdfSh[k] * (float(src[k * 3 + c]) - 128.0f) / 128.0f;
  }
  finalize_scene(scene, name);
  return scene;
}

// The bytes of a v1-v3 payload (header and arrays) with header `h`; refuses extension records.
uint64_t legacy_payload_bytes(const SpzHeader& h, const std::string& name) {
  if (h.flags & kFlagHasExtensions)
    throw_input_error("{}: SPZ v{} extension records are not supported", name, h.version);
  uint64_t total = kLegacyHeaderBytes;
  for (uint64_t s : stream_sizes(h)) total += s;
  return total;
}

// A v1-v3 payload of legacy_payload_bytes(h) bytes: the header, then the six arrays.
GaussianScene decode_legacy(const SpzHeader& h, std::string_view payload, const std::string& name) {
  const auto sizes = stream_sizes(h);
  Arrays a;
  size_t offset = kLegacyHeaderBytes;
  for (size_t k = 0; k < 6; ++k) {
    a.streams[k] = payload.substr(offset, size_t(sizes[k]));
    offset += size_t(sizes[k]);
  }
  return decode(h, a, name);
}

GaussianScene read_legacy(std::string_view bytes, const std::string& name) {
  GzipReader gzip(bytes, name);
  std::string data;
  gzip.read_to(data, kLegacyHeaderBytes);
  const SpzHeader h = parse_header(reinterpret_cast<const unsigned char*>(data.data()), name);
  if (h.version == 4)
    throw_input_error("{}: SPZ version 4 must not be gzip-wrapped", name);
  const uint64_t total = legacy_payload_bytes(h, name);
  if (total > kMaxDecompressedBytes || total / kMaxDeflateRatio > bytes.size())
    throw_input_error("{}: SPZ claims {} points ({} bytes) but the file has only {} bytes", name,
                      h.num_points, total, bytes.size());
  gzip.read_to(data, size_t(total));
  return decode_legacy(h, data, name);
}

// v2 and v3 without the gzip layer: the payload is the file (bytes after it are ignored, as
// after the gzip payload).
GaussianScene read_raw_legacy(std::string_view bytes, const std::string& name) {
  if (bytes.size() < kLegacyHeaderBytes) throw_input_error("{}: truncated SPZ header", name);
  const SpzHeader h = parse_header(reinterpret_cast<const unsigned char*>(bytes.data()), name);
  if (h.version == 1)
    throw_input_error("{}: SPZ version 1 without gzip (only v2 and v3 are read raw)", name);
  const uint64_t total = legacy_payload_bytes(h, name);
  if (total > kMaxDecompressedBytes || total > bytes.size())
    throw_input_error("{}: truncated SPZ: it claims {} points ({} bytes) but the file has only {} "
                      "bytes", name, h.num_points, total, bytes.size());
  return decode_legacy(h, bytes.substr(0, size_t(total)), name);
}

GaussianScene read_v4(std::string_view bytes, const std::string& name) {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() < kV4HeaderBytes) throw_input_error("{}: truncated SPZ v4 header", name);
  const SpzHeader h = parse_header(p, name);
  const size_t num_streams = p[15];
  const uint64_t toc_offset = u32_at(p + 16);
  const auto sizes = stream_sizes(h);
  // Degree 0 files omit the empty SH stream.
  const size_t expected_streams = h.sh_degree > 0 ? 6 : 5;
  if (num_streams != expected_streams)
    throw_input_error("{}: SPZ v4 has {} streams, expected {}", name, num_streams,
                      expected_streams);
  // Extension records (flags & 0x2) sit between the header and the TOC; skipped.
  if (toc_offset < kV4HeaderBytes || toc_offset + num_streams * 16 > bytes.size())
    throw_input_error("{}: SPZ v4 table of contents at {} lies outside the file", name,
                      toc_offset);
  uint64_t offset = toc_offset + num_streams * 16;
  uint64_t total = 0;
  std::array<std::string, 6> decompressed;
  Arrays a;
  for (size_t k = 0; k < num_streams; ++k) {
    const uint64_t compressed = u64_at(p + toc_offset + k * 16);
    const uint64_t uncompressed = u64_at(p + toc_offset + k * 16 + 8);
    if (uncompressed != sizes[k])
      throw_input_error("{}: SPZ v4 stream {} holds {} bytes, {} points need {}", name, k,
                        uncompressed, h.num_points, sizes[k]);
    if (compressed > bytes.size() - offset)
      throw_input_error("{}: truncated SPZ v4: stream {} needs {} bytes, {} remain", name, k,
                        compressed, bytes.size() - offset);
    total += uncompressed;
    if (total > kMaxDecompressedBytes)
      throw_input_error("{}: SPZ v4 decompresses to more than {} bytes", name,
                        kMaxDecompressedBytes);
    const char* src = bytes.data() + offset;
    const unsigned long long frame = ZSTD_getFrameContentSize(src, size_t(compressed));
    if (frame != ZSTD_CONTENTSIZE_UNKNOWN && frame != uncompressed)
      throw_input_error("{}: SPZ v4 stream {}: zstd frame holds {} bytes, TOC says {}", name, k,
                        frame, uncompressed);
    // Stream decompression into a buffer that grows with the output, so memory follows what
    // the data really expands to rather than what the TOC claims.
    std::string& out = decompressed[k];
    std::unique_ptr<ZSTD_DCtx, size_t (*)(ZSTD_DCtx*)> ctx(ZSTD_createDCtx(), ZSTD_freeDCtx);
    ZSTD_inBuffer in{src, size_t(compressed), 0};
    size_t have = 0;
    size_t rc = 1;
    while (have < uncompressed) {
      out.resize(size_t(std::min<uint64_t>(uncompressed, std::max<uint64_t>(have * 2, 1 << 16))));
      ZSTD_outBuffer o{out.data(), out.size(), have};
      rc = ZSTD_decompressStream(ctx.get(), &o, &in);
      if (ZSTD_isError(rc))
        throw_input_error("{}: SPZ v4 stream {}: zstd: {}", name, k, ZSTD_getErrorName(rc));
      const bool progressed = o.pos > have;
      have = o.pos;
      if (!progressed && o.pos < o.size && in.pos == in.size) break;  // input exhausted
      if (rc == 0 && have < uncompressed && in.pos == in.size) break;
    }
    if (have != uncompressed)
      throw_input_error("{}: SPZ v4 stream {}: decompressed {} bytes, expected {}", name, k,
                        have, uncompressed);
    out.resize(have);
    a.streams[k] = out;
    offset += compressed;
  }
  return decode(h, a, name);
}

}  // namespace

GaussianScene read_spz(std::string_view bytes, const std::string& name) {
  if (bytes.size() >= 2 && uint8_t(bytes[0]) == 0x1f && uint8_t(bytes[1]) == 0x8b)
    return read_legacy(bytes, name);
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() >= 4 && u32_at(p) == kSpzMagic)
    return bytes.size() >= 8 && u32_at(p + 4) == 4 ? read_v4(bytes, name) : read_raw_legacy(bytes, name);
  throw_input_error("{}: not an SPZ file (neither gzip nor 'NGSP' magic)", name);
}

}  // namespace lfd::scene
