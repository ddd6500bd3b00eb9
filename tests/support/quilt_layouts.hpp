#pragma once
// Small quilt layouts for tests: a grid of cols x rows tiles, every tile a view.
#include "render/quilt_layout.hpp"

namespace lfd::test {

// A `cols` x `rows` quilt of `width` x `height` pixels whose views are `aspect` wide.
inline render::QuiltLayout quilt_layout(int cols, int rows, int width, int height, double aspect = 1.0) {
  render::QuiltLayout q;
  q.cols = cols;
  q.rows = rows;
  q.views = cols * rows;
  q.width = width;
  q.height = height;
  q.aspect = aspect;
  return q;
}

}  // namespace lfd::test
