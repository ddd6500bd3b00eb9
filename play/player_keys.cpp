#include "play/player_keys.hpp"

#include <iostream>

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include "play/player.hpp"

namespace lfd::play {
namespace {

void print_state(const PlayerState& s) {
  std::cout << fmt::format("[{} {}/{}] {} {:.1f}/{:.1f} s{}, shown {}, decoded {}, dropped {}{}\n",
                           s.playing ? "playing" : "paused", s.entry_index + 1, s.entry_count, s.entry_name,
                           s.position_s, s.duration_s, s.looping ? ", looping" : "", s.frames_shown,
                           s.frames_decoded, s.frames_dropped,
                           s.decode_path.empty() ? "" : ", decoder " + s.decode_path);
}

void on_key(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  auto* keys = static_cast<PlayerKeys*>(glfwGetWindowUserPointer(window));
  if (!keys || !keys->player) return;
  Player& p = *keys->player;
  const bool video = p.state().is_video;
  switch (key) {
    case GLFW_KEY_SPACE: p.toggle_pause(); break;
    case GLFW_KEY_RIGHT: video ? p.seek_by(kSeekStepS) : p.next(); break;
    case GLFW_KEY_LEFT: video ? p.seek_by(-kSeekStepS) : p.previous(); break;
    case GLFW_KEY_DOWN:
    case GLFW_KEY_PAGE_DOWN:
    case GLFW_KEY_N: p.next(); break;
    case GLFW_KEY_UP:
    case GLFW_KEY_PAGE_UP:
    case GLFW_KEY_P: p.previous(); break;
    case GLFW_KEY_L: p.set_loop(!p.state().looping); break;
    case GLFW_KEY_H:
      keys->overlay = !keys->overlay;
      p.set_overlay(keys->overlay);
      std::cout << player_help_text();
      print_state(p.state());
      break;
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q: p.quit(); break;
    default: break;
  }
}

}  // namespace

const char* player_help_text() {
  return "lfd play keys: space pause/play, Left/Right seek 5 s (images: previous/next), Up/Down or\n"
         "PageUp/PageDown previous/next entry, L looping on/off, H this help and the progress bar,\n"
         "Esc or Q quit\n";
}

std::unique_ptr<PlayerKeys> install_player_keys(Player& player, GLFWwindow* window) {
  auto keys = std::make_unique<PlayerKeys>();
  keys->player = &player;
  glfwSetWindowUserPointer(window, keys.get());
  glfwSetKeyCallback(window, on_key);
  return keys;
}

}  // namespace lfd::play
