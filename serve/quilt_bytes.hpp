#pragma once
// A quilt image sent as bytes (holoplay `show`/`cache`) or read from a checked file, decoded to
// RGB: PNG through util's libpng codec, JPEG and the rest through stb_image. The size is checked
// from the header before anything is decoded.
#include <cstdint>
#include <span>
#include <string>

#include "util/image.hpp"

namespace lfd::serve {

// Throws InputError naming `name`.
Image8 decode_quilt_bytes(std::span<const std::uint8_t> bytes, const std::string& name, int max_side_px);

}  // namespace lfd::serve
