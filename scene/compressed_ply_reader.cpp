// PlayCanvas / SuperSplat compressed PLY (after playcanvas/splat-transform decompress-ply.ts;
// docs/rendering.md "Scene formats"): 256 Gaussians per `chunk` carrying min/max
// ranges; each `vertex` packs position, rotation, log scale and colour into four uint32s; an
// optional `sh` element holds 8-bit f_rest_* values (channel-major, like the standard PLY).
#include <cmath>
#include <string>

#include "scene/ply_header.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_parsers.hpp"
#include "scene/sh_basis.hpp"
#include "util/error.hpp"

namespace lfd::scene {

namespace {

constexpr size_t kGaussiansPerChunk = 256;

int require(const PlyElement& e, const std::string& property, PlyType type,
            const std::string& name) {
  const int index = e.find(property);
  if (index < 0)
    throw_input_error("{}: compressed PLY element '{}' has no property '{}'", name, e.name,
                      property);
  if (e.type_of(index) != type)
    throw_input_error("{}: compressed PLY property '{}.{}' has an unexpected type", name, e.name,
                      property);
  return index;
}

float unorm(uint32_t v, int bits) {
  const uint32_t mask = (1u << bits) - 1u;
  return float(v & mask) / float(mask);
}

// 11-10-11 bit packing of position and scale.
std::array<float, 3> unpack_111011(uint32_t v) {
  return {unorm(v >> 21, 11), unorm(v >> 11, 10), unorm(v, 11)};
}

float lerp(float a, float b, float t) { return a + (b - a) * t; }

// Smallest-three quaternion: bits 30-31 index the largest component in (w, x, y, z) order.
std::array<float, 4> unpack_rotation(uint32_t v) {
  const float norm = std::sqrt(2.0f);
  const float a = (unorm(v >> 20, 10) - 0.5f) * norm;
  const float b = (unorm(v >> 10, 10) - 0.5f) * norm;
  const float c = (unorm(v, 10) - 0.5f) * norm;
  const float m = std::sqrt(std::max(0.0f, 1.0f - (a * a + b * b + c * c)));
  switch (v >> 30) {
    case 0: return {m, a, b, c};
    case 1: return {a, m, b, c};
    case 2: return {a, b, m, c};
    default: return {a, b, c, m};
  }
}

}  // namespace

GaussianScene read_compressed_ply(std::string_view bytes, const std::string& name) {
  return compressed_ply_to_scene(parse_ply(bytes, name), name);
}

GaussianScene compressed_ply_to_scene(const PlyFile& ply, const std::string& name) {
  const PlyElement* chunk = ply.find("chunk");
  const PlyElement* vertex = ply.find("vertex");
  if (!chunk) throw_input_error("{}: compressed PLY has no 'chunk' element", name);
  if (!vertex) throw_input_error("{}: compressed PLY has no 'vertex' element", name);
  const size_t n = vertex->count;
  const size_t chunks_needed = (n + kGaussiansPerChunk - 1) / kGaussiansPerChunk;
  if (chunk->count < chunks_needed)
    throw_input_error("{}: {} Gaussians need {} chunks but the file has {}", name, n,
                      chunks_needed, chunk->count);

  const auto F = PlyType::Float32;
  auto chunk_props = [&](const char* const* names, int* out, int count) {
    for (int k = 0; k < count; ++k) out[k] = require(*chunk, names[k], F, name);
  };
  const char* bounds_names[12] = {"min_x", "min_y", "min_z", "max_x", "max_y", "max_z",
                                  "min_scale_x", "min_scale_y", "min_scale_z",
                                  "max_scale_x", "max_scale_y", "max_scale_z"};
  int bounds[12];
  chunk_props(bounds_names, bounds, 12);
  // The colour range is optional (12- or 18-property chunks).
  const bool has_colour_range = chunk->find("min_r") >= 0;
  int colour[6] = {};
  if (has_colour_range) {
    const char* colour_names[6] = {"min_r", "min_g", "min_b", "max_r", "max_g", "max_b"};
    chunk_props(colour_names, colour, 6);
  }

  const auto U = PlyType::UInt32;
  const int packed_position = require(*vertex, "packed_position", U, name);
  const int packed_rotation = require(*vertex, "packed_rotation", U, name);
  const int packed_scale = require(*vertex, "packed_scale", U, name);
  const int packed_color = require(*vertex, "packed_color", U, name);

  int degree = 0;
  std::vector<int> rest;
  if (const PlyElement* sh = ply.find("sh")) {
    if (sh->count != n)
      throw_input_error("{}: 'sh' element has {} rows for {} Gaussians", name, sh->count, n);
    const size_t props = sh->properties.size();
    if (props == 9) degree = 1;
    else if (props == 24) degree = 2;
    else if (props == 45) degree = 3;
    else
      throw_input_error("{}: 'sh' element has {} properties (9, 24 or 45 expected)", name,
                        props);
    for (size_t k = 0; k < props; ++k)
      rest.push_back(require(*sh, "f_rest_" + std::to_string(k), PlyType::UInt8, name));
  }
  const PlyElement* sh_element = ply.find("sh");

  GaussianScene scene;
  resize_scene(scene, n, degree);
  const size_t coeffs = size_t(scene.sh_coeffs());
  const size_t rest_per_channel = coeffs - 1;
  float c[18] = {};
  for (size_t i = 0; i < n; ++i) {
    const size_t ci = i / kGaussiansPerChunk;
    if (i % kGaussiansPerChunk == 0) {
      for (int k = 0; k < 12; ++k) c[k] = chunk->value_float(ci, bounds[k]);
      if (has_colour_range)
        for (int k = 0; k < 6; ++k) c[12 + k] = chunk->value_float(ci, colour[k]);
    }
    const auto p = unpack_111011(uint32_t(vertex->value(i, packed_position)));
    const auto s = unpack_111011(uint32_t(vertex->value(i, packed_scale)));
    for (int a = 0; a < 3; ++a) {
      scene.positions[i][a] = lerp(c[a], c[3 + a], p[a]);
      // min_scale / max_scale are log scales (decompress-ply.ts).
      scene.scales[i][a] = std::exp(lerp(c[6 + a], c[9 + a], s[a]));
    }
    scene.rotations[i] = unpack_rotation(uint32_t(vertex->value(i, packed_rotation)));
    const uint32_t rgba = uint32_t(vertex->value(i, packed_color));
    float* sh = scene.sh.data() + i * coeffs * 3;
    for (int ch = 0; ch < 3; ++ch) {
      float v = unorm(rgba >> (24 - 8 * ch), 8);
      if (has_colour_range) v = lerp(c[12 + ch], c[15 + ch], v);
      sh[ch] = color_to_sh_dc(v);
    }
    // The stored alpha is the activated opacity (the file's logit is -ln(1/a - 1)).
    scene.opacities[i] = unorm(rgba, 8);
    for (size_t ch = 0; ch < 3 && sh_element; ++ch) {
      for (size_t k = 0; k < rest_per_channel; ++k) {
        const int b = int(sh_element->value(i, rest[ch * rest_per_channel + k]));
        const float t = b == 0 ? 0.0f : b == 255 ? 1.0f : (float(b) + 0.5f) / 256.0f;
        sh[(k + 1) * 3 + ch] = (t - 0.5f) * 8.0f;
      }
    }
  }
  finalize_scene(scene, name);
  return scene;
}

}  // namespace lfd::scene
