#pragma once
// Every bound the service keeps, in one place (docs/serve.md, "Security model"): message and
// body sizes, files, the quilt cache, playlists, connections and timeouts.
#include <cstddef>

namespace lfd::serve {

struct ServeLimits {
  std::size_t max_message_bytes = 96u << 20;  // one HoloPlay request (a quilt image inside)
  std::size_t max_body_bytes = 1u << 20;      // one Bridge JSON body
  std::size_t max_event_message_bytes = 4096; // what a client may send on the event socket
  std::size_t max_file_bytes = 256u << 20;    // a `uri` read from disk
  std::size_t max_cache_bytes = 1u << 30;     // decoded quilts kept by `cache`
  int max_cached_quilts = 64;
  int max_playlists = 64;
  int max_playlist_entries = 1024;
  int max_connections = 64;        // per listener
  int worker_threads = 4;          // requests handled at once per protocol
  int io_timeout_s = 10;           // a request's read or write
  int max_cbor_depth = 16;
  std::size_t max_cbor_items = 1u << 20;
  std::size_t max_name_chars = 256;  // cache and playlist names
};

}  // namespace lfd::serve
