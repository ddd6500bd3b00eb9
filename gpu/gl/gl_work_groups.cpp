#include "gpu/gl/gl_work_groups.hpp"

#include <algorithm>
#include <stdexcept>

#include "gpu/gl/shaders/work_groups_io.h"

namespace lfd::gpu {

WorkGroups spread_work_groups(size_t groups) {
  if (groups == 0) return {};
  const size_t x = std::min<size_t>(groups, kMaxWorkGroupsX);
  const size_t y = (groups + x - 1) / x;
  if (y > kMaxWorkGroupsX) throw std::length_error("work groups: over 65535^2 groups in one dispatch");
  return {GLuint(x), GLuint(y)};
}

}  // namespace lfd::gpu
