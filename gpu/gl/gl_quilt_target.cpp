#include "gpu/gl/gl_quilt_target.hpp"

#include "util/error.hpp"

namespace lfd::gpu {

void check_quilt_target(const std::string& renderer, const render::QuiltGeometry& geometry,
                        const render::QuiltLayout& layout, const Texture& quilt) {
  layout.check("quilt");
  if (quilt.width() != layout.width || quilt.height() != layout.height || quilt.layers() != 0)
    throw_input_error("{}: the quilt texture is {}x{}, the layout {}x{}", renderer, quilt.width(), quilt.height(),
                      layout.width, layout.height);
  if (geometry.views > layout.cols * layout.rows)
    throw_input_error("{}: {} views do not fit a quilt of {} tiles", renderer, geometry.views,
                      layout.cols * layout.rows);
}

}  // namespace lfd::gpu
