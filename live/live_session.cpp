#include "live/live_session.hpp"

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::live {
namespace fs = std::filesystem;
namespace {

constexpr const char* kSessionFile = "live-session.json";
constexpr const char* kSessionFormat = "lfd live calibration session";

struct SessionState {
  LiveSessionPlan plan;
  std::map<int, std::set<int>> complete;
};

int int_field(const nlohmann::json& j, const std::string& where, const char* field, int lo,
              int hi) {
  if (!j.contains(field) || !j[field].is_number_integer())
    throw_input_error("{}: {}: missing or not an integer", where, field);
  const int v = j[field].get<int>();
  if (v < lo || v > hi) throw_input_error("{}: {}: {} is outside {}..{}", where, field, v, lo, hi);
  return v;
}

SessionState read_state(const fs::path& path) {
  const std::string where = path.string();
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(path));
  } catch (const nlohmann::json::exception& e) {
    throw_input_error("{}: not JSON ({})", where, e.what());
  }
  if (!j.is_object() || j.value("format", std::string()) != kSessionFormat)
    throw_input_error("{}: format: not \"{}\"", where, kSessionFormat);
  SessionState s;
  s.plan.rounds = int_field(j, where, "rounds", 1, 99);
  s.plan.positions = int_field(j, where, "positions", 1, 99);
  const auto complete = j.value("complete", nlohmann::json::object());
  if (!complete.is_object()) throw_input_error("{}: complete: not an object", where);
  for (int r = 1; r <= s.plan.rounds; ++r) {
    const std::string key = "round-" + std::to_string(r);
    if (!complete.contains(key)) continue;
    if (!complete[key].is_array()) throw_input_error("{}: complete.{}: not a list", where, key);
    for (const auto& name : complete[key]) {
      const std::string n = name.is_string() ? name.get<std::string>() : "";
      int index = -1;
      for (int i = 0; i < s.plan.positions; ++i)
        if (n == LiveSession::position_name(i)) index = i;
      if (index < 0) throw_input_error("{}: complete.{}: \"{}\" is no position", where, key, n);
      s.complete[r].insert(index);
    }
  }
  return s;
}

fs::path position_dir(const fs::path& round_dir, int index) {
  return round_dir / "captures" / LiveSession::position_name(index);
}

}  // namespace

LiveSession::LiveSession(fs::path dir, const LiveSessionPlan& plan)
    : dir_(std::move(dir)), plan_(plan) {
  const fs::path state = dir_ / kSessionFile;
  if (fs::exists(state)) {
    const SessionState s = read_state(state);
    if (s.plan.rounds != plan.rounds)
      throw_input_error("{}: rounds: the session was planned with {}, this run asks for {} "
                        "(--rounds {} resumes it)",
                        state.string(), s.plan.rounds, plan.rounds, s.plan.rounds);
    if (s.plan.positions != plan.positions)
      throw_input_error("{}: positions: the session was planned with {}, this run asks for {} "
                        "(--positions {} resumes it)",
                        state.string(), s.plan.positions, plan.positions, s.plan.positions);
    complete_ = s.complete;
    return;
  }
  if (fs::exists(dir_) && !fs::is_empty(dir_))
    throw_input_error("{}: not empty and no {} in it: give a new folder for the live session",
                      dir_.string(), kSessionFile);
  fs::create_directories(dir_);
  write_state();
}

fs::path LiveSession::round_dir(int round) const {
  return dir_ / ("round-" + std::to_string(round));
}

void LiveSession::write_state() const {
  nlohmann::ordered_json j;
  j["format"] = kSessionFormat;
  j["rounds"] = plan_.rounds;
  j["positions"] = plan_.positions;
  nlohmann::ordered_json complete = nlohmann::ordered_json::object();
  for (const auto& [round, indices] : complete_) {
    auto names = nlohmann::ordered_json::array();
    for (int i : indices) names.push_back(position_name(i));
    complete["round-" + std::to_string(round)] = names;
  }
  j["complete"] = complete;
  j["offline"] = "lfd calibrate <this folder> re-solves the last round";
  write_text_atomic(dir_ / kSessionFile, j.dump(2) + "\n");
}

std::optional<sim::PatternSet> LiveSession::saved_patterns(int round) const {
  if (!fs::exists(round_dir(round) / "patterns" / "manifest.json")) return std::nullopt;
  return sim::read_pattern_set(round_dir(round));
}

sim::PatternSet LiveSession::save_patterns(int round, const sim::PatternSet& set) {
  sim::write_pattern_set(round_dir(round), set, /*force=*/true);  // a half-written earlier try
  return sim::read_pattern_set(round_dir(round));
}

void LiveSession::save_camera(int round, const std::optional<sim::CameraIntrinsics>& camera) {
  const fs::path path = round_dir(round) / "camera.yaml";
  if (camera) camera->write_yaml(path);
  else fs::remove(path);
}

bool LiveSession::position_complete(int round, int index) const {
  auto it = complete_.find(round);
  return it != complete_.end() && it->second.count(index);
}

void LiveSession::begin_position(int round, int index) {
  fs::remove_all(position_dir(round_dir(round), index));
  fs::create_directories(position_dir(round_dir(round), index));
}

cv::Mat LiveSession::save_photo(int round, int index, const std::string& stem, const cv::Mat& rgb,
                                std::string& path) {
  // 16 bits: an average of webcam frames keeps its fractions, and the rounding is 100 times
  // below a camera's noise. The returned image is the file's content, converted as
  // read_capture converts it.
  cv::Mat bgr16, rgb16, out;
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  bgr.convertTo(bgr16, CV_16UC3, 65535.0);
  const fs::path file = position_dir(round_dir(round), index) / (stem + ".png");
  write_file_atomic(file, [&](const fs::path& tmp) {
    const fs::path named = tmp.string() + ".png";  // imwrite picks the format by extension
    if (!cv::imwrite(named.string(), bgr16))
      throw_input_error("{}: cannot write the photograph", file.string());
    fs::rename(named, tmp);
  });
  path = file.string();
  cv::cvtColor(bgr16, rgb16, cv::COLOR_BGR2RGB);
  rgb16.convertTo(out, CV_32FC3, 1.0 / 65535);
  return out;
}

void LiveSession::complete_position(int round, int index) {
  complete_[round].insert(index);
  write_state();
}

sim::PositionCaptures LiveSession::read_position(int round, int index, const sim::PatternSet& set) const {
  sim::PositionCaptures pc;
  pc.name = position_name(index);
  for (const sim::PatternInfo& p : set.patterns) {
    const std::string stem = fs::path(p.file).stem().string();
    const fs::path file = position_dir(round_dir(round), index) / (stem + ".png");
    pc.images[stem] = sim::read_capture(file);
    pc.paths[stem] = file.string();
  }
  return pc;
}

fs::path capture_folder_of(const fs::path& dir) {
  const fs::path state = dir / kSessionFile;
  if (fs::exists(dir / "patterns") || !fs::exists(state)) return dir;
  const SessionState s = read_state(state);
  const int last = s.plan.rounds;
  const auto it = s.complete.find(last);
  const int done = it == s.complete.end() ? 0 : int(it->second.size());
  if (done < s.plan.positions)
    throw_input_error(
        "{}: a live session whose last round ({}) has {} of {} positions: finish it with "
        "`lfd calibrate --live --resume {}`, or calibrate an earlier round's folder",
        dir.string(), last, done, s.plan.positions, dir.string());
  return dir / ("round-" + std::to_string(last));
}

}  // namespace lfd::live
