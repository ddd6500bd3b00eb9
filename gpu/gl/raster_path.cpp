#include "gpu/gl/raster_path.hpp"

#include "util/error.hpp"

namespace lfd::gpu {

const char* raster_path_name(RasterPath path) {
  switch (path) {
    case RasterPath::kHardware: return "hardware";
    case RasterPath::kCompute: return "compute";
    case RasterPath::kAuto: return "auto";
  }
  return "hardware";
}

RasterPath parse_raster_path(std::string_view name) {
  if (name == "hardware") return RasterPath::kHardware;
  if (name == "compute") return RasterPath::kCompute;
  if (name == "auto") return RasterPath::kAuto;
  throw_input_error("--raster: '{}' is not compute, hardware or auto", name);
}

}  // namespace lfd::gpu
