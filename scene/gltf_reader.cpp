// glTF 2.0 with KHR_gaussian_splatting (docs/rendering.md "Scene formats"; KhronosGroup/glTF
// extensions/2.0/Khronos/KHR_gaussian_splatting; as written by playcanvas/splat-transform
// src/lib/writers/write-glb.ts). tinygltf parses the container; this file reads the
// attributes of every POINTS primitive that carries the extension: POSITION,
// KHR_gaussian_splatting:ROTATION (xyzw), :SCALE (linear), :OPACITY (activated, 0-1) and
// :SH_DEGREE_l_COEF_n (VEC3 per coefficient), with COLOR_0 standing in for a missing DC term.
// Rotation and opacity may be normalised integers (KHR_mesh_quantization).
// glTF is y-up with the same handedness as 3DGS's y-down COLMAP frame: the two differ by a
// half turn about z (splat-transform's Transform.PLY), so x and y change sign, as do the
// quaternion's x and y and each SH basis function odd in (x, y). Node transforms are not applied.
#include <tiny_gltf.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "scene/scene_checks.hpp"
#include "scene/scene_parsers.hpp"
#include "scene/sh_basis.hpp"
#include "util/error.hpp"

namespace lfd::scene {

namespace {

constexpr const char* kExtension = "KHR_gaussian_splatting";
constexpr uint64_t kMaxGaussians = uint64_t(1) << 28;
constexpr uint64_t kMaxBufferBytes = uint64_t(1) << 32;
// Parity of each SH basis function (in computeColorFromSH's order) under (x, y) -> (-x, -y).
constexpr float kHalfTurnZSh[15] = {-1, 1, -1, 1, -1, 1, -1, 1, -1, 1, -1, 1, -1, 1, -1};

// One attribute as floats, `components` per Gaussian, after checking that the accessor and its
// buffer view lie inside their buffer.
std::vector<float> read_attribute(const tinygltf::Model& m, int index, int components,
                                  bool allow_normalized, const std::string& name,
                                  const std::string& what) {
  if (index < 0 || size_t(index) >= m.accessors.size())
    throw_input_error("{}: glTF {}: accessor {} does not exist", name, what, index);
  const tinygltf::Accessor& a = m.accessors[size_t(index)];
  if (a.sparse.isSparse) throw_input_error("{}: glTF {}: sparse accessors are not supported", name, what);
  const int type_components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  if (type_components != components)
    throw_input_error("{}: glTF {}: accessor has {} components, expected {}", name, what,
                      type_components, components);
  const bool is_float = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
  if (!is_float && !(allow_normalized && a.normalized))
    throw_input_error("{}: glTF {}: component type {} is not float{}", name, what,
                      a.componentType, allow_normalized ? " or a normalised integer" : "");
  const int size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  if (size <= 0 || (!is_float && size > 2))
    throw_input_error("{}: glTF {}: component type {} is not supported", name, what, a.componentType);
  if (a.bufferView < 0 || size_t(a.bufferView) >= m.bufferViews.size())
    throw_input_error("{}: glTF {}: buffer view {} does not exist", name, what, a.bufferView);
  const tinygltf::BufferView& v = m.bufferViews[size_t(a.bufferView)];
  if (v.buffer < 0 || size_t(v.buffer) >= m.buffers.size())
    throw_input_error("{}: glTF {}: buffer {} does not exist", name, what, v.buffer);
  const std::vector<unsigned char>& buffer = m.buffers[size_t(v.buffer)].data;
  const uint64_t element = uint64_t(size) * uint64_t(components);
  const uint64_t stride = v.byteStride ? uint64_t(v.byteStride) : element;
  const uint64_t start = uint64_t(v.byteOffset) + uint64_t(a.byteOffset);
  if (a.count > kMaxGaussians || stride < element || uint64_t(v.byteOffset) > buffer.size() ||
      uint64_t(v.byteLength) > buffer.size() - v.byteOffset ||
      (a.count > 0 && uint64_t(a.byteOffset) + stride * (a.count - 1) + element > v.byteLength))
    throw_input_error("{}: glTF {}: {} elements do not fit in their buffer view", name, what,
                      a.count);
  std::vector<float> out(a.count * size_t(components));
  const unsigned char* base = buffer.data() + start;
  for (size_t i = 0; i < a.count; ++i)
    for (int k = 0; k < components; ++k) {
      const unsigned char* p = base + i * stride + size_t(k * size);
      float value = 0;
      switch (a.componentType) {  // glTF 2.0 3.11: normalised integer to float
        case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(&value, p, 4); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: value = float(*p) / 255.0f; break;
        case TINYGLTF_COMPONENT_TYPE_BYTE: value = std::max(float(int8_t(*p)) / 127.0f, -1.0f); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: value = float(uint16_t(p[0] | p[1] << 8)) / 65535.0f; break;
        case TINYGLTF_COMPONENT_TYPE_SHORT: value = std::max(float(int16_t(p[0] | p[1] << 8)) / 32767.0f, -1.0f); break;
        default: throw_input_error("{}: glTF {}: component type {} is not supported", name, what, a.componentType);
      }
      out[i * size_t(components) + size_t(k)] = value;
    }
  return out;
}

int attribute(const tinygltf::Primitive& p, const std::string& key) {
  const auto it = p.attributes.find(key);
  return it == p.attributes.end() ? -1 : it->second;
}

std::string sh_key(int degree, int coefficient) {
  return fmt::format("{}:SH_DEGREE_{}_COEF_{}", kExtension, degree, coefficient);
}

// The highest complete SH degree of a primitive (all 2l + 1 coefficients of each band).
int sh_degree_of(const tinygltf::Primitive& p) {
  int degree = 0;
  while (degree < 3) {
    for (int c = 0; c < 2 * degree + 3; ++c)
      if (attribute(p, sh_key(degree + 1, c)) < 0) return degree;
    ++degree;
  }
  return degree;
}

std::vector<float> required(const tinygltf::Model& m, const tinygltf::Primitive& p,
                            const std::string& key, int components, bool normalized,
                            size_t count, const std::string& name) {
  const int index = attribute(p, key);
  if (index < 0) throw_input_error("{}: glTF splat primitive has no {} attribute", name, key);
  std::vector<float> v = read_attribute(m, index, components, normalized, name, key);
  if (v.size() != count * size_t(components))
    throw_input_error("{}: glTF {} holds {} elements, POSITION {}", name, key,
                      v.size() / size_t(components), count);
  return v;
}

// Appends the Gaussians of one splat primitive to `scene` (already at its final SH degree).
void append_primitive(const tinygltf::Model& m, const tinygltf::Primitive& p,
                      GaussianScene& scene, size_t first, const std::string& name) {
  const std::string ext = std::string(kExtension) + ":";
  const int pos_index = attribute(p, "POSITION");
  if (pos_index < 0) throw_input_error("{}: glTF splat primitive has no POSITION", name);
  const std::vector<float> pos = read_attribute(m, pos_index, 3, false, name, "POSITION");
  const size_t n = pos.size() / 3;
  const auto rot = required(m, p, ext + "ROTATION", 4, true, n, name);
  const auto scale = required(m, p, ext + "SCALE", 3, false, n, name);
  const auto opacity = required(m, p, ext + "OPACITY", 1, true, n, name);
  const bool has_dc = attribute(p, sh_key(0, 0)) >= 0;
  const auto dc = has_dc ? required(m, p, sh_key(0, 0), 3, false, n, name)
                         : required(m, p, "COLOR_0", 4, true, n, name);
  const size_t coeffs = size_t(scene.sh_coeffs());
  for (size_t i = 0; i < n; ++i) {
    const size_t g = first + i;
    scene.positions[g] = {-pos[i * 3], -pos[i * 3 + 1], pos[i * 3 + 2]};
    scene.scales[g] = {scale[i * 3], scale[i * 3 + 1], scale[i * 3 + 2]};
    scene.rotations[g] = {rot[i * 4 + 3], -rot[i * 4], -rot[i * 4 + 1], rot[i * 4 + 2]};
    scene.opacities[g] = opacity[i];
    for (int c = 0; c < 3; ++c)
      scene.sh[g * coeffs * 3 + size_t(c)] =
          has_dc ? dc[i * 3 + size_t(c)] : color_to_sh_dc(dc[i * 4 + size_t(c)]);
  }
  int k = 0;
  for (int degree = 1; degree <= scene.sh_degree; ++degree)
    for (int c = 0; c < 2 * degree + 1; ++c, ++k) {
      const auto sh = required(m, p, sh_key(degree, c), 3, false, n, name);
      for (size_t i = 0; i < n; ++i)
        for (int ch = 0; ch < 3; ++ch)
          scene.sh[((first + i) * coeffs + size_t(k) + 1) * 3 + size_t(ch)] =
              kHalfTurnZSh[k] * sh[i * 3 + size_t(ch)];
    }
}

// Reads buffers that a .gltf names beside itself; bounded, regular files only.
bool read_neighbour(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                    void*) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || !std::filesystem::is_regular_file(path, ec) || size > kMaxBufferBytes) {
    if (err) *err += "cannot read buffer file " + path + "\n";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  out->resize(size_t(size));
  return bool(in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size)));
}

bool no_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
              const unsigned char*, int, void*) {
  return true;  // splat scenes need no textures; never decode them
}

tinygltf::Model parse_model(std::string_view bytes, const std::string& name) {
  if (bytes.size() > UINT32_MAX) throw_input_error("{}: glTF file larger than 4 GiB", name);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(no_image, nullptr);
  loader.SetFsCallbacks({&tinygltf::FileExists, &tinygltf::ExpandFilePath, &read_neighbour,
                         &tinygltf::WriteWholeFile, nullptr});
  tinygltf::Model model;
  std::string err, warn;
  const std::string dir = std::filesystem::path(name).parent_path().string();
  bool ok = false;
  try {
    ok = bytes.substr(0, 4) == "glTF"
             ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                           reinterpret_cast<const unsigned char*>(bytes.data()),
                                           unsigned(bytes.size()), dir)
             : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                          unsigned(bytes.size()), dir);
  } catch (const std::exception& e) {
    throw_input_error("{}: malformed glTF ({})", name, e.what());
  }
  if (!ok) {
    for (char& c : err) if (c == '\n') c = ' ';
    while (!err.empty() && err.back() == ' ') err.pop_back();
    throw_input_error("{}: malformed glTF: {}", name, err.empty() ? "unreadable" : err);
  }
  return model;
}

}  // namespace

GaussianScene read_gltf(std::string_view bytes, const std::string& name) {
  const tinygltf::Model model = parse_model(bytes, name);
  std::vector<const tinygltf::Primitive*> splats;
  for (const auto& mesh : model.meshes)
    for (const auto& p : mesh.primitives)
      if (p.extensions.count(kExtension)) splats.push_back(&p);
  if (splats.empty())
    throw_input_error("{}: glTF has no primitive with the {} extension", name, kExtension);
  size_t total = 0;
  int degree = 3;
  for (const auto* p : splats) {
    if (p->mode != TINYGLTF_MODE_POINTS)
      throw_input_error("{}: glTF splat primitive has mode {}, not POINTS", name, p->mode);
    const int pos = attribute(*p, "POSITION");
    if (pos < 0) throw_input_error("{}: glTF splat primitive has no POSITION", name);
    // Read (and so bounds-check) the positions before sizing the scene by their count.
    total += read_attribute(model, pos, 3, false, name, "POSITION").size() / 3;
    if (total > kMaxGaussians)
      throw_input_error("{}: glTF claims more than {} Gaussians", name, kMaxGaussians);
    degree = std::min(degree, sh_degree_of(*p));  // bands every primitive has
  }
  GaussianScene scene;
  resize_scene(scene, total, degree);
  size_t first = 0;
  for (const auto* p : splats) {
    append_primitive(model, *p, scene, first, name);
    first += model.accessors[size_t(attribute(*p, "POSITION"))].count;
  }
  finalize_scene(scene, name);
  return scene;
}

}  // namespace lfd::scene
