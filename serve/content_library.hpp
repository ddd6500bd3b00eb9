#pragma once
// The service's content folder as the console's library (docs/console.md, "Content"): the
// files it holds, each probed from its bytes (a quilt image, a quilt video, an RGB-D photo) with
// the layout its `_qs` name gives; uploads stored under a name the service makes, written
// atomically; renames and deletes of the files it lists. No path from a request is ever opened:
// a request names an item, which must be a plain file name of the folder. Thread-safe.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "serve/library_file_name.hpp"

namespace lfd::serve {

struct LibraryItem {
  std::string name;             // the file's name in the folder
  std::filesystem::path path;   // folder / name
  std::string kind;             // "quilt", "quilt video", "rgbd photo"
  std::size_t bytes = 0;
  int width = 0, height = 0;
  int cols = 0, rows = 0, views = 0;  // the tiling (quilts)
  double aspect = 0;
};

nlohmann::json library_item_json(const LibraryItem& item);

class ContentLibrary {
 public:
  // `display_aspect`: the aspect of quilts that do not say theirs (the first display's).
  ContentLibrary(std::filesystem::path folder, std::size_t max_upload_bytes, double display_aspect);
  const std::filesystem::path& folder() const { return folder_; }
  std::size_t max_upload_bytes() const { return max_upload_bytes_; }

  std::vector<LibraryItem> items() const;
  // The item called `name`; InputError when the name is not a plain file name of the folder.
  LibraryItem item(const std::string& name) const;

  // An upload called `client_name`, its bytes read by `read` (which calls the sink per chunk
  // and returns false when the transfer failed). Refused with InputError, nothing left in the
  // folder: a name that is not a plain file name, over the size limit, content that is not a
  // quilt image, quilt video or RGB-D photo. Stored as the name made of `client_name` (letters,
  // digits, '.', '_', '-'; the extension of the probed type), never over an existing file.
  LibraryItem upload(const std::string& client_name,
                     const std::function<bool(const std::function<bool(const char*, std::size_t)>&)>& read);
  LibraryItem rename(const std::string& name, const std::string& new_name);
  void remove(const std::string& name);

 private:
  std::optional<LibraryItem> probe(const std::filesystem::path& path, const std::string& name, std::string* why) const;

  std::filesystem::path folder_;
  std::size_t max_upload_bytes_;
  double display_aspect_;
  mutable std::mutex mutex_;
};


}  // namespace lfd::serve
