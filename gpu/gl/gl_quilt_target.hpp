#pragma once
// The one check of a caller's quilt texture before a GL renderer draws a quilt into it (the
// per-view renderers, G2LF and V2LF): the layout is usable, the texture is a plain 2D texture of
// the layout's size, and there is a tile for every view.
#include <string>

#include "gpu/gl/gl_objects.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"

namespace lfd::gpu {

// layout.check("quilt"), then InputError "<renderer>: ..." when `quilt` is not a 2D texture of
// the layout's size or geometry.views do not fit its cols x rows tiles.
void check_quilt_target(const std::string& renderer, const render::QuiltGeometry& geometry,
                        const render::QuiltLayout& layout, const Texture& quilt);

}  // namespace lfd::gpu
