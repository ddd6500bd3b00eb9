#include "gpu/gl/gl_limits.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <string>

#include <epoxy/gl.h>

#include "util/error.hpp"

namespace lfd::gpu {

GlLimits lower_gl_limits(GlLimits limits, std::string_view lowered) {
  while (!lowered.empty()) {
    const size_t comma = lowered.find(',');
    const std::string_view item = lowered.substr(0, comma);
    lowered = comma == std::string_view::npos ? std::string_view() : lowered.substr(comma + 1);
    if (item.empty()) continue;
    const size_t equals = item.find('=');
    const std::string_view name = item.substr(0, equals);
    long long value = -1;
    const std::string_view number = equals == std::string_view::npos ? std::string_view() : item.substr(equals + 1);
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (number.empty() || error != std::errc() || end != number.data() + number.size() || value <= 0)
      throw_input_error("LFD_GL_LIMITS: '{}' is not NAME=POSITIVE_INTEGER", item);
    const auto lower = [&](auto& field) { field = std::min<std::decay_t<decltype(field)>>(field, value); };
    if (name == "storage") lower(limits.storage_block_bytes);
    else if (name == "shared") lower(limits.shared_bytes);
    else if (name == "invocations") lower(limits.invocations);
    else if (name == "groups") lower(limits.work_groups_x);
    else if (name == "texture") lower(limits.texture_size);
    else if (name == "layers") lower(limits.array_layers);
    else throw_input_error("LFD_GL_LIMITS: '{}' is not storage, shared, invocations, groups, texture or layers", name);
  }
  return limits;
}

GlLimits gl_limits() {
  GlLimits limits;
  GLint64 storage = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &storage);
  limits.storage_block_bytes = storage;
  glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &limits.shared_bytes);
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &limits.invocations);
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &limits.work_groups_x);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &limits.texture_size);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &limits.array_layers);
  const char* lowered = std::getenv("LFD_GL_LIMITS");
  return lowered ? lower_gl_limits(limits, lowered) : limits;
}

}  // namespace lfd::gpu
