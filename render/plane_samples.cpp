// The direct pass's sampling kernels (render/plane_samples.hpp). Both compute, per slot and in
// the same order of operations (no fused multiply-add), the sample column, the sample and the
// front-to-back step, so their results agree bit for bit.
//
// Why a vector kernel: the scalar loop's selects (is the ray still live, is the column inside)
// compile to branches, and rays stop in no order the branch predictor can follow; profiled on
// the Go at 256 planes, the scalar kernel was the direct pass's largest cost. Eight lanes with
// masks have no branches, and the four texel reads become gathers.
#include "render/plane_samples.hpp"

#include "util/error.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define LFD_PLANE_SAMPLES_AVX2 1
#endif

namespace lfd::render {
namespace {

// x clamped to [0, top], NaN to 0.
inline float clamp_to(float x, float top) {
  const float low = x > 0.0f ? x : 0.0f;
  return low < top ? low : top;
}

template <bool kBilinear>
int sample_scalar(const SampleWindow& w, size_t i0, size_t i1) {
  const float* __restrict values = w.values;
  const float* __restrict trans_row = w.trans_row;
  float* __restrict colour = w.colour;
  float* __restrict trans = w.trans;
  const float* __restrict dx = w.dx;
  const float* __restrict u = w.u;
  const int32_t* __restrict channel_offset = w.channel_offset;
  const float ax = w.ax, au = w.au, a0 = w.a0;
  const float top = float(w.length - 1);
  const int last0 = w.length - 2;
  int fell = 0;
  for (size_t i = i0; i < i1; ++i) {
    const float t = trans[i];
    const bool live = t >= kPlaneRayMinTransmittance;
    // Clamping keeps a sample on the padding (empty) when rounding put it a hair outside.
    const float px = clamp_to(dx[i] * ax + u[i] * au + a0, top);
    float c_sampled, a_sampled;
    if constexpr (kBilinear) {
      const int col0_raw = int(px);
      const int col0 = col0_raw < last0 ? col0_raw : last0;
      const float fx = px - float(col0);
      const int at = channel_offset[i] + col0;
      const float c0 = values[at], c1 = values[at + 1];
      const float t0 = trans_row[col0], t1 = trans_row[col0 + 1];
      c_sampled = c0 + fx * (c1 - c0);
      a_sampled = t0 + fx * (t1 - t0);
    } else {
      const int col = int(px + 0.5f);
      c_sampled = values[channel_offset[i] + col];
      a_sampled = trans_row[col];
    }
    const float c = live ? c_sampled : 0.0f;
    const float a = live ? a_sampled : 1.0f;
    const float t_after = t * a;
    colour[i] += t * c;
    trans[i] = t_after;
    fell += int(live) & int(t_after < kPlaneRayMinTransmittance);
  }
  return fell;
}

#ifdef LFD_PLANE_SAMPLES_AVX2
// Eight slots a step. Lanes past i1 and stopped rays keep their colour and transmittance (a
// blend, not a multiply by zero, so they stay bit for bit what they were).
template <bool kBilinear>
__attribute__((target("avx2"))) int sample_avx2(const SampleWindow& w, size_t i0, size_t i1) {
  const __m256 ax = _mm256_set1_ps(w.ax), au = _mm256_set1_ps(w.au), a0 = _mm256_set1_ps(w.a0);
  const __m256 zero = _mm256_setzero_ps(), top = _mm256_set1_ps(float(w.length - 1));
  const __m256 half = _mm256_set1_ps(0.5f), stop = _mm256_set1_ps(kPlaneRayMinTransmittance);
  const __m256i last0 = _mm256_set1_epi32(w.length - 2);
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  int fell = 0;
  for (size_t i = i0; i < i1; i += 8) {
    const __m256 t = _mm256_loadu_ps(w.trans + i);
    __m256 live = _mm256_cmp_ps(t, stop, _CMP_GE_OQ);
    if (i1 - i < 8) {
      const __m256i inside = _mm256_cmpgt_epi32(_mm256_set1_epi32(int(i1 - i)), lane);
      live = _mm256_and_ps(live, _mm256_castsi256_ps(inside));
    }
    // (dx ax + u au) + a0, then max(., 0) and min(., top): clamp_to's order and NaN rule.
    const __m256 raw = _mm256_add_ps(
        _mm256_add_ps(_mm256_mul_ps(_mm256_loadu_ps(w.dx + i), ax), _mm256_mul_ps(_mm256_loadu_ps(w.u + i), au)), a0);
    const __m256 px = _mm256_min_ps(_mm256_max_ps(raw, zero), top);
    const __m256i offset = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(w.channel_offset + i));
    __m256 c, a;
    if constexpr (kBilinear) {
      const __m256i col0 = _mm256_min_epi32(_mm256_cvttps_epi32(px), last0);
      const __m256 fx = _mm256_sub_ps(px, _mm256_cvtepi32_ps(col0));
      const __m256i at = _mm256_add_epi32(offset, col0);
      const __m256 c0 = _mm256_i32gather_ps(w.values, at, 4), c1 = _mm256_i32gather_ps(w.values + 1, at, 4);
      const __m256 t0 = _mm256_i32gather_ps(w.trans_row, col0, 4), t1 = _mm256_i32gather_ps(w.trans_row + 1, col0, 4);
      c = _mm256_add_ps(c0, _mm256_mul_ps(fx, _mm256_sub_ps(c1, c0)));
      a = _mm256_add_ps(t0, _mm256_mul_ps(fx, _mm256_sub_ps(t1, t0)));
    } else {
      const __m256i col = _mm256_cvttps_epi32(_mm256_add_ps(px, half));
      c = _mm256_i32gather_ps(w.values, _mm256_add_epi32(offset, col), 4);
      a = _mm256_i32gather_ps(w.trans_row, col, 4);
    }
    const __m256 t_after = _mm256_blendv_ps(t, _mm256_mul_ps(t, a), live);
    const __m256 colour = _mm256_loadu_ps(w.colour + i);
    _mm256_storeu_ps(w.colour + i, _mm256_blendv_ps(colour, _mm256_add_ps(colour, _mm256_mul_ps(t, c)), live));
    _mm256_storeu_ps(w.trans + i, t_after);
    const __m256 fell_now = _mm256_and_ps(live, _mm256_cmp_ps(t_after, stop, _CMP_LT_OQ));
    fell += __builtin_popcount(unsigned(_mm256_movemask_ps(fell_now)));
  }
  return fell;
}
#endif

SampleKernel detect_kernel() {
#ifdef LFD_PLANE_SAMPLES_AVX2
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2")) return SampleKernel::kAvx2;
#endif
  return SampleKernel::kScalar;
}

}  // namespace

const char* sample_kernel_name(SampleKernel kernel) { return kernel == SampleKernel::kAvx2 ? "avx2" : "scalar"; }

SampleKernel parse_sample_kernel(const std::string& name) {
  if (name == "scalar") return SampleKernel::kScalar;
  if (name == "avx2") return SampleKernel::kAvx2;
  throw_input_error("sampling kernel '{}': expected scalar or avx2", name);
}

SampleKernel sample_window_kernel() {
  static const SampleKernel kernel = detect_kernel();
  return kernel;
}

bool sample_kernel_available(SampleKernel kernel) {
  return kernel == SampleKernel::kScalar || sample_window_kernel() == SampleKernel::kAvx2;
}

int sample_window(SampleKernel kernel, const SampleWindow& w, size_t i0, size_t i1, bool bilinear) {
#ifdef LFD_PLANE_SAMPLES_AVX2
  if (kernel == SampleKernel::kAvx2) return bilinear ? sample_avx2<true>(w, i0, i1) : sample_avx2<false>(w, i0, i1);
#endif
  (void)kernel;
  return bilinear ? sample_scalar<true>(w, i0, i1) : sample_scalar<false>(w, i0, i1);
}

}  // namespace lfd::render
