// The HoloPlay Service commands (docs/serve.md, "HoloPlay Service protocol").
#include "serve/holoplay_protocol.hpp"

#include <cmath>
#include <memory>

#include <spdlog/spdlog.h>

#include "display/display_quilt.hpp"
#include "display/lens_model.hpp"
#include "serve/served_display_json.hpp"
#include "util/error.hpp"

namespace lfd::serve {

using json = nlohmann::json;

namespace {

// An InputError that carries the reply's error value.
struct ProtocolError : InputError {
  HoloPlayError code;
  ProtocolError(HoloPlayError c, const std::string& m) : InputError(m), code(c) {}
};

json ok() { return {{"error", 0}}; }

json device_json(const ServedDisplay& d) {
  return {{"buttons", {{"left", 0}, {"right", 0}, {"square", 0}, {"circle", 0}}},
          {"calibration", served_calibration(d)},
          {"defaultQuilt", served_default_quilt(d)},
          {"hardwareVersion", d.hardware_version},
          {"hwid", d.hwid},
          {"index", d.index},
          {"joystickIndex", -1},
          {"state", "ok"},
          {"unityIndex", d.index},
          {"windowCoords", {d.window_x, d.window_y}}};
}

}  // namespace

json holoplay_error(HoloPlayError error, const std::string& message) {
  return {{"error", static_cast<int>(error)}, {"errorMessage", message}};
}

HoloPlayProtocol::HoloPlayProtocol(DisplayService& displays, QuiltCache& cache, DecodedQuilts& decoded,
                                   MemoryBudget& budget, const ServeLimits& limits)
    : displays_(displays), cache_(cache), decoded_(decoded), budget_(budget), limits_(limits) {}

// The message, the parsed CBOR's copy of `bin` and the request's: three times its size while it
// is handled (docs/serve.md, "Memory").
constexpr std::size_t kCopiesOfAMessage = 3;

MemoryBudget::Reservation HoloPlayProtocol::admit(std::size_t bytes) {
  return budget_.try_reserve(kCopiesOfAMessage * bytes);
}

bool HoloPlayProtocol::carries_content(std::span<const std::uint8_t> payload, std::size_t small_bytes) const {
  if (payload.size() > small_bytes) return true;
  try {
    return !parse_holoplay_request(payload, {limits_.max_cbor_depth, limits_.max_cbor_items}).bin.empty();
  } catch (const std::exception&) {
    return false;
  }
}

std::vector<std::uint8_t> HoloPlayProtocol::busy_reply(const std::string& message) {
  return encode_cbor(holoplay_error(HoloPlayError::kBusy, message));
}

std::vector<std::uint8_t> HoloPlayProtocol::handle(std::span<const std::uint8_t> payload) {
  return handle(payload, MemoryBudget::Reservation());
}

std::vector<std::uint8_t> HoloPlayProtocol::handle(std::span<const std::uint8_t> payload,
                                                   MemoryBudget::Reservation held) {
  json reply;
  try {
    const MemoryBudget::Reservation message =
        held ? std::move(held) : budget_.reserve_or_busy(kCopiesOfAMessage * payload.size(), "a HoloPlay message");
    const HoloPlayRequest request =
        parse_holoplay_request(payload, {limits_.max_cbor_depth, limits_.max_cbor_items});
    reply = handle_request(request);
  } catch (const BusyError& e) {
    reply = holoplay_error(HoloPlayError::kBusy, e.what());  // not logged: a log line per refusal under load
  } catch (const InputError& e) {
    spdlog::warn("holoplay: refused a request: {}", e.what());
    reply = holoplay_error(HoloPlayError::kBadMessage, e.what());
  }
  return encode_cbor(reply);
}

json HoloPlayProtocol::handle_request(const HoloPlayRequest& r) {
  try {
    if (r.command == "init" || r.command == "info") return info();
    if (r.command == "show") return show(r);
    if (r.command == "cache") return cache(r);
    if (r.command == "check") return check(r);
    if (r.command == "delete") return erase(r);
    if (r.command == "wipe") return wipe(r);
    if (r.command == "uniforms") return uniforms();
    // The vendor's service sent its GLSL; lfd's interlacer is GL 4.5 with its own uniforms, of
    // no use to a WebGL client, and holoplay-core builds its shader itself (docs/serve.md).
    if (r.command == "shader")
      throw ProtocolError(HoloPlayError::kUnknownCommand,
                          "shader: not provided; build it from the calibration (holoplay-core's Shader) with `uniforms`");
    throw ProtocolError(HoloPlayError::kUnknownCommand,
                        "unknown or unimplemented command: " + r.command.substr(0, 64));
  } catch (const ProtocolError& e) {
    spdlog::warn("holoplay {}: {}", r.command.substr(0, 64), e.what());
    return holoplay_error(e.code, e.what());
  } catch (const BusyError& e) {
    return holoplay_error(HoloPlayError::kBusy, e.what());
  } catch (const InputError& e) {
    spdlog::warn("holoplay {}: {}", r.command.substr(0, 64), e.what());
    return holoplay_error(HoloPlayError::kBadArgument, e.what());
  } catch (const nlohmann::json::exception& e) {
    spdlog::warn("holoplay {}: {}", r.command.substr(0, 64), e.what());
    return holoplay_error(HoloPlayError::kBadArgument, e.what());
  } catch (const std::exception& e) {
    spdlog::error("holoplay {}: {}", r.command.substr(0, 64), e.what());
    return holoplay_error(HoloPlayError::kInternal, e.what());
  }
}

json HoloPlayProtocol::info() const {
  json devices = json::array();
  for (const ServedDisplay& d : displays_.displays()) devices.push_back(device_json(d));
  return {{"error", 0}, {"version", kHoloPlayServiceVersion}, {"devices", devices}};
}

json HoloPlayProtocol::uniforms() const {
  json devices = json::array();
  for (const ServedDisplay& d : displays_.displays()) {
    const display::DisplayCalibration& c = d.calibration.display;
    const display::LensModel lens(c, d.calibration.correction);
    // The shader's terms (display/lens_relations.hpp, shader_terms): the phase of subpixel k of
    // pixel (u, v) is ((u + k subp) + v tilt) pitch - center.
    devices.push_back({{"index", d.index},
                       {"pitch", lens.pitch_periods()},
                       {"tilt", lens.tilt()},
                       {"center", c.center_periods},
                       {"subp", 1.0 / (3.0 * c.screen_w)},
                       {"invView", c.inv_view ? 1 : 0},
                       {"flipX", c.flip_image_x ? 1 : 0},
                       {"ri", c.flip_subp ? 2 : 0},
                       {"bi", c.flip_subp ? 0 : 2},
                       {"displayAspect", double(c.screen_w) / c.screen_h},
                       {"viewCone", display::effective_view_cone_deg(d.calibration)},
                       {"screenW", c.screen_w},
                       {"screenH", c.screen_h}});
  }
  return {{"error", 0}, {"uniforms", devices}};
}

int HoloPlayProtocol::target_display(const json& args) const {
  const auto t = args.find("targetDisplay");
  const int count = static_cast<int>(displays_.displays().size());
  if (count == 0) throw ProtocolError(HoloPlayError::kInternal, "no display is served");
  if (t == args.end() || t->is_null()) return 0;
  if (!t->is_number() || t->get<double>() != std::floor(t->get<double>()) || t->get<double>() < 0 ||
      t->get<double>() >= count)
    throw_input_error("targetDisplay: not a display index in 0..{}", count - 1);
  return t->get<int>();
}

std::string HoloPlayProtocol::quilt_name(const json& holder) const {
  const auto n = holder.find("name");
  if (n == holder.end() || !n->is_string() || n->get_ref<const std::string&>().empty())
    throw_input_error("name: missing or not text");
  const std::string& name = n->get_ref<const std::string&>();
  if (name.size() > limits_.max_name_chars) throw_input_error("name: longer than {} characters", limits_.max_name_chars);
  return name;
}

json HoloPlayProtocol::show(const HoloPlayRequest& r) {
  const int display = target_display(r.args);
  const json quilt = r.args.value("quilt", json::object());
  if (!quilt.is_object()) throw_input_error("show: quilt: not a map");
  const std::string source = r.args.value("source", std::string("bindata"));
  if (source == "cache") {
    const std::string name = quilt_name(quilt);
    auto cached = cache_.get(name);
    if (!cached) throw ProtocolError(HoloPlayError::kNotFound, "show: no cached quilt named " + name);
    const QuiltSettings settings =
        quilt.contains("settings") ? holoplay_quilt_settings(quilt["settings"]) : cached->settings;
    displays_.show_quilt(display, *cached->image, settings, "cached quilt " + name);
    return ok();
  }
  if (source != "bindata") throw_input_error("show: source: {} is neither bindata nor cache", source.substr(0, 64));
  const QuiltSettings settings = holoplay_quilt_settings(quilt.value("settings", json()));
  const std::shared_ptr<const Image8> image = decoded_.decode(r.bin, "show: bin");
  displays_.show_quilt(display, *image, settings, "quilt sent by a HoloPlay client");
  return ok();
}

json HoloPlayProtocol::cache(const HoloPlayRequest& r) {
  const json quilt = r.args.value("quilt", json::object());
  if (!quilt.is_object()) throw_input_error("cache: quilt: not a map");
  CachedQuilt entry;
  entry.name = quilt_name(quilt);
  entry.settings = holoplay_quilt_settings(quilt.value("settings", json()));
  entry.image = decoded_.decode(r.bin, "cache: bin");
  const bool show = r.args.value("show", false);
  if (show) displays_.show_quilt(target_display(r.args), *entry.image, entry.settings, "cached quilt " + entry.name);
  cache_.put(std::move(entry));
  return ok();
}

json HoloPlayProtocol::check(const HoloPlayRequest& r) const {
  const std::string name = quilt_name(r.args);
  if (!cache_.contains(name)) throw ProtocolError(HoloPlayError::kNotFound, "check: no cached quilt named " + name);
  return ok();
}

json HoloPlayProtocol::erase(const HoloPlayRequest& r) {
  const std::string name = quilt_name(r.args);
  if (!cache_.erase(name)) throw ProtocolError(HoloPlayError::kNotFound, "delete: no cached quilt named " + name);
  return ok();
}

json HoloPlayProtocol::wipe(const HoloPlayRequest& r) {
  displays_.wipe(target_display(r.args));
  return ok();
}

}  // namespace lfd::serve
