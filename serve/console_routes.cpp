// The console's routes (docs/console.md).
#include "serve/console_routes.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include <fmt/format.h>
#include <httplib.h>
#include <spdlog/spdlog.h>

#include "serve/bounded_body.hpp"
#include "serve/console_assets.hpp"
#include "serve/bridge_request.hpp"
#include "serve/calibration_report_summary.hpp"
#include "serve/request_file.hpp"
#include "util/error.hpp"

namespace lfd::serve {

using json = nlohmann::json;

namespace {

// Scripts ask `/` for JSON (bridge.js's "is Bridge running"); browsers say they take HTML.
bool wants_html(const httplib::Request& req) {
  return req.get_header_value("Accept").find("text/html") != std::string::npos;
}

void send_asset(httplib::Response& res, const ConsoleAsset& asset, int status = 200) {
  res.status = status;
  // The page loads nothing from elsewhere and cannot be framed; its WebSocket is the event
  // socket on another port of the same host.
  res.set_header("Content-Security-Policy",
                 "default-src 'self'; connect-src 'self' ws: wss:; img-src 'self' data: blob:; "
                 "style-src 'self'; frame-ancestors 'none'; form-action 'self'");
  res.set_header("X-Content-Type-Options", "nosniff");
  res.set_header("Cache-Control", "no-store");
  res.set_content(std::string(asset.bytes), std::string(asset.content_type));
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  res.status = status;
  res.set_content(json{{"error", message}}.dump(), "application/json");
}

// Runs `answer`, turning a refusal into a one-line JSON error.
template <typename F>
void answering(const char* what, httplib::Response& res, F&& answer) {
  try {
    res.set_content(answer().dump(), "application/json");
  } catch (const InputError& e) {
    spdlog::warn("console {}: {}", what, e.what());
    send_error(res, 400, e.what());
  } catch (const std::exception& e) {
    spdlog::error("console {}: {}", what, e.what());
    send_error(res, 500, e.what());
  }
}

constexpr std::size_t kSmallBodyBytes = 1u << 16;  // a rename, a delete, the login form

std::string percent_decoded(const std::string& s) { return httplib::detail::decode_url(s, false); }

// A query parameter that must be a whole number / a finite number: `fallback` when absent.
int int_param(const httplib::Request& req, const char* name, int fallback) {
  if (!req.has_param(name)) return fallback;
  const std::string text = req.get_param_value(name);
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) throw_input_error("{}: not a whole number", name);
  return value;
}

double number_param(const httplib::Request& req, const char* name) {
  const std::string text = req.get_param_value(name);
  if (text.empty()) throw_input_error("{}: missing", name);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw_input_error("{}: not a number", name);
  return value;
}

json playlist_json(const Playlist& p, const std::filesystem::path& folder) {
  json entries = json::array();
  for (const PlaylistEntry& e : p.entries) {
    const bool in_library = e.file.parent_path() == folder;
    entries.push_back({{"uri", e.file.string()}, {"name", e.file.filename().string()}, {"in_library", in_library},
                       {"cols", e.quilt.cols}, {"rows", e.quilt.rows}, {"views", e.quilt.views},
                       {"aspect", e.quilt.aspect}, {"durationMS", e.duration_ms}, {"isRGBD", e.rgbd.has_value()}});
  }
  return {{"name", p.name}, {"loop", p.loop}, {"entries", entries}};
}

}  // namespace

ConsoleRoutes::ConsoleRoutes(const DisplayService& displays, PlaylistStore& playlists, ContentLibrary& library,
                             LibraryThumbnails& thumbnails, SeenFromRenderer& seen_from, const OriginPolicy& origins,
                             const ListenAddress& listen)
    : displays_(displays),
      playlists_(playlists),
      library_(library),
      thumbnails_(thumbnails), seen_from_(seen_from), origins_(origins), listen_(listen) {}

bool ConsoleRoutes::answer_without_token(const httplib::Request& req, httplib::Response& res) const {
  const ConsoleAsset* login = console_asset("login.html");
  if (req.method == "GET" && req.path == "/") {
    if (!wants_html(req)) return send_error(res, 401, "the access token is needed (lfd serve --print-token)"), true;
    send_asset(res, *login, 401);
    return true;
  }
  if (req.method == "GET" && req.path == "/console/console.css") return send_asset(res, *console_asset("console.css")), true;
  return false;
}

bool ConsoleRoutes::is_login(const httplib::Request& req) { return req.method == "POST" && req.path == "/login"; }

bool ConsoleRoutes::reads_bounded_body(const std::string& path) {
  if (path == "/library/rename" || path == "/library/delete") return true;
  // Bridge's /<endpoint> (and /login among them).
  return path.size() >= 2 && path.size() <= 65 && path[0] == '/' &&
         std::all_of(path.begin() + 1, path.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; });
}

void ConsoleRoutes::add_routes(httplib::Server& s) {
  s.Post("/login", [this](const httplib::Request&, httplib::Response& res, const httplib::ContentReader& read) {
    const ConsoleAsset* login = console_asset("login.html");
    const auto body = read_bounded_body(read, kSmallBodyBytes);
    if (!origins_.token()) return res.set_redirect("/", 303);  // loopback: nothing to sign in to
    // A form post (application/x-www-form-urlencoded): token=<64 hex digits>.
    httplib::Params form;
    if (body) httplib::detail::parse_query_text(*body, form);
    const std::string given = form.count("token") ? form.find("token")->second : "";
    if (origins_.token()->matches(given)) {
      // The cookie goes with every request to this host, the event socket's port too.
      res.set_header("Set-Cookie", std::string(kTokenCookie) + "=" + origins_.token()->text() +
                                       "; Path=/; HttpOnly; SameSite=Strict; Max-Age=31536000");
      return res.set_redirect("/", 303);
    }
    spdlog::warn("console: a login with a wrong token");
    std::string page(login->bytes);
    const std::string mark = "<!--message-->";
    if (const auto at = page.find(mark); at != std::string::npos)
      page.replace(at, mark.size(), "<p role=\"alert\" class=\"error\">That is not the token of this service.</p>");
    res.status = 401;
    res.set_content(page, std::string(login->content_type));
  });
  s.Get("/", [](const httplib::Request& req, httplib::Response& res) {
    if (wants_html(req)) return send_asset(res, *console_asset("index.html"));
    res.set_content(R"({"service":"lfd serve"})", "application/json");
  });
  s.Get(R"(/console/([a-z_]{1,32}\.(js|css|svg)))", [](const httplib::Request& req, httplib::Response& res) {
    const ConsoleAsset* asset = console_asset(req.matches[1].str());
    if (!asset) return send_error(res, 404, "no such file");
    send_asset(res, *asset);
  });
  s.Get("/console/config", [this](const httplib::Request&, httplib::Response& res) {
    answering("config", res, [&] {
      return json{{"events_port", listen_.events_port}, {"bridge_port", listen_.bridge_port},
                  {"token_required", origins_.token_required()}, {"upload_limit_bytes", library_.max_upload_bytes()},
                  {"content_folder", library_.folder().string()}};
    });
  });
  s.Get("/library", [this](const httplib::Request&, httplib::Response& res) {
    answering("library", res, [&] {
      json items = json::array();
      for (const auto& item : library_.items()) items.push_back(library_item_json(item));
      return json{{"folder", library_.folder().string()}, {"items", items}};
    });
  });
  s.Get("/library/file", [this](const httplib::Request& req, httplib::Response& res) {
    try {
      const LibraryItem item = library_.item(req.get_param_value("name"));
      const std::string type = item.kind == "quilt video" ? "video/mp4" : "application/octet-stream";
      // The service's own file, checked as any request's file and streamed in 64 KiB pieces
      // (a thumbnail is the whole quilt: never held in memory).
      const auto path = checked_request_file(item.path.string(), library_.max_upload_bytes());
      auto in = std::make_shared<std::ifstream>(path, std::ios::binary);
      const std::size_t size = std::filesystem::file_size(path);
      res.set_header("X-Content-Type-Options", "nosniff");
      res.set_content_provider(size,
                               item.name.ends_with(".png")    ? "image/png"
                               : item.name.ends_with(".jpg")  ? "image/jpeg"
                               : item.name.ends_with(".webp") ? "image/webp"
                                                              : type,
                               [in](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                 std::vector<char> piece(std::min<std::size_t>(length, 64u << 10));
                                 in->seekg(static_cast<std::streamoff>(offset));
                                 in->read(piece.data(), static_cast<std::streamsize>(piece.size()));
                                 if (in->gcount() <= 0) return false;
                                 sink.write(piece.data(), static_cast<std::size_t>(in->gcount()));
                                 return true;
                               });
    } catch (const InputError& e) {
      send_error(res, 404, e.what());
    }
  });
  s.Get("/library/thumbnail", [this](const httplib::Request& req, httplib::Response& res) {
    try {
      const std::string picture = thumbnails_.png(req.get_param_value("name"));
      res.set_header("X-Content-Type-Options", "nosniff");
      res.set_header("Cache-Control", "no-cache");  // the same name may hold other content later
      res.set_content(picture, "image/png");
    } catch (const InputError& e) {
      send_error(res, 404, e.what());
    } catch (const BusyError& e) {
      send_error(res, 503, e.what());
      res.set_header("Retry-After", "1");
    }
  });
  s.Post(kUploadPath, [this](const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader) {
    answering("upload", res, [&] {
      const std::string name = percent_decoded(req.get_header_value("X-File-Name"));
      const LibraryItem item = library_.upload(name, [&](const std::function<bool(const char*, std::size_t)>& sink) {
        return reader([&](const char* data, std::size_t n) { return sink(data, n); });
      });
      spdlog::info("console: uploaded {} ({}, {} bytes)", item.name, item.kind, item.bytes);
      return library_item_json(item);
    });
    if (res.status == 400 && res.body.find("upload limit") != std::string::npos) res.status = 413;
  });
  s.Post("/library/rename", [this](const httplib::Request&, httplib::Response& res, const httplib::ContentReader& read) {
    const auto body = read_bounded_body(read, kSmallBodyBytes);
    answering("rename", res, [&] {
      if (!body) throw_input_error("body: larger than {} bytes", kSmallBodyBytes);
      const json r = parse_bridge_request(*body, kSmallBodyBytes);
      const LibraryItem item = library_.rename(field_text(r, "name", 256, ""), field_text(r, "new_name", 256, ""));
      return library_item_json(item);
    });
  });
  s.Post("/library/delete", [this](const httplib::Request&, httplib::Response& res, const httplib::ContentReader& read) {
    const auto body = read_bounded_body(read, kSmallBodyBytes);
    answering("delete", res, [&] {
      if (!body) throw_input_error("body: larger than {} bytes", kSmallBodyBytes);
      const json r = parse_bridge_request(*body, kSmallBodyBytes);
      const std::string name = field_text(r, "name", 256, "");
      library_.remove(name);
      return json{{"deleted", name}};
    });
  });
  s.Get("/calibration_report", [this](const httplib::Request& req, httplib::Response& res) {
    answering("calibration report", res, [&] {
      const int index = int_param(req, "display", 0);
      const auto all = displays_.displays();
      if (index < 0 || index >= static_cast<int>(all.size()))
        throw_input_error("display: {} is not served (0..{})", index, static_cast<int>(all.size()) - 1);
      const auto file = find_calibration_report(all[static_cast<std::size_t>(index)]);
      // No report is an answer, not an error: a factory calibration has none.
      return file ? json{{"display", index}, {"report", calibration_report_summary(*file)}}
                  : json{{"display", index}, {"report", nullptr}};
    });
  });
  s.Get("/seen_from/range", [this](const httplib::Request& req, httplib::Response& res) {
    answering("seen from", res, [&] {
      const SeenFromRange r = seen_from_.range(int_param(req, "display", 0));
      return json{{"cone_deg", r.cone_deg}, {"views", r.views}, {"first_view_deg", r.first_view_deg},
                  {"last_view_deg", r.last_view_deg}, {"distance_m", r.distance_m},
                  {"panel_width_m", r.panel_width_m}, {"panel_height_m", r.panel_height_m},
                  {"max_height_px", kSeenFromMaxHeightPx}};
    });
  });
  s.Get("/seen_from", [this](const httplib::Request& req, httplib::Response& res) {
    try {
      // The eye's angle in degrees, or the view whose middle it sees (the page's slider).
      const int display = int_param(req, "display", 0);
      if (req.has_param("angle") == req.has_param("view")) throw_input_error("give angle (degrees) or view, one of them");
      const double angle = req.has_param("angle") ? number_param(req, "angle")
                                                  : seen_from_.angle_of_view(display, number_param(req, "view"));
      const std::string picture = seen_from_.png(display, angle, int_param(req, "height", kSeenFromDefaultHeightPx));
      res.set_header("X-Seen-From-Angle", fmt::format("{:.2f}", angle));
      res.set_header("Cache-Control", "no-store");
      res.set_header("X-Content-Type-Options", "nosniff");
      res.set_content(picture, "image/png");
    } catch (const InputError& e) {
      spdlog::warn("console seen from: {}", e.what());
      send_error(res, 400, e.what());
    } catch (const BusyError& e) {
      send_error(res, 503, e.what());
      res.set_header("Retry-After", "1");
    }
  });
  s.Get("/playlists", [this](const httplib::Request&, httplib::Response& res) {
    answering("playlists", res, [&] {
      json lists = json::array();
      for (const Playlist& p : playlists_.all()) lists.push_back(playlist_json(p, library_.folder()));
      const auto autostart = playlists_.autostart();
      return json{{"playlists", lists},
                  {"autostart", autostart ? json{{"name", autostart->name}, {"head_index", autostart->head_index}}
                                          : json(nullptr)}};
    });
  });
}

}  // namespace lfd::serve
