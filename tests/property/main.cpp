// The property suite's main: tests/test_main.cpp plus the coverage gate, registered here rather
// than from a static initializer so that it certainly exists before RUN_ALL_TESTS.
// Floating-point traps are on in debug builds, as in the unit tests: a NaN is caught where it is
// born, not as a failed comparison later.
#include <gtest/gtest.h>

#if defined(GEODEX_FPE_TRAPS) && defined(__linux__)
#include <cfenv>
#endif

#include "coverage.h"

int main(int argc, char** argv) {
#if defined(GEODEX_FPE_TRAPS) && defined(__linux__)
  feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
#endif
  ::testing::InitGoogleTest(&argc, argv);
  ::testing::AddGlobalTestEnvironment(new geodex::proptest::CoverageGate);
  return RUN_ALL_TESTS();
}
