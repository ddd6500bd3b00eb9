#pragma once
// The console's library thumbnails (docs/console.md, "Thumbnails"): a quilt's centre view (a
// quilt video's, from its first frame), an RGB-D photo whole, made small by the service (at most
// kThumbnailPx per side, each thumbnail pixel the mean of the pixels it covers) and sent as PNG,
// so a phone loads a few kB per item instead of the whole quilt. Bounded: kept per content (the
// file's name, size and modification time) in a cache of at most kThumbnailsKept, least recently
// asked first out; one made at a time (another meanwhile is busy at once, not queued); the
// decoded picture reserved from the service's memory budget first. Thread-safe.
#include <cstddef>
#include <filesystem>
#include <list>
#include <mutex>
#include <string>

#include "serve/content_library.hpp"
#include "serve/memory_budget.hpp"
#include "util/image.hpp"

namespace lfd::serve {

inline constexpr int kThumbnailPx = 160;
inline constexpr std::size_t kThumbnailsKept = 128;

// `picture` made to fit kThumbnailPx x kThumbnailPx (aspect kept; never enlarged).
Image8 shrink_to_thumbnail(const Image8& picture);

class LibraryThumbnails {
 public:
  // Both outlive this object.
  LibraryThumbnails(const ContentLibrary& library, MemoryBudget& budget);
  // The PNG bytes of item `name`'s thumbnail. InputError when it is not an item of the library
  // (ContentLibrary::item) or cannot be decoded; BusyError while another is being made or the
  // budget cannot hold its picture now.
  std::string png(const std::string& name);
  // Thumbnails made since the start (not taken from the cache): what the tests count.
  std::size_t made() const;

 private:
  struct Kept {
    std::string key;  // name, size, modification time
    std::string png;
  };
  std::string make(const LibraryItem& item);

  const ContentLibrary& library_;
  MemoryBudget& budget_;
  mutable std::mutex mutex_;
  std::list<Kept> kept_;  // most recently asked first
  bool making_ = false;
  std::size_t made_ = 0;
};

}  // namespace lfd::serve
