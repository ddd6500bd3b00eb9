#include "scene/scene_sequence.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "util/error.hpp"

namespace lfd::scene {
namespace {

namespace fs = std::filesystem;

// A printf number in a file name: "%d" or "%0Nd" (N < 10).
struct Pattern {
  std::string prefix, suffix;
  int width = 0;  // 0: any number of digits
};

std::optional<Pattern> parse_pattern(const std::string& name) {
  const size_t at = name.find('%');
  if (at == std::string::npos) return std::nullopt;
  Pattern p;
  p.prefix = name.substr(0, at);
  size_t i = at + 1;
  if (i + 1 < name.size() && name[i] == '0' && std::isdigit(static_cast<unsigned char>(name[i + 1]))) {
    p.width = name[i + 1] - '0';
    i += 2;
  }
  if (i >= name.size() || name[i] != 'd') return std::nullopt;
  p.suffix = name.substr(i + 1);
  return p;
}

// The frame number a file name gives under the pattern, if it matches.
std::optional<long> number_of(const std::string& name, const Pattern& p) {
  if (name.size() <= p.prefix.size() + p.suffix.size() || !name.starts_with(p.prefix) || !name.ends_with(p.suffix))
    return std::nullopt;
  const std::string digits = name.substr(p.prefix.size(), name.size() - p.prefix.size() - p.suffix.size());
  if (digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    return std::nullopt;
  if (p.width > 0 && int(digits.size()) != p.width) return std::nullopt;
  return std::stol(digits);
}

SceneSequence from_pattern(const std::string& spec, const Pattern& p) {
  const fs::path folder = fs::path(spec).parent_path().empty() ? fs::path(".") : fs::path(spec).parent_path();
  if (!fs::is_directory(folder)) throw_input_error("{}: no folder '{}'", spec, folder.string());
  std::map<long, fs::path> found;
  for (const auto& e : fs::directory_iterator(folder))
    if (const auto n = number_of(e.path().filename().string(), p); n && e.is_regular_file()) {
      if (const auto [it, added] = found.emplace(*n, e.path()); !added)
        throw_input_error("{}: two files are frame {} ({}, {})", spec, *n, it->second.filename().string(),
                          e.path().filename().string());
    }
  if (found.empty()) throw_input_error("{}: no frame matches the pattern", spec);
  SceneSequence s{spec, {}};
  const long first = found.begin()->first, last = found.rbegin()->first;
  for (long n = first; n <= last; ++n) {
    const auto it = found.find(n);
    if (it == found.end())
      throw_input_error("{}: frame {} ({}) is missing (frames {}..{} present)", spec, n,
                        fmt::format("{}{:0{}d}{}", p.prefix, n, std::max(p.width, 1), p.suffix), first, last);
    s.frames.push_back(it->second);
  }
  return s;
}

SceneSequence from_folder(const std::string& spec) {
  SceneSequence s{spec, {}};
  for (const auto& e : fs::directory_iterator(spec))
    if (e.is_regular_file() && !e.path().filename().string().starts_with(".")) s.frames.push_back(e.path());
  std::sort(s.frames.begin(), s.frames.end());
  if (s.frames.empty()) throw_input_error("{}: the folder holds no frame", spec);
  return s;
}

SceneSequence from_list(const std::string& spec) {
  std::ifstream in(spec);
  if (!in) throw_input_error("{}: cannot open the frame list", spec);
  SceneSequence s{spec, {}};
  const fs::path folder = fs::path(spec).parent_path();
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    if (line.empty() || line.starts_with("#")) continue;
    const fs::path frame = fs::path(line).is_absolute() ? fs::path(line) : folder / line;
    if (!fs::is_regular_file(frame)) throw_input_error("{}: line {}: '{}' not found", spec, number, frame.string());
    s.frames.push_back(frame);
  }
  if (s.frames.empty()) throw_input_error("{}: the frame list is empty", spec);
  return s;
}

}  // namespace

bool is_scene_sequence(const std::string& spec) {
  return parse_pattern(fs::path(spec).filename().string()).has_value() || fs::is_directory(spec) ||
         fs::path(spec).extension() == ".txt";
}

SceneSequence find_scene_sequence(const std::string& spec) {
  if (const auto p = parse_pattern(fs::path(spec).filename().string())) return from_pattern(spec, *p);
  if (fs::is_directory(spec)) return from_folder(spec);
  if (fs::path(spec).extension() == ".txt") return from_list(spec);
  return SceneSequence{spec, {fs::path(spec)}};
}

}  // namespace lfd::scene
