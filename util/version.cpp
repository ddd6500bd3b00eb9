#include "util/version.hpp"

#include "lfd_version_info.hpp"  // generated: LFD_VERSION_STRING, LFD_GIT_COMMIT, LFD_BUILD_DATE

namespace lfd {

const VersionInfo& version_info() {
  static const VersionInfo info{LFD_VERSION_STRING, LFD_GIT_COMMIT, LFD_BUILD_DATE};
  return info;
}

std::string version_line() {
  const VersionInfo& v = version_info();
  return "lfd " + v.version + " (commit " + v.commit + ", built " + v.build_date + ")";
}

}  // namespace lfd
