#pragma once
// Driver bugs lfd steps around for every context it makes (docs/gpu.md "What zink found").
// Called before the first EGL display or GLFW window of the process: the drivers read their
// options when their screen is created.
namespace lfd::gpu {

// Mesa 22.3's zink can dispatch a compute program with a shader variant compiled for earlier
// values of its uniforms when it inlines them (ZINK_INLINE_UNIFORMS, on by default on CPU Vulkan
// devices such as lavapipe; reproducer: tests/drivers/zink_inlined_uniforms.c). Turns the
// inlining off unless the user set ZINK_INLINE_UNIFORMS; other drivers ignore the variable.
void apply_driver_workarounds();

}  // namespace lfd::gpu
