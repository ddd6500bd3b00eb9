// The console's content library (docs/console.md, "Content").
#include "serve/content_library.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <random>

#include <fmt/format.h>

#include "media/quilt_image.hpp"
#include "media/quilt_name.hpp"
#include "interlace/quilt_file.hpp"
#include "media/video_decoder.hpp"
#include "serve/library_file_name.hpp"
#include "serve/studio_playlist.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::serve {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kHeaderBytes = 1u << 20;  // what an image's size is read from

std::vector<uint8_t> file_head(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> head(kHeaderBytes);
  in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return head;
}

std::string extension_of(media::ImageFormat format) {
  switch (format) {
    case media::ImageFormat::kPng: return ".png";
    case media::ImageFormat::kJpeg: return ".jpg";
    case media::ImageFormat::kWebp: return ".webp";
    case media::ImageFormat::kUnknown: break;
  }
  return "";
}

std::string video_extension(const std::string& container) {
  if (container.find("webm") != std::string::npos || container.find("matroska") != std::string::npos) return ".webm";
  return ".mp4";
}

// `name` with its extension replaced by `extension`.
// An extension is a dot and 1 to 5 characters with a letter among them (".75" of "_qs4x3a0.75"
// is not one).
std::string with_extension(const std::string& name, const std::string& extension) {
  const std::size_t dot = name.rfind('.');
  const std::string_view ext = dot == std::string::npos ? std::string_view() : std::string_view(name).substr(dot + 1);
  const bool has_ext = dot != std::string::npos && dot > 0 && !ext.empty() && ext.size() <= 5 &&
                       std::any_of(ext.begin(), ext.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)); });
  return (has_ext ? name.substr(0, dot) : name) + extension;
}

// rename(2) that never replaces: link then unlink (the same folder, one file system).
bool rename_no_replace(const fs::path& from, const fs::path& to) {
  if (::link(from.c_str(), to.c_str()) != 0) return false;
  ::unlink(from.c_str());
  return true;
}

fs::path sidecar_path(const fs::path& file) {
  fs::path sidecar = file;
  sidecar += ".json";
  return sidecar;
}

// A Looking Glass Studio sidecar beside the file, `<name>.json` (docs/serve.md "Studio
// playlists"): the layout of a file whose name has no `_qs` tiling, or that it is an RGB-D photo.
// None when there is none; InputError naming the sidecar for one that is not a sidecar.
std::optional<PlaylistEntry> sidecar_of(const fs::path& file) {
  const fs::path sidecar = sidecar_path(file);
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(sidecar, ec))) return std::nullopt;  // no link out of the folder
  const auto bytes = fs::file_size(sidecar, ec);
  if (ec || bytes > kMaxStudioSidecarBytes)
    throw_input_error("{}: not a sidecar (more than {} bytes)", sidecar.filename().string(), kMaxStudioSidecarBytes);
  try {
    return parse_studio_sidecar(read_text_file(sidecar));
  } catch (const InputError& e) {
    throw_input_error("{}: {}", sidecar.filename().string(), e.what());
  }
}

// The tiling a sidecar gives a quilt (none for an RGB-D photo's).
interlace::QuiltOverrides overrides_of(const PlaylistEntry& sidecar) {
  interlace::QuiltOverrides o;
  o.cols = sidecar.quilt.cols;
  o.rows = sidecar.quilt.rows;
  o.views = sidecar.quilt.views;
  o.aspect = sidecar.quilt.aspect;
  return o;
}

bool is_sidecar_name(const std::string& name) { return name.size() > 5 && name.ends_with(".json"); }

}  // namespace

nlohmann::json library_item_json(const LibraryItem& i) {
  return {{"name", i.name}, {"uri", i.path.string()}, {"kind", i.kind}, {"bytes", i.bytes},
          {"width", i.width}, {"height", i.height}, {"cols", i.cols}, {"rows", i.rows},
          {"views", i.views}, {"aspect", i.aspect}};
}

ContentLibrary::ContentLibrary(fs::path folder, std::size_t max_upload_bytes, double display_aspect)
    : folder_(std::move(folder)), max_upload_bytes_(max_upload_bytes), display_aspect_(display_aspect) {
  std::error_code ec;
  fs::create_directories(folder_, ec);
}

std::optional<LibraryItem> ContentLibrary::probe(const fs::path& path, const std::string& name, std::string* why) const {
  LibraryItem item;
  item.name = name;
  item.path = path;
  std::error_code ec;
  item.bytes = static_cast<std::size_t>(fs::file_size(path, ec));
  try {
    const auto head = file_head(path);
    if (media::sniff_image_format(head) != media::ImageFormat::kUnknown) {
      const auto size = media::image_size(head, name);
      item.width = size.width;
      item.height = size.height;
      // The `_qs` name's tiling, else the Studio sidecar's; a picture with neither (or a sidecar
      // saying rgbd) is an RGB-D photo: colour and depth side by side.
      const auto sidecar = media::parse_quilt_name(name) ? std::nullopt : sidecar_of(path);
      if (media::parse_quilt_name(name) || (sidecar && !sidecar->rgbd)) {
        const auto q = media::quilt_layout_for(name, size.width, size.height,
                                               sidecar ? overrides_of(*sidecar) : interlace::QuiltOverrides{},
                                               display_aspect_);
        item.kind = "quilt";
        item.cols = q.cols, item.rows = q.rows, item.views = q.views, item.aspect = q.aspect;
      } else {
        item.kind = "rgbd photo";
      }
      return item;
    }
    media::VideoDecoder video(path, {.try_hardware = false, .threads = 1});
    item.width = video.info().width;
    item.height = video.info().height;
    const auto sidecar = media::parse_quilt_name(name) ? std::nullopt : sidecar_of(path);
    if (sidecar && sidecar->rgbd) throw_input_error("{}: an RGB-D video is not supported", name);
    const auto q = media::quilt_layout_for(name, item.width, item.height,
                                           sidecar ? overrides_of(*sidecar) : interlace::QuiltOverrides{},
                                           display_aspect_);
    item.kind = "quilt video";
    item.cols = q.cols, item.rows = q.rows, item.views = q.views, item.aspect = q.aspect;
    return item;
  } catch (const std::exception& e) {
    if (why) *why = e.what();
    return std::nullopt;
  }
}

std::vector<LibraryItem> ContentLibrary::items() const {
  std::lock_guard lock(mutex_);
  std::vector<LibraryItem> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder_, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.front() == '.' || !entry.is_regular_file(ec)) continue;  // uploads in flight
    if (is_sidecar_name(name)) continue;  // a Studio sidecar: its file's settings, not an item
    if (auto item = probe(entry.path(), name, nullptr)) out.push_back(std::move(*item));
  }
  std::sort(out.begin(), out.end(), [](const LibraryItem& a, const LibraryItem& b) { return a.name < b.name; });
  return out;
}

LibraryItem ContentLibrary::item(const std::string& name) const {
  if (library_file_name(name) != name) throw_input_error("name {}: not an item of the library", name);
  std::lock_guard lock(mutex_);
  const fs::path path = folder_ / name;
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(path, ec))) throw_input_error("name {}: not an item of the library", name);
  std::string why;
  auto item = probe(path, name, &why);
  if (!item) throw_input_error("{}: {}", name, why);
  return *item;
}

LibraryItem ContentLibrary::upload(const std::string& client_name,
                                   const std::function<bool(const std::function<bool(const char*, std::size_t)>&)>& read) {
  // A refusal still reads the body (discarding it): bytes left unread on a kept-alive connection
  // would be taken for the next request. cpp-httplib bounds what it reads (its payload limit).
  const auto refuse_unread = [&](const std::string& why) -> LibraryItem {
    read([](const char*, std::size_t) { return true; });
    throw InputError(why);
  };
  std::string base;
  try {
    base = library_file_name(client_name);
  } catch (const InputError& e) {
    return refuse_unread(e.what());
  }
  static thread_local std::mt19937_64 random{std::random_device{}()};
  const fs::path tmp = folder_ / fmt::format(".upload-{:016x}", random());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return refuse_unread(fmt::format("upload: cannot write in the content folder {}", folder_.string()));
  std::size_t total = 0;
  bool too_large = false, write_failed = false;
  const bool complete = read([&](const char* data, std::size_t n) {
    total += n;
    too_large = too_large || total > max_upload_bytes_;
    if (too_large || write_failed) return true;  // read on, written no more
    write_failed = ::write(fd, data, n) != static_cast<ssize_t>(n);
    return true;
  });
  const bool synced = ::fsync(fd) == 0;
  ::close(fd);
  const auto refuse = [&](const std::string& why) -> LibraryItem {
    ::unlink(tmp.c_str());
    throw InputError(why);
  };
  if (too_large) return refuse(fmt::format("{}: larger than the upload limit of {} MiB", base, max_upload_bytes_ >> 20));
  if (!complete || write_failed || !synced) return refuse(fmt::format("{}: the upload did not arrive whole", base));
  if (total == 0) return refuse(fmt::format("{}: empty", base));
  std::string why;
  auto probed = probe(tmp, base, &why);
  if (!probed) {
    // The reason names the file by the client's name, not the hidden temporary path.
    for (std::size_t at; (at = why.find(tmp.string())) != std::string::npos;) why.replace(at, tmp.string().size(), base);
    return refuse(fmt::format("{}: not a quilt image, quilt video or RGB-D photo ({})", base, why));
  }
  // The extension of what the bytes are, not of what the name said.
  const auto head = file_head(tmp);
  const auto format = media::sniff_image_format(head);
  const std::string ext = format != media::ImageFormat::kUnknown ? extension_of(format) : video_extension(
      media::VideoDecoder(tmp, {.try_hardware = false, .threads = 1}).info().container);
  std::lock_guard lock(mutex_);
  std::string name = with_extension(base, ext);
  for (int n = 2; !rename_no_replace(tmp, folder_ / name); ++n) {
    if (errno != EEXIST || n > 999) return refuse(fmt::format("{}: cannot store it in the content folder", base));
    name = with_extension(base, fmt::format("-{}{}", n, ext));
  }
  probed->name = name;
  probed->path = folder_ / name;
  return *probed;
}

LibraryItem ContentLibrary::rename(const std::string& name, const std::string& new_name) {
  const LibraryItem old = item(name);
  // The new name keeps the file's extension (its type was probed when it came in).
  const std::string target = with_extension(library_file_name(new_name), old.path.extension().string());
  if (target == name) return old;
  {
    std::lock_guard lock(mutex_);
    // The sidecar goes with its file (its settings are found by the file's name).
    std::error_code ec;
    const bool has_sidecar = fs::is_regular_file(sidecar_path(old.path), ec);
    if (has_sidecar && fs::exists(sidecar_path(folder_ / target), ec))
      throw_input_error("{}: cannot rename to {} (its sidecar's name is taken)", name, target);
    if (!rename_no_replace(old.path, folder_ / target))
      throw_input_error("{}: cannot rename to {} ({})", name, target, errno == EEXIST ? "that name is taken" : "the folder refused");
    if (has_sidecar) rename_no_replace(sidecar_path(old.path), sidecar_path(folder_ / target));
  }
  return item(target);
}

void ContentLibrary::remove(const std::string& name) {
  const LibraryItem old = item(name);
  std::lock_guard lock(mutex_);
  if (::unlink(old.path.c_str()) != 0) throw_input_error("{}: cannot delete it", name);
  ::unlink(sidecar_path(old.path).c_str());  // its Studio sidecar, if it has one
}

}  // namespace lfd::serve
