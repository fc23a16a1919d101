// GoogleTest main. In debug builds floating-point traps are on (libigl's test main does the same),
// so a NaN or an overflow is caught where it is born instead of surfacing as a wrong distance.
#include <gtest/gtest.h>

#if defined(GEODEX_FPE_TRAPS) && defined(__linux__)
#include <cfenv>
#endif

int main(int argc, char** argv) {
#if defined(GEODEX_FPE_TRAPS) && defined(__linux__)
  feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
#endif
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
