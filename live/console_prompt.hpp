#pragma once
// Asking the user to act (move the camera) and waiting for Enter, while the pattern window
// keeps handling its events: a window that stops answering is greyed out or covered by a
// "not responding" dialog on some desktops, which the camera would photograph.
#include <functional>
#include <string>

namespace lfd::live {

// Prints `prompt` on stderr and returns when a line arrives on stdin or `poll` (called about
// every 50 ms meanwhile: the window's events) returns true (Enter pressed in the window).
// Throws InputError if stdin is closed.
void wait_for_enter(const std::string& prompt, const std::function<bool()>& poll);

}  // namespace lfd::live
