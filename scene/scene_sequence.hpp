#pragma once
// Animated scenes ("4D" splats; docs/record.md "Scenes that move"): a scene given as a sequence
// of frames, each an ordinary scene file of any format lfd reads (scene::load_scene), played at
// a frame rate. The sequence is named by
//   a pattern    `monkey_%04d.sog` (printf's %d or %0Nd): the frames numbered from the lowest
//                number present upward, with no gaps;
//   a folder     its scene files in name order;
//   a list file  `frames.txt`: one path per line (relative to the list's folder; blank lines
//                and lines starting with # skipped).
// Only the file names are found here; the frames are read one at a time by whoever plays them.
#include <filesystem>
#include <string>
#include <vector>

namespace lfd::scene {

struct SceneSequence {
  std::string source;                         // what the user named
  std::vector<std::filesystem::path> frames;  // at least one, in order
};

// True when `spec` names a sequence: a pattern with %d, a folder, or a .txt list file.
bool is_scene_sequence(const std::string& spec);

// The frames of `spec`. InputError naming `spec` (and the line of a list) when it holds no
// frame, a numbered frame is missing between the lowest and the highest ("frame 3
// (monkey_0003.sog) is missing"), two files are one frame (`%d`: m_7 and m_007), or a listed
// file does not exist.
SceneSequence find_scene_sequence(const std::string& spec);

}  // namespace lfd::scene
