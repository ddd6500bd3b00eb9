#include "gpu/gl/driver_workarounds.hpp"

#include <cstdlib>

namespace lfd::gpu {

void apply_driver_workarounds() {
  // overwrite = 0: a user's own ZINK_INLINE_UNIFORMS (e.g. =1 to see the bug) is kept.
  setenv("ZINK_INLINE_UNIFORMS", "0", 0);
}

}  // namespace lfd::gpu
