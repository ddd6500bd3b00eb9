#pragma once
// The player's keyboard (docs/play.md "Controls"), on its window: space pauses, Left/Right seek
// 5 s back/forward (an image: the previous/next entry), Up/PageUp and Down/PageDown go to the
// previous/next entry, L toggles looping, H shows or hides the overlay and prints the help and
// the state on the terminal, Esc/Q quit. Keys only queue the Player's thread-safe commands.
#include <memory>

struct GLFWwindow;

namespace lfd::play {

class Player;

inline constexpr double kSeekStepS = 5.0;

// What the key callback needs (the window's user pointer points at it).
struct PlayerKeys {
  Player* player = nullptr;
  bool overlay = false;
};

// Installs the key callback on `window`; the returned object must outlive the window's use.
std::unique_ptr<PlayerKeys> install_player_keys(Player& player, GLFWwindow* window);

// The help text H prints.
const char* player_help_text();

}  // namespace lfd::play
