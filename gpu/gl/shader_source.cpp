#include "gpu/gl/shader_source.hpp"

#include <algorithm>
#include <cctype>
#include <regex>
#include <sstream>

namespace lfd::gpu {
namespace {

constexpr std::string_view kFilesTag = "//! files: ";

std::string without_comments(std::string_view source) {
  std::string out;
  out.reserve(source.size());
  for (size_t i = 0; i < source.size(); ++i) {
    if (source.compare(i, 2, "//") == 0) {
      while (i < source.size() && source[i] != '\n') ++i;
      out += '\n';
    } else if (source.compare(i, 2, "/*") == 0) {
      const size_t end = source.find("*/", i + 2);
      i = end == std::string_view::npos ? source.size() : end + 1;
      out += ' ';
    } else {
      out += source[i];
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> shader_files(std::string_view source) {
  if (source.substr(0, kFilesTag.size()) != kFilesTag) return {};
  const size_t end = source.find('\n');
  std::istringstream names(std::string(source.substr(kFilesTag.size(), end - kFilesTag.size())));
  std::vector<std::string> files;
  for (std::string name; names >> name;) files.push_back(name);
  return files;
}

std::string name_files_in_log(const std::string& log, const std::vector<std::string>& files) {
  if (files.empty()) return log;
  // Mesa: "3:12(5): error: ..."; NVIDIA: "3(12) : error C1008: ...". At a line's start.
  static const std::regex location(R"((^|\n)(\d+)(?::(\d+)\((\d+)\)|\((\d+)\)))");
  std::string out;
  auto begin = log.cbegin();
  for (std::sregex_iterator it(log.begin(), log.end(), location), end; it != end; ++it) {
    const std::smatch& m = *it;
    out.append(begin, m[0].first);
    const size_t number = std::stoul(m[2].str());
    if (number >= files.size()) {
      out += m[0].str();
    } else {
      const std::string line = m[3].matched ? m[3].str() : m[5].str();
      out += m[1].str() + files[number] + ":" + line + (m[4].matched ? "(" + m[4].str() + ")" : "");
    }
    begin = m[0].second;
  }
  out.append(begin, log.cend());
  return out;
}

std::vector<std::string> declared_uniforms(std::string_view source) {
  const std::string text = without_comments(source);
  // `uniform [precision] TYPE NAME[, NAME...]` ended by ';' — a block (`uniform NAME {`) has no
  // second identifier before its brace and does not match.
  static const std::regex declaration(R"(\buniform\s+(?:(?:lowp|mediump|highp)\s+)?\w+\s+([^;{}]+);)");
  static const std::regex name(R"((?:^|,)\s*(\w+))");
  std::vector<std::string> names;
  for (std::sregex_iterator it(text.begin(), text.end(), declaration), end; it != end; ++it) {
    const std::string list = (*it)[1].str();
    for (std::sregex_iterator n(list.begin(), list.end(), name); n != end; ++n) names.push_back((*n)[1].str());
  }
  return names;
}

std::string glsl_version_header(bool es) {
  if (!es) return "#version 450 core\n";
  return "#version 310 es\n"
         "#if defined(GL_EXT_gpu_shader5)\n"
         "#extension GL_EXT_gpu_shader5 : enable\n"
         "#else\n"
         "#define precise\n"
         "#endif\n"
         "precision highp float;\n"
         "precision highp int;\n"
         "precision highp sampler2D;\n"
         "precision highp sampler2DArray;\n"
         "precision highp sampler3D;\n"
         "precision highp isampler2D;\n"
         "precision highp usampler2D;\n"
         "precision highp image2D;\n"
         "precision highp iimage2D;\n"
         "precision highp uimage2D;\n"
         "precision highp image2DArray;\n";
}

namespace {

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// `LFD_IO_INT(name, value) // ...` -> `#define name value // ...`; other lines unchanged.
std::string contract_line_as_define(const std::string& line) {
  size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos) return line;
  std::string_view rest(line);
  rest.remove_prefix(i);
  size_t open = 0;
  if (rest.substr(0, 11) == "LFD_IO_INT(") open = 10;
  else if (rest.substr(0, 12) == "LFD_IO_UINT(") open = 11;
  else return line;
  const size_t comma = rest.find(',', open);
  if (comma == std::string_view::npos) return line;
  int depth = 1;
  size_t close = comma;
  while (++close < rest.size() && depth > 0) {
    if (rest[close] == '(') ++depth;
    if (rest[close] == ')') --depth;
  }
  if (depth != 0) return line;
  --close;  // the closing parenthesis
  auto trim = [](std::string_view t) {
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.remove_prefix(1);
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.remove_suffix(1);
    return std::string(t);
  };
  const std::string name = trim(rest.substr(open + 1, comma - open - 1));
  const std::string value = trim(rest.substr(comma + 1, close - comma - 1));
  const bool literal = std::all_of(value.begin(), value.end(), word_char);
  return "#define " + name + " " + (literal ? value : "(" + value + ")") + std::string(rest.substr(close + 1));
}

}  // namespace

std::string glsl_es_source(std::string_view source) {
  // Pass 1: the contracts' constants as macros, line by line.
  std::string text;
  text.reserve(source.size());
  for (size_t start = 0; start < source.size();) {
    size_t end = source.find('\n', start);
    if (end == std::string_view::npos) end = source.size();
    text += contract_line_as_define(std::string(source.substr(start, end - start)));
    if (end < source.size()) text += '\n';
    start = end + 1;
  }
  // Pass 2: `const` inside function bodies (brace depth > 0), outside comments.
  std::string out;
  out.reserve(text.size());
  int depth = 0;
  for (size_t i = 0; i < text.size();) {
    if (text.compare(i, 2, "//") == 0) {
      const size_t end = std::min(text.find('\n', i), text.size());  // npos: the end
      out.append(text, i, end - i);
      i = end;
    } else if (text.compare(i, 2, "/*") == 0) {
      const size_t close = text.find("*/", i + 2);
      const size_t end = close == std::string::npos ? text.size() : close + 2;
      out.append(text, i, end - i);
      i = end;
    } else if (text[i] == '{' || text[i] == '}') {
      depth += text[i] == '{' ? 1 : -1;
      out += text[i++];
    } else if (depth > 0 && text.compare(i, 5, "const") == 0 && (i == 0 || !word_char(text[i - 1])) &&
               (i + 5 >= text.size() || !word_char(text[i + 5]))) {
      i += 5;
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    } else {
      out += text[i++];
    }
  }
  return out;
}

}  // namespace lfd::gpu
