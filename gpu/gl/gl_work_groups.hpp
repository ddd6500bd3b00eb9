#pragma once
// One work group a thing past the 65535 groups a dimension takes (gpu/gl/shaders/work_groups_io.h):
// the groups as min(groups, kMaxWorkGroupsX) x rows, the shader skipping those past the count with
// flat_group_index() (gpu/gl/shaders/flat_group.glsl).
#include <cstddef>

#include <epoxy/gl.h>

namespace lfd::gpu {

struct WorkGroups {
  GLuint x = 0, y = 0;
};
// `groups` groups spread over rows of at most kMaxWorkGroupsX (0 x 0 for none). A pass dispatches
// them through its program (Program::dispatch_groups, dispatch_1d), which checks its bindings first.
WorkGroups spread_work_groups(size_t groups);

}  // namespace lfd::gpu
