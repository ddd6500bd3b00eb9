#pragma once
// The innermost loop of the direct pass (render/plane_rays.hpp; docs/performance.md "Where the
// direct pass's time went"): a window of rays, consecutive slots of the row's arrays, each
// sampling one blended plane row (render/plane_row.hpp) at its own column and compositing the
// sample front to back. Two kernels compute it bit for bit alike: a scalar one, and on x86-64
// CPUs with AVX2 one that does eight rays at a time with gathers. sample_window_kernel() is the
// AVX2 one where the CPU has it.
#include <cstddef>
#include <cstdint>
#include <string>

namespace lfd::render {

// A ray stops below half an 8-bit step of transmittance, as the swizzle's
// (render/swizzle_blend.cpp).
constexpr float kPlaneRayMinTransmittance = 0.5f / 255.0f;

// Slots [i0, i1) sample the blended row at buffer coordinate px = dx ax + u au + a0. A ray
// already below kPlaneRayMinTransmittance is left as it is (its sample is an empty texel).
struct SampleWindow {
  const float* values;     // BlendedPlaneRow::values: R, G, B, T arrays `stride` floats apart
  const float* trans_row;  // its T array
  int length;              // texels per array, the padding included
  float ax, au, a0;
  const float* dx;
  const float* u;
  const int32_t* channel_offset;  // channel x stride, per slot
  float* colour;
  float* trans;
};

// The vector kernel reads (but leaves as they are) up to this many slots past i1 - 1: the slot
// arrays must extend that far, with a finite dx and u and a channel offset within the row.
constexpr size_t kSampleWindowOverread = 7;

enum class SampleKernel { kScalar, kAvx2 };
// "scalar", "avx2"; the parse throws InputError naming the value.
const char* sample_kernel_name(SampleKernel kernel);
SampleKernel parse_sample_kernel(const std::string& name);

// The fastest kernel this CPU has (render::PlaneRays' default).
SampleKernel sample_window_kernel();
// Whether this CPU can run `kernel`.
bool sample_kernel_available(SampleKernel kernel);

// Samples and composites the window with `kernel` (it must be available); returns how many rays
// fell below the stopping transmittance. `bilinear`: linear between the two columns around px;
// else the nearest column.
int sample_window(SampleKernel kernel, const SampleWindow& w, size_t i0, size_t i1, bool bilinear);

}  // namespace lfd::render
