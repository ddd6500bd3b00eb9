#include "gpu/gl/shader_source.hpp"

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

}  // namespace lfd::gpu
