#pragma once
// The sweeping planes of G2LF on the GPU (paper Alg. 1 lines 4-5; the GL twin of
// render/sweeping_planes.hpp): one layer of a 2D array texture per plane, RGBA = premultiplied
// colour C_k and transmittance T_k, rows bottom-up as GL draws them (texel row Hp - 1 - r holds
// row r of the CPU's plane, whose row 0 is the top of the reference image), and beside it the plane table the binning pass writes on the GPU: how many
// planes there are this frame and their base-camera depths d_k. The array has a layer for every
// possible plane (N_chunk); which are used is known only on the GPU, so no frame waits for it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/planes/shaders/plane_table_io.h"
#include "render/sweeping_planes.hpp"

namespace lfd::gpu {

// Texel format of the planes. kRgba8 is the CPU's kU8 (the paper's default), kRgba32f its kF32;
// kRgba16f halves kRgba32f's memory (no CPU twin).
enum class PlaneFormat { kRgba8, kRgba16f, kRgba32f };

GLenum gl_internal_format(PlaneFormat format);
size_t bytes_per_plane_texel(PlaneFormat format);
PlaneFormat plane_format_for(render::PlanePrecision precision);
const char* plane_format_name(PlaneFormat format);

// The plane table buffer's layout (std430), PlaneTableHeader then PlaneTableEntry[max_planes + 1],
// is the shaders' own: gpu/planes/shaders/plane_table_io.h.
static_assert(sizeof(PlaneTableHeader) == 16 && sizeof(PlaneTableEntry) == 8, "std430: packed 4-byte members");
inline size_t plane_table_bytes(int max_planes) {
  return sizeof(PlaneTableHeader) + sizeof(PlaneTableEntry) * (size_t(max_planes) + 1);
}

// The plane table on the GPU (written by the binning, read by the swizzle).
struct GlPlaneTable {
  int max_planes = 0;
  Buffer buffer;  // PlaneTableHeader, PlaneTableEntry[max_planes + 1]

  GlPlaneTable() = default;
  explicit GlPlaneTable(int max_planes);  // zeroed: no planes
  // Read-backs for tests and reports (they wait for the GPU).
  PlaneTableHeader read_header() const;
  std::vector<PlaneTableEntry> read_entries() const;  // the plane_count + 1 in use
};

struct GlPlanes {
  PlaneFormat format = PlaneFormat::kRgba8;
  int max_planes = 0, width = 0, height = 0;
  Texture texels;  // GL_TEXTURE_2D_ARRAY, max_planes layers
  GlPlaneTable table;

  GlPlanes() = default;
  GlPlanes(PlaneFormat format, int max_planes, int width, int height);
};


// Sets `sampler` to filter planes bilinearly in the texture unit, as the CPU's bilinear plane
// lookup does (the swizzle's and the direct pass's hardware_bilinear): GL_LINEAR, and outside a
// plane the CPU's empty texel (0, 0, 0, 1) as the border colour. One fetch instead of four, with
// the unit's own weights (8 bits of fraction on NVIDIA), so within the tests' bars, not exact.
void set_plane_bilinear(const Sampler& sampler);

// The texels `planes` needs for `max_planes` layers of `width` x `height` in `format`.
size_t plane_texture_bytes(PlaneFormat format, int max_planes, int width, int height);

// CPU planes on the GPU (to swizzle them there: tests, and the stage-by-stage comparison). The
// format follows the CPU precision unless `format` says otherwise (f32 planes into RGBA16F).
GlPlanes upload_planes(const render::SweepingPlanes& planes);
GlPlanes upload_planes(const render::SweepingPlanes& planes, PlaneFormat format);

}  // namespace lfd::gpu
