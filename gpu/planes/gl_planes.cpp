#include "gpu/planes/gl_planes.hpp"

#include <algorithm>
#include <stdexcept>


namespace lfd::gpu {

void set_plane_bilinear(const Sampler& sampler) {
  const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  glSamplerParameterfv(sampler.id(), GL_TEXTURE_BORDER_COLOR, empty);
}

GLenum gl_internal_format(PlaneFormat format) {
  switch (format) {
    case PlaneFormat::kRgba8: return GL_RGBA8;
    case PlaneFormat::kRgba16f: return GL_RGBA16F;
    case PlaneFormat::kRgba32f: return GL_RGBA32F;
  }
  return GL_RGBA8;
}

size_t bytes_per_plane_texel(PlaneFormat format) { return bytes_per_texel(gl_internal_format(format)); }

PlaneFormat plane_format_for(render::PlanePrecision precision) {
  return precision == render::PlanePrecision::kU8 ? PlaneFormat::kRgba8 : PlaneFormat::kRgba32f;
}

const char* plane_format_name(PlaneFormat format) {
  switch (format) {
    case PlaneFormat::kRgba8: return "u8";
    case PlaneFormat::kRgba16f: return "f16";
    case PlaneFormat::kRgba32f: return "f32";
  }
  return "?";
}

size_t plane_texture_bytes(PlaneFormat format, int max_planes, int width, int height) {
  return size_t(width) * size_t(height) * size_t(max_planes) * bytes_per_plane_texel(format);
}

GlPlaneTable::GlPlaneTable(int planes) : max_planes(planes), buffer(plane_table_bytes(planes)) {
  const std::vector<uint8_t> zero(buffer.bytes(), 0);
  buffer.upload(zero.data(), zero.size());
}

PlaneTableHeader GlPlaneTable::read_header() const {
  PlaneTableHeader h;
  buffer.download(&h, sizeof(h));
  return h;
}

std::vector<PlaneTableEntry> GlPlaneTable::read_entries() const {
  const uint32_t count = read_header().plane_count;
  std::vector<PlaneTableEntry> out(count + 1);
  buffer.download(out.data(), out.size() * sizeof(PlaneTableEntry), sizeof(PlaneTableHeader));
  return out;
}

GlPlanes::GlPlanes(PlaneFormat f, int planes, int w, int h)
    : format(f), max_planes(planes), width(w), height(h),
      texels(gl_internal_format(f), w, h, planes), table(planes) {
  // Texels are read with texelFetch (the swizzle filters by hand, as the CPU), so the sampler
  // state only matters to other readers.
  texels.set_filter(GL_NEAREST);
}

GlPlanes upload_planes(const render::SweepingPlanes& planes) {
  return upload_planes(planes, plane_format_for(planes.precision));
}

GlPlanes upload_planes(const render::SweepingPlanes& planes, PlaneFormat format) {
  if (planes.count < 1) throw std::logic_error("upload_planes: no planes");
  const bool u8 = planes.precision == render::PlanePrecision::kU8;
  if (u8 != (format == PlaneFormat::kRgba8))
    throw std::logic_error("upload_planes: u8 planes go to RGBA8 and float planes to RGBA16F/32F");
  GlPlanes out(format, planes.count, planes.width, planes.height);
  // Rows bottom-up, as the layered raster draws them.
  const size_t texel_bytes = u8 ? 4 : 4 * sizeof(float);
  const size_t row_bytes = size_t(planes.width) * texel_bytes;
  const auto* src = u8 ? static_cast<const uint8_t*>(planes.texels_u8.data())
                       : reinterpret_cast<const uint8_t*>(planes.texels_f32.data());
  std::vector<uint8_t> flipped(row_bytes * planes.height * planes.count);
  for (int k = 0; k < planes.count; ++k)
    for (int r = 0; r < planes.height; ++r)
      std::copy_n(src + (size_t(k) * planes.height + r) * row_bytes, row_bytes,
                  flipped.data() + (size_t(k) * planes.height + (planes.height - 1 - r)) * row_bytes);
  glTextureSubImage3D(out.texels.id(), 0, 0, 0, 0, planes.width, planes.height, planes.count,
                      GL_RGBA, u8 ? GL_UNSIGNED_BYTE : GL_FLOAT, flipped.data());
  check_gl("uploading sweeping planes");
  PlaneTableHeader header;
  header.plane_count = uint32_t(planes.count);
  out.table.buffer.upload(&header, sizeof(header));
  std::vector<PlaneTableEntry> entries(size_t(planes.count) + 1);
  for (int k = 0; k < planes.count; ++k) entries[size_t(k)].depth = planes.plane_depth[size_t(k)];
  out.table.buffer.upload(entries.data(), entries.size() * sizeof(PlaneTableEntry), sizeof(header));
  return out;
}

}  // namespace lfd::gpu
