#include "gpu/gl/shader_dump.hpp"

#include <unistd.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

namespace lfd::gpu {
namespace {

const char* stage_extension(GLenum stage) {
  switch (stage) {
    case GL_COMPUTE_SHADER: return "comp";
    case GL_VERTEX_SHADER: return "vert";
    case GL_FRAGMENT_SHADER: return "frag";
    case GL_GEOMETRY_SHADER: return "geom";
    default: return "glsl";
  }
}

// FNV-1a: a stable name for a text (the same variant from two processes is one file).
uint64_t text_hash(std::string_view text) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::string file_label(std::string_view label) {
  std::string out;
  for (char c : label) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '_') ? c : '_';
  return out.empty() ? "program" : out;
}

}  // namespace

void dump_shader_variant(std::string_view label, GLenum stage, const std::string& header, const char* source) {
  static const char* dir = std::getenv("LFD_SHADER_DUMP");
  if (dir == nullptr || *dir == '\0') return;
  // Only embedded shaders (their first line lists their files): a caller's own test source is
  // not one of the program's variants.
  if (std::string_view(source).rfind("//! files:", 0) != 0) return;
  const std::string text = header + source;
  const std::filesystem::path path = std::filesystem::path(dir) / fmt::format(
      "{}-{:016x}.{}", file_label(label), text_hash(text), stage_extension(stage));
  std::error_code error;
  if (std::filesystem::exists(path, error)) return;
  std::filesystem::create_directories(dir, error);
  const std::filesystem::path partial = path.string() + fmt::format(".{}.tmp", ::getpid());
  {
    std::ofstream out(partial, std::ios::binary);
    out << text;
    if (!out) {
      static bool reported = false;
      if (!reported) std::fprintf(stderr, "LFD_SHADER_DUMP: cannot write %s\n", partial.c_str());
      reported = true;
      return;
    }
  }
  std::filesystem::rename(partial, path, error);
}

}  // namespace lfd::gpu
