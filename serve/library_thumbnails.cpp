// The console's library thumbnails (docs/console.md, "Thumbnails").
#include "serve/library_thumbnails.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>

#include "media/quilt_image.hpp"
#include "media/video_decoder.hpp"
#include "media/yuv_frame.hpp"
#include "render/quilt_layout.hpp"
#include "util/error.hpp"
#include "util/png_codec.hpp"

namespace lfd::serve {

namespace fs = std::filesystem;

namespace {

// The part of `picture` at (x, y) of w x h.
Image8 crop(const Image8& picture, int x, int y, int w, int h) {
  Image8 out(w, h, picture.channels);
  for (int row = 0; row < h; ++row)
    std::copy_n(picture.row(y + row) + std::size_t(x) * picture.channels, std::size_t(w) * picture.channels,
                out.row(row));
  return out;
}

// The centre view of a quilt picture with the library's tiling (view views / 2, as Looking Glass
// software shows a quilt head-on).
Image8 centre_view(const Image8& quilt, const LibraryItem& item) {
  render::QuiltLayout q;
  q.cols = item.cols;
  q.rows = item.rows;
  q.views = item.views;
  q.width = quilt.width;
  q.height = quilt.height;
  q.aspect = item.aspect;
  const int view = q.views / 2;
  return crop(quilt, q.tile_x(view), q.tile_y_top_down(view), q.tile_width(), q.tile_height());
}

std::string content_key(const LibraryItem& item) {
  std::error_code ec;
  const auto modified = fs::last_write_time(item.path, ec).time_since_epoch().count();
  return fmt::format("{}\n{}\n{}", item.name, item.bytes, modified);
}

}  // namespace

Image8 shrink_to_thumbnail(const Image8& picture) {
  if (picture.width < 1 || picture.height < 1) throw_input_error("thumbnail: an empty picture");
  const double scale = std::min({1.0, double(kThumbnailPx) / picture.width, double(kThumbnailPx) / picture.height});
  const int w = std::max(1, int(picture.width * scale)), h = std::max(1, int(picture.height * scale));
  Image8 out(w, h, picture.channels);
  for (int y = 0; y < h; ++y) {
    const int y0 = int(std::int64_t(y) * picture.height / h), y1 = std::max(y0 + 1, int(std::int64_t(y + 1) * picture.height / h));
    for (int x = 0; x < w; ++x) {
      const int x0 = int(std::int64_t(x) * picture.width / w), x1 = std::max(x0 + 1, int(std::int64_t(x + 1) * picture.width / w));
      for (int c = 0; c < picture.channels; ++c) {
        std::uint64_t sum = 0;
        for (int sy = y0; sy < y1; ++sy)
          for (int sx = x0; sx < x1; ++sx) sum += picture.at(sx, sy, c);
        const std::uint64_t n = std::uint64_t(y1 - y0) * std::uint64_t(x1 - x0);
        out.at(x, y, c) = static_cast<std::uint8_t>((sum + n / 2) / n);
      }
    }
  }
  return out;
}

LibraryThumbnails::LibraryThumbnails(const ContentLibrary& library, MemoryBudget& budget)
    : library_(library), budget_(budget) {}

std::size_t LibraryThumbnails::made() const {
  std::lock_guard lock(mutex_);
  return made_;
}

std::string LibraryThumbnails::png(const std::string& name) {
  const LibraryItem item = library_.item(name);
  const std::string key = content_key(item);
  {
    std::lock_guard lock(mutex_);
    const auto kept = std::find_if(kept_.begin(), kept_.end(), [&](const Kept& k) { return k.key == key; });
    if (kept != kept_.end()) {
      kept_.splice(kept_.begin(), kept_, kept);
      return kept_.front().png;
    }
    if (making_) throw BusyError("thumbnail: another is being made; try again");
    making_ = true;
  }
  std::string made;
  try {
    made = make(item);
  } catch (...) {
    std::lock_guard lock(mutex_);
    making_ = false;
    throw;
  }
  std::lock_guard lock(mutex_);
  making_ = false;
  ++made_;
  // The same content under its old key (renamed, changed) goes; then the oldest beyond the bound.
  kept_.remove_if([&](const Kept& k) { return k.key.starts_with(item.name + "\n"); });
  kept_.push_front({key, made});
  while (kept_.size() > kThumbnailsKept) kept_.pop_back();
  return made;
}

std::string LibraryThumbnails::make(const LibraryItem& item) {
  // The decoded picture (RGB) and its thumbnail's working copy.
  const std::size_t picture_bytes = std::size_t(item.width) * std::size_t(item.height) * 3 * 2;
  const MemoryBudget::Reservation held = budget_.reserve_or_busy(picture_bytes, "the thumbnail of " + item.name);
  if (item.kind == "quilt video") {
    media::VideoDecoder video(item.path, {.try_hardware = false, .threads = 1});
    const auto frame = video.next_frame();
    if (!frame) throw_input_error("{}: no frame to make a thumbnail of", item.name);
    return png::encode_to_bytes("thumbnail", shrink_to_thumbnail(centre_view(media::yuv_to_rgb(*frame), item)));
  }
  const Image8 picture = media::decode_image(media::read_file_bytes(item.path), item.name);
  if (item.kind == "quilt") return png::encode_to_bytes("thumbnail", shrink_to_thumbnail(centre_view(picture, item)));
  return png::encode_to_bytes("thumbnail", shrink_to_thumbnail(picture));  // an RGB-D photo: colour and depth side by side
}

}  // namespace lfd::serve
