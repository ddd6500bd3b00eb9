#include "util/error.hpp"

namespace lfd {

void require_field(bool ok, const std::string& file, const std::string& field,
                   const std::string& message) {
  if (!ok) throw InputError(fmt::format("{}: {}: {}", file, field, message));
}

}  // namespace lfd
