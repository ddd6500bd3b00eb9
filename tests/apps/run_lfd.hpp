#pragma once
// Forwards to the shared CLI runner (tests/support/run_lfd.hpp) for the test files that still
// include it here (tests/gpu/, which is moving); new tests include tests/support/run_lfd.hpp.
#include "tests/support/run_lfd.hpp"
