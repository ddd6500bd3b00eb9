#pragma once
// The RGB-D options of the command line, shared by `lfd play` and `lfd rgbd-quilt`
// (docs/rgbd.md): a bridge.js settings file, then one flag per bridge.js key over it.
#include <string>

#include <CLI/CLI.hpp>

#include "rgbd/rgbd_options.hpp"

namespace lfd::apps {

struct RgbdFlags {
  std::string settings, depth_loc, depthiness, focus, zoom, crop_x, crop_y, cutoff;
  bool inversion = false, chroma = false;

  // Adds the flags to `app`; `settings_flag` names the settings file's option and `help_prefix`
  // starts each flag's help ("RGB-D: " where the command plays other files too).
  void add(CLI::App& app, const std::string& settings_flag, const std::string& help_prefix = "");
  // A settings file or any flag was given.
  bool any() const;
  // The settings file's options with the flags over them; InputError naming the file or key.
  rgbd::RgbdOptions options() const;
};

}  // namespace lfd::apps
