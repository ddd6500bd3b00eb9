// The flat index of a work group dispatched spread over y past 65535 groups, and of an invocation
// of a 1D group (gpu/gl/shaders/work_groups_io.h; C++: gpu/gl/gl_work_groups.hpp). Include it
// after the shader's layout(local_size_x ...) line: flat_invocation_index reads gl_WorkGroupSize.
#include "gpu/gl/shaders/work_groups_io.h"

uint flat_group_index() { return gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x; }

uint flat_invocation_index() { return flat_group_index() * gl_WorkGroupSize.x + gl_LocalInvocationID.x; }
