#include "play/playlist.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "media/quilt_name.hpp"
#include "util/error.hpp"

namespace lfd::play {
namespace {

using nlohmann::json;

int read_count(const json& v, const std::string& where, int max) {
  if (!v.is_number_integer() || v.get<int64_t>() < 1 || v.get<int64_t>() > max)
    throw_input_error("{}: must be an integer from 1 to {}", where, max);
  return v.get<int>();
}

double read_positive(const json& v, const std::string& where, double max) {
  if (!v.is_number()) throw_input_error("{}: must be a number", where);
  const double x = v.get<double>();
  if (!std::isfinite(x) || x <= 0 || x > max) throw_input_error("{}: must be in (0, {}]", where, max);
  return x;
}

PlaylistEntry parse_entry(const json& e, const std::string& where, const std::filesystem::path& base) {
  if (!e.is_object()) throw_input_error("{}: must be an object with a \"file\"", where);
  PlaylistEntry entry;
  for (const auto& [key, value] : e.items()) {
    const std::string field = where + "." + key;
    if (key == "file") {
      if (!value.is_string() || value.get<std::string>().empty()) throw_input_error("{}: must be a file name", field);
      const std::filesystem::path file = value.get<std::string>();
      entry.path = file.is_absolute() ? file : base / file;
    } else if (key == "duration") {
      entry.duration_s = read_positive(value, field, 1e7);
    } else if (key == "cols") {
      entry.quilt.cols = read_count(value, field, media::kMaxQuiltTilesPerAxis);
    } else if (key == "rows") {
      entry.quilt.rows = read_count(value, field, media::kMaxQuiltTilesPerAxis);
    } else if (key == "views") {
      entry.quilt.views = read_count(value, field, media::kMaxQuiltViews);
    } else if (key == "aspect") {
      entry.quilt.aspect = read_positive(value, field, media::kMaxQuiltAspect);
    } else {
      throw_input_error("{}: unknown field (file, duration, cols, rows, views, aspect)", field);
    }
  }
  if (entry.path.empty()) throw_input_error("{}.file: missing", where);
  return entry;
}

}  // namespace

Playlist parse_playlist_json(const std::string& text, const std::string& name, const std::filesystem::path& base) {
  const json doc = json::parse(text, nullptr, false);
  if (doc.is_discarded()) throw_input_error("{}: not valid JSON", name);
  const json* entries = &doc;
  Playlist playlist;
  if (doc.is_object()) {
    for (const auto& [key, value] : doc.items())
      if (key != "entries" && key != "loop") throw_input_error("{}: {}: unknown field (entries, loop)", name, key);
    if (!doc.contains("entries")) throw_input_error("{}: entries: missing", name);
    entries = &doc["entries"];
    if (doc.contains("loop")) {
      if (!doc["loop"].is_boolean()) throw_input_error("{}: loop: must be true or false", name);
      playlist.loop = doc["loop"].get<bool>();
    }
  }
  if (!entries->is_array()) throw_input_error("{}: entries: must be an array", name);
  if (entries->empty()) throw_input_error("{}: entries: empty", name);
  if (entries->size() > kMaxPlaylistEntries)
    throw_input_error("{}: entries: more than {}", name, kMaxPlaylistEntries);
  for (size_t i = 0; i < entries->size(); ++i)
    playlist.entries.push_back(parse_entry((*entries)[i], fmt::format("{}: entries[{}]", name, i), base));
  return playlist;
}

Playlist read_playlist_json(const std::filesystem::path& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw_input_error("{}: cannot read ({})", path.string(), ec.message());
  if (size > kMaxPlaylistBytes) throw_input_error("{}: larger than {} bytes", path.string(), kMaxPlaylistBytes);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return parse_playlist_json(text.str(), path.string(), path.parent_path());
}

bool is_playlist_file(const std::filesystem::path& path) { return path.extension() == ".json"; }

}  // namespace lfd::play
