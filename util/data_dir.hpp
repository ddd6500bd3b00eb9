#pragma once
// Where the program finds its bundled data (display templates, the demo scene, calibrations),
// the first of:
//   1. $LFD_DATA_DIR, when set;
//   2. <folder of the executable>/../share/lfd: the installed layout (`cmake --install`, the
//      .deb), relative to the executable so an installed tree can be moved anywhere;
//   3. the source tree's data/, for a program run from its build folder;
//   4. <install prefix>/share/lfd as configured, for other programs linking the libraries.
// Only existing folders count, except that $LFD_DATA_DIR is taken as given; when none exists
// the result is the source tree's folder, so that messages name the place data was expected.
#include <filesystem>

namespace lfd {

std::filesystem::path data_dir();

}  // namespace lfd
