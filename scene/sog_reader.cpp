// PlayCanvas SOG (docs/rendering.md "What each reader follows"; the PlayCanvas user manual's
// SOG page; formulas after playcanvas/splat-transform src/lib/readers/read-sog.ts and
// read-sog-v1.ts). Gaussian i is pixel i of every image (row-major). Both versions store:
// means as two 8-bit images (low, high byte) of a 16-bit lerp between per-axis mins and maxs of
// sign(x) ln(|x| + 1); quaternions as "smallest three" bytes (v / 255 * 2 - 1) / sqrt 2 with
// the index of the largest component (w, x, y, z) as alpha 252-255. Version 2 (`version: 2`)
// indexes 256-entry codebooks for log scales, DC colour and SH; its sh0 alpha is the activated
// opacity. Version 1 (no version) lerps every channel between per-channel mins and maxs, and
// its sh0 alpha is the opacity logit. SH beyond DC: a 16-bit label per Gaussian into a palette
// image 64 entries wide, each entry one pixel per coefficient (RGB). Coordinates are those of
// the 3DGS PLY (splat-transform's Transform.PLY), so nothing is flipped.
#include <cmath>

#include <nlohmann/json.hpp>

#include "scene/scene_checks.hpp"
#include "scene/scene_parsers.hpp"
#include "scene/sog_files.hpp"
#include "util/error.hpp"

namespace lfd::scene {

namespace {

using nlohmann::json;

constexpr uint64_t kMaxGaussians = uint64_t(1) << 28;
constexpr size_t kMaxPaletteEntries = 65536;  // labels are 16-bit

struct SogContext {
  const SogFileSource& files;
  const std::string& name;
};

const json& field(const json& j, const std::string& key, const std::string& name,
                  const std::string& where) {
  if (!j.is_object() || !j.contains(key))
    throw_input_error("{}: SOG meta.json: {} has no '{}'", name, where, key);
  return j.at(key);
}

std::vector<float> numbers(const json& j, const std::string& key, size_t size,
                           const std::string& name, const std::string& where) {
  const json& a = field(j, key, name, where);
  if (!a.is_array() || a.size() != size)
    throw_input_error("{}: SOG meta.json: {}.{} must be an array of {} numbers", name, where,
                      key, size);
  std::vector<float> out;
  for (const json& v : a) {
    if (!v.is_number() || !std::isfinite(v.get<double>()) || std::fabs(v.get<double>()) > 1e30)
      throw_input_error("{}: SOG meta.json: {}.{} holds a value that is not a finite number",
                        name, where, key);
    out.push_back(v.get<float>());
  }
  return out;
}

float number(const json& j, const std::string& key, const std::string& name,
             const std::string& where) {
  const json& v = field(j, key, name, where);
  if (!v.is_number() || !std::isfinite(v.get<double>()) || std::fabs(v.get<double>()) > 1e30)
    throw_input_error("{}: SOG meta.json: {}.{} is not a finite number", name, where, key);
  return v.get<float>();
}

uint64_t whole_number(const json& v, uint64_t max, const std::string& name,
                      const std::string& what) {
  if (!v.is_number_unsigned() || v.get<uint64_t>() > max)
    throw_input_error("{}: SOG meta.json: {} must be a whole number 0..{}", name, what, max);
  return v.get<uint64_t>();
}

std::string file_name(const json& section, size_t index, const std::string& name,
                      const std::string& where) {
  const json& files = field(section, "files", name, where);
  if (!files.is_array() || files.size() <= index || !files[index].is_string())
    throw_input_error("{}: SOG meta.json: {}.files needs {} file names", name, where, index + 1);
  return files[index].get<std::string>();
}

// Loads image `index` of `section`; it must hold at least `need` and at most `limit` pixels.
RgbaImage load_image(const SogContext& c, const json& meta, const std::string& section,
                     size_t index, size_t need, size_t limit) {
  const std::string file = file_name(field(meta, section, c.name, "meta"), index, c.name, section);
  RgbaImage image = decode_webp(c.files(file), limit, c.name, file);
  if (image.pixels() < need)
    throw_input_error("{}: {}: {}x{} pixels, fewer than the {} Gaussians", c.name, file,
                      image.width, image.height, need);
  return image;
}

// The pixel budget of a per-Gaussian image: the writer pads to a multiple of 4 in each
// direction; anything far larger is a lie that would only cost memory.
size_t image_limit(size_t count) { return 2 * count + (size_t(1) << 20); }

float inverse_log_transform(float v) {
  const float e = std::exp(std::fabs(v)) - 1.0f;
  return v < 0 ? -e : e;
}

void decode_means(const SogContext& c, const json& meta, size_t n, GaussianScene& scene) {
  const json& means = field(meta, "means", c.name, "meta");
  const auto mins = numbers(means, "mins", 3, c.name, "means");
  const auto maxs = numbers(means, "maxs", 3, c.name, "means");
  const RgbaImage lo = load_image(c, meta, "means", 0, n, image_limit(n));
  const RgbaImage hi = load_image(c, meta, "means", 1, n, image_limit(n));
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      const float range = maxs[a] - mins[a] != 0.0f ? maxs[a] - mins[a] : 1.0f;
      const int q = lo.rgba[i * 4 + a] | hi.rgba[i * 4 + a] << 8;
      scene.positions[i][a] = inverse_log_transform(mins[a] + range * float(q) / 65535.0f);
    }
}

// Smallest three: alpha 252 + index (w, x, y, z) of the largest component, which is positive.
void decode_quats(const SogContext& c, const json& meta, size_t n, GaussianScene& scene) {
  const RgbaImage quats = load_image(c, meta, "quats", 0, n, image_limit(n));
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* p = &quats.rgba[i * 4];
    if (p[3] < 252) {  // not a tag: the reference reader takes the identity
      scene.rotations[i] = {1, 0, 0, 0};
      continue;
    }
    const int largest = p[3] - 252;
    std::array<float, 4> q{};
    float sum = 0;
    for (int k = 0, j = 0; k < 4; ++k) {
      if (k == largest) continue;
      q[k] = (float(p[j++]) / 255.0f * 2.0f - 1.0f) / float(M_SQRT2);
      sum += q[k] * q[k];
    }
    q[largest] = std::sqrt(std::max(0.0f, 1.0f - sum));
    scene.rotations[i] = q;
  }
}

// Scales and DC colour with opacity: codebooks (v2) or per-channel lerps (v1).
void decode_scales_colours(const SogContext& c, const json& meta, size_t n, bool v2,
                           GaussianScene& scene) {
  const RgbaImage scales = load_image(c, meta, "scales", 0, n, image_limit(n));
  const RgbaImage sh0 = load_image(c, meta, "sh0", 0, n, image_limit(n));
  const json& sj = field(meta, "scales", c.name, "meta");
  const json& cj = field(meta, "sh0", c.name, "meta");
  const size_t coeffs = size_t(scene.sh_coeffs());
  if (v2) {
    const auto scode = numbers(sj, "codebook", 256, c.name, "scales");
    const auto ccode = numbers(cj, "codebook", 256, c.name, "sh0");
    for (size_t i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a) {
        scene.scales[i][a] = std::exp(scode[scales.rgba[i * 4 + a]]);
        scene.sh[i * coeffs * 3 + size_t(a)] = ccode[sh0.rgba[i * 4 + a]];
      }
    for (size_t i = 0; i < n; ++i) scene.opacities[i] = float(sh0.rgba[i * 4 + 3]) / 255.0f;
    return;
  }
  const auto smin = numbers(sj, "mins", 3, c.name, "scales");
  const auto smax = numbers(sj, "maxs", 3, c.name, "scales");
  const auto cmin = numbers(cj, "mins", 4, c.name, "sh0");
  const auto cmax = numbers(cj, "maxs", 4, c.name, "sh0");
  auto lerp = [](float lo, float hi, uint8_t b) { return lo + (hi - lo) * float(b) / 255.0f; };
  for (size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      scene.scales[i][a] = std::exp(lerp(smin[a], smax[a], scales.rgba[i * 4 + a]));
      scene.sh[i * coeffs * 3 + size_t(a)] = lerp(cmin[a], cmax[a], sh0.rgba[i * 4 + a]);
    }
    scene.opacities[i] = sigmoid(lerp(cmin[3], cmax[3], sh0.rgba[i * 4 + 3]));
  }
}

// SH bands of the palette: v2 names them; v1 implies them by the palette's width.
int sh_bands(const json& meta, bool v2, const SogContext& c) {
  if (!meta.contains("shN")) return 0;
  const json& shn = meta.at("shN");
  if (v2) return int(whole_number(field(shn, "bands", c.name, "shN"), 3, c.name, "shN.bands"));
  const std::string file = file_name(shn, 0, c.name, "shN");
  int width = 0, height = 0;
  if (!webp_dimensions(c.files(file), width, height))
    throw_input_error("{}: {}: not a WebP image", c.name, file);
  if (width == 192) return 1;
  if (width == 512) return 2;
  if (width == 960) return 3;
  throw_input_error("{}: {}: palette width {} is not 192, 512 or 960 (SH bands 1-3)", c.name,
                    file, width);
}

void decode_sh_rest(const SogContext& c, const json& meta, size_t n, bool v2,
                    GaussianScene& scene) {
  const int rest = scene.sh_coeffs() - 1;
  if (rest == 0) return;
  const json& shn = meta.at("shN");
  const RgbaImage palette =
      load_image(c, meta, "shN", 0, 0, size_t(64 * rest) * (kMaxPaletteEntries / 64));
  const RgbaImage labels = load_image(c, meta, "shN", 1, n, image_limit(n));
  if (palette.width != 64 * rest)
    throw_input_error("{}: SOG shN palette is {} pixels wide, {} SH coefficients need {}",
                      c.name, palette.width, rest, 64 * rest);
  size_t entries = size_t(palette.height) * 64;
  std::vector<float> table(256);
  if (v2) {
    entries = size_t(whole_number(field(shn, "count", c.name, "shN"), entries, c.name,
                                  "shN.count (at most 64 per palette row)"));
    table = numbers(shn, "codebook", 256, c.name, "shN");
  } else {
    const float lo = number(shn, "mins", c.name, "shN"), hi = number(shn, "maxs", c.name, "shN");
    for (int b = 0; b < 256; ++b) table[size_t(b)] = lo + (hi - lo) * float(b) / 255.0f;
  }
  const size_t coeffs = size_t(scene.sh_coeffs());
  for (size_t i = 0; i < n; ++i) {
    const size_t label = labels.rgba[i * 4] | labels.rgba[i * 4 + 1] << 8;
    if (label >= entries) continue;  // as the reference reader: no SH beyond DC
    const size_t row = label / 64, column = (label % 64) * size_t(rest);
    for (int k = 0; k < rest; ++k) {
      const uint8_t* p = &palette.rgba[(row * size_t(palette.width) + column + size_t(k)) * 4];
      for (int ch = 0; ch < 3; ++ch) scene.sh[(i * coeffs + size_t(k) + 1) * 3 + size_t(ch)] = table[p[ch]];
    }
  }
}

}  // namespace

GaussianScene read_sog_files(const SogFileSource& files, std::string_view meta_bytes,
                             const std::string& name) {
  json meta;
  try {
    meta = json::parse(meta_bytes);
  } catch (const json::exception& e) {
    throw_input_error("{}: SOG meta.json is not valid JSON ({})", name, e.what());
  }
  if (!meta.is_object()) throw_input_error("{}: SOG meta.json is not a JSON object", name);
  const bool v2 = meta.contains("version");
  if (v2 && whole_number(meta.at("version"), 1000, name, "version") != 2)
    throw_input_error("{}: SOG version {} is not supported (1 or 2)", name,
                      meta.at("version").dump());
  const SogContext c{files, name};
  const json& shape = v2 ? json() : field(field(meta, "means", name, "meta"), "shape", name, "means");
  if (!v2 && (!shape.is_array() || shape.empty()))
    throw_input_error("{}: SOG v1 meta.json: means.shape must be [count, 3]", name);
  const uint64_t n = whole_number(v2 ? field(meta, "count", name, "meta") : shape[0],
                                  kMaxGaussians, name, v2 ? "count" : "means.shape[0]");
  GaussianScene scene;
  resize_scene(scene, size_t(n), sh_bands(meta, v2, c));
  decode_means(c, meta, size_t(n), scene);
  decode_quats(c, meta, size_t(n), scene);
  decode_scales_colours(c, meta, size_t(n), v2, scene);
  decode_sh_rest(c, meta, size_t(n), v2, scene);
  finalize_scene(scene, name);
  return scene;
}

GaussianScene read_sog_meta(std::string_view meta_bytes, const std::string& name) {
  return read_sog_files(sog_folder_source(std::filesystem::path(name).parent_path(), name),
                        meta_bytes, name);
}

GaussianScene read_sog(std::string_view bytes, const std::string& name) {
  const SogFileSource files = sog_zip_source(bytes, name);
  return read_sog_files(files, files("meta.json"), name);
}

}  // namespace lfd::scene
