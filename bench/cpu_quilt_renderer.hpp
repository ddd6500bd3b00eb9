#pragma once
// The CPU backend of `lfd bench render`: the reference per-view quilt and CPU G2LF
// (render/per_view_quilt.hpp, render/g2lf.hpp) on all OpenMP threads; memory is the process's
// peak RSS.
#include <memory>

#include "bench/quilt_renderer.hpp"

namespace lfd::bench {

std::unique_ptr<QuiltRenderer> make_cpu_quilt_renderer();

}  // namespace lfd::bench
