#pragma once
// Every bound the service keeps, in one place (docs/serve.md, "Security model", "Memory"):
// the memory budget, message and body sizes, files, playlists, connections and timeouts.
#include <cstddef>

namespace lfd::serve {

struct ServeLimits {
  // The ONE byte budget of everything a request's content holds while it waits (decoded
  // quilts, pictures handed to the display, the quilt cache, Bridge bodies, queued events),
  // and of the service's own resident memory at start (apps/serve.cpp reserves it): sized for a
  // small board beside the display. Over it, requests are answered busy (memory_budget.hpp).
  std::size_t memory_budget_bytes = 512u << 20;
  std::size_t max_message_bytes = 96u << 20;  // one HoloPlay request (a quilt image inside)
  std::size_t max_body_bytes = 1u << 20;      // one Bridge JSON body
  std::size_t max_event_message_bytes = 4096; // what a client may send on the event socket
  std::size_t max_file_bytes = 256u << 20;    // a `uri` read from disk
  std::size_t max_upload_bytes = 256u << 20;  // a file uploaded to the console's content folder
  int max_cached_quilts = 64;
  int max_playlists = 64;
  int max_playlist_entries = 1024;
  int max_connections = 64;        // per listener
  int worker_threads = 4;          // requests handled at once per protocol
  // Quilt images decoded at once: the rest of the workers stay free for cheap requests (info,
  // shows of content already decoded); a show that needs a decode while all are busy is busy.
  int max_decodes = 1;
  int decoded_quilts_kept = 4;     // distinct contents kept decoded (decoding once per content)
  int io_timeout_s = 10;           // a request's read or write
  int max_cbor_depth = 16;
  std::size_t max_cbor_items = 1u << 20;
  std::size_t max_name_chars = 256;  // cache and playlist names
};

}  // namespace lfd::serve
