#pragma once
// `lfd calibrate --live` on real hardware: the live loop (live/live_calibration.hpp) with a
// full-screen PatternWindow on the display's monitor and a VideoCaptureSource camera. With
// one physical camera, the user is asked on the console to move it between positions
// (--positions N), with the board on screen to aim at.
#include "live/live_calibration.hpp"

namespace lfd::live {

// Checks before anything opens (intrinsics or >= 3 positions), then finds the monitor
// ("no display: ..." without an X server), opens the camera (InputError naming the index)
// and the window, and runs the loop. Camera settings the backend refuses are warned about on
// stderr as they happen (a round that fails may fail because of them).
calib::CalibrationOutcome run_live_calibration_on_hardware(const display::Calibration& nominal,
                                                    const LiveOptions& options);

}  // namespace lfd::live
