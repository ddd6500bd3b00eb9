#include "scene/ply_header.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "util/error.hpp"

namespace lfd::scene {

namespace {

// The longest header we accept; a real 3DGS header with SH degree 3 is about 1.5 kB.
constexpr size_t kMaxHeaderBytes = 1 << 20;

std::optional<PlyType> parse_type(std::string_view t) {
  if (t == "char" || t == "int8") return PlyType::Int8;
  if (t == "uchar" || t == "uint8") return PlyType::UInt8;
  if (t == "short" || t == "int16") return PlyType::Int16;
  if (t == "ushort" || t == "uint16") return PlyType::UInt16;
  if (t == "int" || t == "int32") return PlyType::Int32;
  if (t == "uint" || t == "uint32") return PlyType::UInt32;
  if (t == "float" || t == "float32") return PlyType::Float32;
  if (t == "double" || t == "float64") return PlyType::Float64;
  return std::nullopt;
}

size_t type_size(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 4;
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

template <typename T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;  // little-endian host assumed (x86-64 / aarch64), as every 3DGS tool does
}

// ASCII values of integer properties must be integers the type can hold, so that
// value() always returns what a binary file could have stored.
bool in_range(PlyType t, double v) {
  auto integer_within = [v](double lo, double hi) {
    return v >= lo && v <= hi && std::floor(v) == v;
  };
  switch (t) {
    case PlyType::Int8: return integer_within(-128, 127);
    case PlyType::UInt8: return integer_within(0, 255);
    case PlyType::Int16: return integer_within(-32768, 32767);
    case PlyType::UInt16: return integer_within(0, 65535);
    case PlyType::Int32: return integer_within(-2147483648.0, 2147483647.0);
    case PlyType::UInt32: return integer_within(0, 4294967295.0);
    case PlyType::Float32:
    case PlyType::Float64: return true;
  }
  return true;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// Parses ASCII rows of `element` starting at `pos`, advancing it.
void parse_ascii_rows(std::string_view bytes, size_t& pos, PlyElement& element,
                      const std::string& name) {
  const size_t per_row = element.properties.size();
  // Every value needs at least one character and one separator, so a count the remaining
  // bytes cannot hold is rejected before the allocation.
  const size_t remaining = bytes.size() - pos;
  if (per_row > 0 && element.count > (remaining + 1) / (2 * per_row))
    throw_input_error("{}: element '{}' claims {} rows but the file has only {} bytes left",
                      name, element.name, element.count, remaining);
  element.ascii_values.resize(element.count * per_row);
  for (size_t row = 0; row < element.count; ++row) {
    for (size_t p = 0; p < per_row; ++p) {
      while (pos < bytes.size() && is_space(bytes[pos])) ++pos;
      if (pos >= bytes.size())
        throw_input_error("{}: truncated: element '{}' ends at row {} of {}", name, element.name,
                          row, element.count);
      size_t end = pos;
      while (end < bytes.size() && !is_space(bytes[end])) ++end;
      const std::string_view word = bytes.substr(pos, end - pos);
      double v = 0;
      const auto res = std::from_chars(word.data(), word.data() + word.size(), v);
      if (res.ec != std::errc() || res.ptr != word.data() + word.size())
        throw_input_error("{}: element '{}' row {}: '{}' is not a number", name, element.name,
                          row, word.substr(0, 32));
      if (!in_range(element.properties[p].type, v))
        throw_input_error("{}: element '{}' row {}: {} does not fit property '{}'", name,
                          element.name, row, word.substr(0, 32), element.properties[p].name);
      element.ascii_values[row * per_row + p] = v;
      pos = end;
    }
  }
}

}  // namespace

int PlyElement::find(std::string_view property_name) const {
  for (size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == property_name) return int(i);
  return -1;
}

double PlyElement::value(size_t row, int property) const {
  if (!rows) return ascii_values[row * properties.size() + size_t(property)];
  const PlyProperty& p = properties[size_t(property)];
  const unsigned char* at = rows + row * stride_bytes + p.offset_bytes;
  switch (p.type) {
    case PlyType::Int8: return load<int8_t>(at);
    case PlyType::UInt8: return load<uint8_t>(at);
    case PlyType::Int16: return load<int16_t>(at);
    case PlyType::UInt16: return load<uint16_t>(at);
    case PlyType::Int32: return load<int32_t>(at);
    case PlyType::UInt32: return load<uint32_t>(at);
    case PlyType::Float32: return load<float>(at);
    case PlyType::Float64: return load<double>(at);
  }
  return 0.0;
}

float PlyElement::value_float(size_t row, int property) const {
  const double v = value(row, property);
  constexpr double kMax = std::numeric_limits<float>::max();
  if (v > kMax) return std::numeric_limits<float>::infinity();
  if (v < -kMax) return -std::numeric_limits<float>::infinity();
  return float(v);  // NaN stays NaN
}

const PlyElement* PlyFile::find(std::string_view element_name) const {
  for (const auto& e : elements)
    if (e.name == element_name) return &e;
  return nullptr;
}

bool looks_like_ply(std::string_view bytes) {
  return bytes.size() >= 4 && bytes.substr(0, 3) == "ply" &&
         (bytes[3] == '\n' || bytes[3] == '\r');
}

PlyFile parse_ply(std::string_view bytes, const std::string& name) {
  if (!looks_like_ply(bytes)) throw_input_error("{}: not a PLY file (no 'ply' magic line)", name);
  const std::string_view marker = "end_header";
  const size_t end_at = bytes.substr(0, std::min(bytes.size(), kMaxHeaderBytes)).find(marker);
  if (end_at == std::string_view::npos)
    throw_input_error("{}: PLY header has no 'end_header' within {} bytes", name,
                      std::min(bytes.size(), kMaxHeaderBytes));
  size_t data_start = end_at + marker.size();
  if (data_start < bytes.size() && bytes[data_start] == '\r') ++data_start;
  if (data_start >= bytes.size() || bytes[data_start] != '\n') {
    if (data_start < bytes.size())
      throw_input_error("{}: PLY 'end_header' is not followed by a newline", name);
  } else {
    ++data_start;
  }

  PlyFile file;
  bool have_format = false;
  const std::string_view header = bytes.substr(0, end_at);
  size_t line_start = 0;
  int line_number = 0;
  while (line_start < header.size()) {
    size_t line_end = header.find('\n', line_start);
    if (line_end == std::string_view::npos) line_end = header.size();
    const std::string_view line = header.substr(line_start, line_end - line_start);
    line_start = line_end + 1;
    ++line_number;
    const auto words = split_words(line);
    if (words.empty() || line_number == 1) continue;  // line 1 is the magic
    const std::string_view key = words[0];
    if (key == "comment" || key == "obj_info") {
      file.comments.emplace_back(line.substr(std::min(line.size(), key.size() + 1)));
    } else if (key == "format") {
      if (words.size() < 3)
        throw_input_error("{}: PLY header line {}: malformed format line", name, line_number);
      if (words[1] == "ascii") {
        file.ascii = true;
      } else if (words[1] != "binary_little_endian") {
        throw_input_error("{}: PLY format '{}' is not supported (binary_little_endian or ascii)",
                          name, words[1]);
      }
      have_format = true;
    } else if (key == "element") {
      if (words.size() != 3)
        throw_input_error("{}: PLY header line {}: malformed element line", name, line_number);
      PlyElement e;
      e.name = std::string(words[1]);
      uint64_t count = 0;
      const auto res = std::from_chars(words[2].data(), words[2].data() + words[2].size(), count);
      if (res.ec != std::errc() || res.ptr != words[2].data() + words[2].size())
        throw_input_error("{}: PLY element '{}' has an invalid count '{}'", name, e.name,
                          words[2]);
      e.count = size_t(count);
      file.elements.push_back(std::move(e));
    } else if (key == "property") {
      if (file.elements.empty())
        throw_input_error("{}: PLY header line {}: property before any element", name,
                          line_number);
      if (words.size() >= 2 && words[1] == "list")
        throw_input_error("{}: PLY list properties are not supported (element '{}')", name,
                          file.elements.back().name);
      if (words.size() != 3)
        throw_input_error("{}: PLY header line {}: malformed property line", name, line_number);
      const auto type = parse_type(words[1]);
      if (!type)
        throw_input_error("{}: PLY property '{}' has unknown type '{}'", name, words[2],
                          words[1]);
      PlyElement& e = file.elements.back();
      if (e.find(words[2]) >= 0)
        throw_input_error("{}: PLY property '{}' appears twice in element '{}'", name, words[2],
                          e.name);
      e.properties.push_back({std::string(words[2]), *type, e.stride_bytes});
      e.stride_bytes += type_size(*type);
    } else {
      throw_input_error("{}: PLY header line {}: unknown keyword '{}'", name, line_number,
                        key.substr(0, 32));
    }
  }
  if (!have_format) throw_input_error("{}: PLY header has no format line", name);

  size_t pos = data_start;
  for (PlyElement& e : file.elements) {
    // Rows without properties occupy no bytes, so nothing bounds their count: reject them
    // (found by fuzzing: an ASCII "element x 10^18" with no properties looped for minutes).
    if (e.properties.empty() && e.count > 0)
      throw_input_error("{}: PLY element '{}' has {} rows but no properties", name, e.name,
                        e.count);
    if (file.ascii) {
      parse_ascii_rows(bytes, pos, e, name);
      continue;
    }
    const size_t remaining = bytes.size() - pos;
    if (e.stride_bytes > 0 && e.count > remaining / e.stride_bytes)
      throw_input_error(
          "{}: truncated: element '{}' needs {} rows of {} bytes but only {} bytes remain", name,
          e.name, e.count, e.stride_bytes, remaining);
    e.rows = reinterpret_cast<const unsigned char*>(bytes.data()) + pos;
    pos += e.count * e.stride_bytes;
  }
  return file;
}

}  // namespace lfd::scene
