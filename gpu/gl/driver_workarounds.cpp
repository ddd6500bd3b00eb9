#include "gpu/gl/driver_workarounds.hpp"

#include <cstdlib>
#include <mutex>

namespace lfd::gpu {

void apply_driver_workarounds() {
  // Once per process, before the drivers start: setenv is not safe beside another thread's
  // getenv, so it is not repeated for every context. overwrite = 0 keeps a user's own value
  // (ZINK_INLINE_UNIFORMS=1 shows the bug again).
  static std::once_flag once;
  std::call_once(once, [] { setenv("ZINK_INLINE_UNIFORMS", "0", 0); });
}

}  // namespace lfd::gpu
