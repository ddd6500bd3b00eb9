#pragma once
// The files of a SOG scene (docs/rendering.md "Scene formats", after
// playcanvas/splat-transform src/lib/readers/read-sog.ts): `meta.json` and lossless WebP
// images, either inside a `.sog` ZIP archive (stored entries) or side by side in a folder.
// Reading is bounded: an entry's size is checked against the archive before it is read, and
// an image's dimensions against a limit before any pixel is decoded.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/gaussian_scene.hpp"

namespace lfd::scene {

// Returns the bytes of one file of the scene by its name in meta.json; throws InputError.
using SogFileSource = std::function<std::string(const std::string& file)>;

// A source over the entries of a `.sog` ZIP archive held in memory (libzip).
SogFileSource sog_zip_source(std::string_view archive, const std::string& name);

// A source over the files in `folder` (the unpacked layout beside meta.json `name`).
SogFileSource sog_folder_source(const std::filesystem::path& folder, const std::string& name);

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4, row-major
  size_t pixels() const { return size_t(width) * size_t(height); }
};

// The dimensions in a WebP header, without decoding; false if it is not WebP.
bool webp_dimensions(std::string_view bytes, int& width, int& height);

// Decodes a WebP image (libwebp) whose width * height must not exceed `max_pixels`; `what`
// names the file in errors ("<scene>: <what>: ...").
RgbaImage decode_webp(std::string_view bytes, size_t max_pixels, const std::string& scene,
                      const std::string& what);

// Decodes a SOG scene (v1 or v2) from its meta.json and the files it names (sog_reader.cpp).
GaussianScene read_sog_files(const SogFileSource& files, std::string_view meta_bytes,
                             const std::string& name);

}  // namespace lfd::scene
