#pragma once
// A minimal PLY container reader shared by the standard and compressed 3DGS loaders: parses the
// header, then exposes each element's rows by property NAME (files in the wild add, drop and
// reorder properties: never rely on offsets). Binary little-endian rows are read in place; ASCII
// rows are parsed into doubles. Counts are checked against the bytes present before anything is
// allocated, so a header claiming billions of rows fails fast instead of exhausting memory.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lfd::scene {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;
  size_t offset_bytes = 0;  // within a binary row
};

struct PlyElement {
  std::string name;
  size_t count = 0;
  std::vector<PlyProperty> properties;
  size_t stride_bytes = 0;            // binary row size
  const unsigned char* rows = nullptr;  // binary: first row (points into the file's bytes)
  std::vector<double> ascii_values;     // ASCII: count * properties.size(), row-major

  // Index of the property called `name`, or -1.
  int find(std::string_view property_name) const;
  PlyType type_of(int property) const { return properties[size_t(property)].type; }
  double value(size_t row, int property) const;
  // value() as a float; magnitudes beyond float range become +-inf (not UB), so the loaders'
  // finiteness check reports them.
  float value_float(size_t row, int property) const;
};

struct PlyFile {
  bool ascii = false;
  std::vector<std::string> comments;
  std::vector<PlyElement> elements;

  const PlyElement* find(std::string_view element_name) const;
};

// Parses a whole PLY file held in memory; `bytes` must outlive the result (binary rows point
// into it). Throws InputError("<name>: ...") for anything malformed, truncated or unsupported
// (big-endian, list properties, unknown types).
PlyFile parse_ply(std::string_view bytes, const std::string& name);

// True if `bytes` starts like a PLY file.
bool looks_like_ply(std::string_view bytes);

}  // namespace lfd::scene
