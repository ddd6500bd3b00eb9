#pragma once
// `lfd serve`'s console (docs/console.md): the page (embedded at build time, console_assets.hpp)
// on the Bridge API's port, and the routes the page needs beyond Bridge's own endpoints: the
// content library (list, upload, file, thumbnail, rename, delete), the playlists kept, "Seen from", the
// calibration's report, its settings, and
// the login form of a service listening beyond loopback. Everything else the page does is a
// Bridge call (docs/serve.md). The Origin, Host and token checks run before any of these
// (BridgeServer's pre-routing handler).
#include <string>

#include "serve/content_library.hpp"
#include "serve/library_thumbnails.hpp"
#include "serve/listen_address.hpp"
#include "serve/origin_policy.hpp"
#include "serve/playlist_store.hpp"
#include "serve/seen_from.hpp"

namespace httplib {
class Server;
struct Request;
struct Response;
}  // namespace httplib

namespace lfd::serve {

// The one route whose body may exceed ServeLimits::max_body_bytes (up to the upload limit).
inline constexpr const char* kUploadPath = "/library/upload";

class ConsoleRoutes {
 public:
  ConsoleRoutes(const DisplayService& displays, PlaylistStore& playlists, ContentLibrary& library,
                LibraryThumbnails& thumbnails, SeenFromRenderer& seen_from, const OriginPolicy& origins,
                const ListenAddress& listen);
  // Registered before Bridge's routes: GET / answers the page to a browser (Accept: text/html)
  // and Bridge's JSON to a script.
  void add_routes(httplib::Server& server);
  // Without the token (beyond loopback): GET / is the login form (and its style); true when
  // the request was one of those and `res` is its answer.
  bool answer_without_token(const httplib::Request& req, httplib::Response& res) const;
  // POST /login: the form's token, checked by its route once the body is read.
  static bool is_login(const httplib::Request& req);
  // Whether a PUT/POST to `path` reaches a route that reads its body with its own bound
  // (bounded_body.hpp): Bridge's endpoints, the login form, rename and delete.
  static bool reads_bounded_body(const std::string& path);

 private:
  const DisplayService& displays_;
  PlaylistStore& playlists_;
  ContentLibrary& library_;
  LibraryThumbnails& thumbnails_;
  SeenFromRenderer& seen_from_;
  const OriginPolicy& origins_;
  ListenAddress listen_;
};

}  // namespace lfd::serve
