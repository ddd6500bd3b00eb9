#include "gpu/planes/gl_swizzle.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "gpu/planes/shaders/plane_table_io.h"
#include "gpu/planes/shaders/swizzle.comp.glsl.hpp"
#include "gpu/planes/shaders/swizzle_io.h"
#include "gpu/planes/shaders/swizzle_table.comp.glsl.hpp"

namespace lfd::gpu {
namespace {


// The cameras a plane column is computed from: the table pass's, or the swizzle's without a table.
void set_camera_uniforms(const Program& p, const render::QuiltGeometry& geometry, const render::ReferenceCamera& ref) {
  glUniform1f(p.uniform("focal_distance"), geometry.focal_distance);
  glUniform1f(p.uniform("tan_x"), geometry.base.tan_half_fov_x());
  glUniform1f(p.uniform("tan_y"), geometry.base.tan_half_fov_y());
  glUniform1f(p.uniform("tan_rx"), ref.camera.tan_half_fov_x());
  glUniform1f(p.uniform("tan_ry"), ref.camera.tan_half_fov_y());
  glUniform1f(p.uniform("d_forward_eff"), ref.d_forward_eff);
}


}  // namespace

GlSwizzle::GlSwizzle(int views_per_invocation)
    : GlSwizzle(SwizzleOptions{views_per_invocation, SwizzleOptions{}.factor_table, SwizzleOptions{}.hardware_bilinear}) {}

GlSwizzle::GlSwizzle(const SwizzleOptions& options) : options_(options) {
  if (options_.views_per_invocation < 1 || options_.views_per_invocation > 64)
    throw std::invalid_argument("GlSwizzle: views per invocation must be 1..64");
  if (options_.factor_table)
    table_ = Program("g2lf swizzle: views x planes table", {{GL_COMPUTE_SHADER, swizzle_table_comp_glsl}}, {},
                     {storage_buffer("plane_table", kPlaneTableBinding, Access::read),
                      storage_buffer("view_offsets", kSwizzleViewOffsetsBinding, Access::read),
                      storage_buffer("plane_factors", kSwizzlePlaneFactorsBinding, Access::write),
                      storage_buffer("view_plane_columns", kSwizzleViewPlaneColumnsBinding, Access::write)});
  if (options_.hardware_bilinear) set_plane_bilinear(linear_);
}

const Program& GlSwizzle::program(render::PlaneFilter filter, GLenum quilt_format) {
  const auto key = std::make_pair(int(filter), quilt_format);
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    const bool bilinear = filter == render::PlaneFilter::kBilinear;
    std::vector<Binding> bindings{texture("planes", kSwizzlePlanesUnit), image("quilt", kSwizzleQuiltImage, Access::write),
                                  storage_buffer("plane_table", kPlaneTableBinding, Access::read)};
    if (options_.factor_table) {  // the table pass's columns; without it the view offsets
      bindings.push_back(storage_buffer("plane_factors", kSwizzlePlaneFactorsBinding, Access::read));
      bindings.push_back(storage_buffer("view_plane_columns", kSwizzleViewPlaneColumnsBinding, Access::read));
    } else {
      bindings.push_back(storage_buffer("view_offsets", kSwizzleViewOffsetsBinding, Access::read));
    }
    Program p(std::string("g2lf swizzle (") + (bilinear ? "bilinear" : "nearest") + ")",
              {{GL_COMPUTE_SHADER, swizzle_comp_glsl}},
              {std::string("BILINEAR ") + (bilinear ? "1" : "0"),
               std::string("HW_BILINEAR ") + (options_.hardware_bilinear ? "1" : "0"),
               std::string("TABLE ") + (options_.factor_table ? "1" : "0"),
               std::string("QUILT_FORMAT ") + image_format_qualifier(quilt_format, "quilt texture"),
               "VIEWS " + std::to_string(options_.views_per_invocation)},
              std::move(bindings));
    it = programs_.emplace(key, std::move(p)).first;
  }
  return it->second;
}

void GlSwizzle::write_table(const GlPlanes& planes, const render::QuiltGeometry& geometry,
                            const render::ReferenceCamera& ref) {
  const int V = geometry.views;
  plane_factors_.ensure(size_t(std::max(planes.max_planes, 1)) * 2 * sizeof(float));
  view_plane_columns_.ensure(size_t(std::max(planes.max_planes, 1)) * size_t(V) * sizeof(float));
  const Program& p = table_;
  p.use();
  p.bind("plane_table", planes.table.buffer);
  p.bind("view_offsets", view_offsets_);
  p.bind("plane_factors", plane_factors_);
  p.bind("view_plane_columns", view_plane_columns_);
  glUniform2i(p.uniform("view_size"), geometry.base.width, geometry.base.height);
  glUniform2i(p.uniform("plane_size"), planes.width, planes.height);
  set_camera_uniforms(p, geometry, ref);
  glUniform1i(p.uniform("view_count"), V);
  // Every possible plane (the count is on the GPU); those past it return at once.
  p.dispatch((GLuint(V) + kSwizzleTableGroupSize - 1) / kSwizzleTableGroupSize, GLuint(std::max(planes.max_planes, 1)));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GlSwizzle::run(const GlPlanes& planes, const render::QuiltGeometry& geometry,
                    const render::ReferenceCamera& ref, const render::QuiltLayout& layout,
                    render::PlaneFilter filter, const glm::vec3& background, const Texture& quilt) {
  if (quilt.width() != layout.width || quilt.height() != layout.height || quilt.layers() != 0)
    throw std::logic_error("GlSwizzle: the quilt texture does not have the layout's size");
  const int V = geometry.views;
  if (V > layout.cols * layout.rows) throw std::logic_error("GlSwizzle: more views than tiles");
  // dx_j as the CPU computes them (std::tan), so both sample the same plane positions.
  std::vector<float> offsets(static_cast<size_t>(V));
  for (int j = 0; j < V; ++j) offsets[size_t(j)] = geometry.view_offset(j);
  view_offsets_.ensure(offsets.size() * sizeof(float));
  view_offsets_.upload(offsets.data(), offsets.size() * sizeof(float));
  if (options_.factor_table) write_table(planes, geometry, ref);

  const Program& p = program(filter, quilt.internal_format());
  p.use();
  p.bind("planes", planes.texels);
  const bool sampled = options_.hardware_bilinear && filter == render::PlaneFilter::kBilinear;
  glBindSampler(kSwizzlePlanesUnit, sampled ? linear_.id() : 0);
  p.bind("quilt", quilt);
  p.bind("plane_table", planes.table.buffer);
  if (options_.factor_table) {
    p.bind("plane_factors", plane_factors_);
    p.bind("view_plane_columns", view_plane_columns_);
  } else {
    p.bind("view_offsets", view_offsets_);
  }
  const int W = geometry.base.width, H = geometry.base.height;
  glUniform2i(p.uniform("view_size"), W, H);
  glUniform2i(p.uniform("plane_size"), planes.width, planes.height);
  glUniform3i(p.uniform("tiles"), layout.cols, layout.tile_width(), layout.tile_height());
  if (!options_.factor_table) {  // with the table, the table pass used the cameras
    set_camera_uniforms(p, geometry, ref);
  }
  glUniform3f(p.uniform("background"), background.x, background.y, background.z);
  glUniform1i(p.uniform("view_count"), V);
  const int view_groups = (V + options_.views_per_invocation - 1) / options_.views_per_invocation;
  p.dispatch((GLuint(W) + kSwizzleGroupWidth - 1) / kSwizzleGroupWidth,
             (GLuint(H) + kSwizzleGroupHeight - 1) / kSwizzleGroupHeight, GLuint(view_groups));
  glBindSampler(kSwizzlePlanesUnit, 0);
  // The quilt is read next by texture fetches (interlacing) or a read-back.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  check_gl("the G2LF swizzle pass");
}

Texture make_quilt_texture(const render::QuiltLayout& layout, GLenum internal_format) {
  Texture quilt(internal_format, layout.width, layout.height);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(quilt.id(), 0, GL_RGBA, GL_FLOAT, zero);
  check_gl("clearing the quilt texture");
  return quilt;
}

}  // namespace lfd::gpu
