#pragma once
// Strings across the C API (docs/bridge-inproc.md "Strings"). Bridge's header declares some paths
// wchar_t (quiltify_rgbd, instance_offscreen_window) where the Python SDK passes UTF-8 char
// strings, and initialize_bridge char where the SDK passes wchar_t: a string is read as wchar_t
// (UTF-32 on Linux) when its first character's next three bytes are zero, else as UTF-8. A
// one-character UTF-8 string is the one case this misreads, and no path or name is that short.
#include <string>

namespace lfd::bridge {

// The text at `p`, either encoding; BadCall naming `what` for null or empty text, or text longer
// than 4096 characters (an unterminated buffer).
std::string text_of_c_or_wide(const void* p, const std::string& what);

// Two-call string output: with `out` null, *count = the wide characters `text` needs with its
// terminator; else copies at most *count of them (terminated) and sets *count to what was
// written. BadCall when `count` is null or not positive with a buffer.
void write_wide(const std::string& text, int* count, wchar_t* out);

// `text` as UTF-32 wchar_t (ASCII is all lfd writes; other bytes pass through as themselves).
std::wstring widen(const std::string& text);

}  // namespace lfd::bridge
