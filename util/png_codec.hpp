#pragma once
// PNG encoding and decoding through libpng, behind util/image.hpp (which adds atomic writes and
// the non-PNG formats). libpng rather than stb_image_write or libspng: on a 45-view 512x512
// quilt (2560x4608 RGB) libpng at zlib level 1 with the Up filter writes in a sixth of
// stb_image_write's time and a smaller file, faster than libspng at the same settings, and
// reads faster than stb_image (docs/performance.md, "Writing PNG").
#include <cstdio>
#include <string>

#include "util/image.hpp"

namespace lfd::png {

// True when `file` starts with the PNG signature; reads 8 bytes (the decoder expects them read).
bool has_png_signature(std::FILE* file);

// Decodes the rest of a PNG whose signature has been read as `channels` 8-bit channels (1, 3
// or 4), converted as stb_image converts (16-bit samples keep their high byte; palette, low bit
// depths and tRNS expanded; colour to gray by stb's integer luma; alpha dropped or set to 255).
// Throws InputError naming `name` for a corrupt, truncated or absurdly large file.
Image8 decode(std::FILE* file, const std::string& name, int channels);

// Encodes `image` (1 to 4 channels: gray, gray + alpha, RGB, RGBA) as an 8-bit PNG; settings
// chosen for speed: zlib level 1, every row Up-filtered. Throws std::runtime_error naming `name`
// when libpng fails (e.g. a write error).
void encode(std::FILE* file, const std::string& name, const Image8& image);
// The same PNG as bytes in memory (what a service sends as a reply body).
std::string encode_to_bytes(const std::string& name, const Image8& image);

}  // namespace lfd::png
