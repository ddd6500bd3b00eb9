// Format dispatch for load_gaussian_scene (by content, see scene_parsers.hpp) and save_ply.
#include "scene/gaussian_io.hpp"

#include <fstream>

#include "scene/ply_header.hpp"
#include "scene/ply_writer.hpp"
#include "scene/scene_parsers.hpp"
#include "scene/spz_writer.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::scene {

namespace {

std::string lower_extension(const std::string& name) {
  std::string ext = std::filesystem::path(name).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string read_binary_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw_input_error("{}: no such file", path.string());
  const auto size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) throw_input_error("{}: cannot open for reading", path.string());
  std::string bytes(size_t(size), '\0');
  if (!in.read(bytes.data(), std::streamsize(size)))
    throw_input_error("{}: read error", path.string());
  return bytes;
}

}  // namespace

GaussianScene read_scene_bytes(std::string_view bytes, const std::string& name) {
  if (bytes.empty()) throw_input_error("{}: empty file", name);
  if (looks_like_ply(bytes)) {
    // A compressed PLY is a PLY with a `chunk` element (splat-transform decompress-ply.ts).
    const PlyFile ply = parse_ply(bytes, name);
    return ply.find("chunk") ? compressed_ply_to_scene(ply, name)
                             : standard_ply_to_scene(ply, name);
  }
  const auto b0 = uint8_t(bytes[0]);
  if ((bytes.size() >= 2 && b0 == 0x1f && uint8_t(bytes[1]) == 0x8b) ||
      (bytes.size() >= 4 && bytes.substr(0, 4) == "NGSP"))
    return read_spz(bytes, name);
  if (bytes.size() >= 4 && bytes.substr(0, 4) == std::string_view("PK\x03\x04", 4))
    return read_sog(bytes, name);
  if (bytes.size() >= 4 && bytes.substr(0, 4) == "glTF") return read_gltf(bytes, name);
  const std::string ext = lower_extension(name);
  if (ext == ".splat") return read_splat(bytes, name);
  if (ext == ".ksplat") return read_ksplat(bytes, name);
  if (ext == ".gltf") return read_gltf(bytes, name);
  if (ext == ".json") return read_sog_meta(bytes, name);
  throw_input_error(
      "{}: unrecognised scene format (expected PLY, compressed PLY, .splat, SPZ, SOG (.sog or "
      "meta.json), glTF/GLB with KHR_gaussian_splatting or .ksplat)",
      name);
}

GaussianScene load_gaussian_scene(const std::filesystem::path& path) {
  const std::string bytes = read_binary_file(path);
  return read_scene_bytes(bytes, path.string());
}

namespace {

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  write_file_atomic(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    if (!out) throw_input_error("{}: cannot write", path.string());
  });
}

}  // namespace

void save_ply(const std::filesystem::path& path, const GaussianScene& scene) {
  write_bytes(path, encode_ply(scene, PlyEncoding::BinaryLittleEndian));
}

void save_gaussian_scene(const std::filesystem::path& path, const GaussianScene& scene) {
  const std::string ext = lower_extension(path.string());
  if (ext == ".ply") return save_ply(path, scene);
  if (ext == ".spz") {
    std::string bytes;
    try {
      bytes = encode_spz(scene);
    } catch (const InputError& e) {
      throw_input_error("{}: {}", path.string(), e.what());
    }
    return write_bytes(path, bytes);
  }
  throw_input_error("{}: lfd writes scenes as .ply or .spz, not '{}'", path.string(), ext);
}

}  // namespace lfd::scene
