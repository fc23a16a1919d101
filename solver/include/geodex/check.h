#pragma once
// One check macro, in cost tiers (STYLE.md). No bare assert in solver/: a release build must not
// silently skip the check that stood between bad input and a wrong answer.
//
//  GEODEX_REQUIRE(cond, msg)  always on: preconditions on user input and API misuse.
//  GEODEX_CHECK(cond, msg)    cheap internal invariants; compiled in debug, asan and fuzz builds
//                             (GEODEX_CHECKS=ON), compiled out of release.
// The expensive tier (full Algorithm-2 step-6 verification, pointwise-min sampling) lives in
// verify/ behind a run-time switch, attached to the solver as an observer.

#include <sstream>
#include <stdexcept>
#include <string>

namespace geodex {

/// Thrown when an internal invariant fails: a bug in geodex, never the user's fault.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

[[noreturn]] void failCheck(const char* expr, const std::string& message, const char* file,
                            int line);

}  // namespace geodex

#define GEODEX_REQUIRE(cond, msg)                                           \
  do {                                                                      \
    if (!(cond)) [[unlikely]] {                                             \
      std::ostringstream geodex_os_;                                        \
      geodex_os_ << msg;                                                    \
      ::geodex::failCheck(#cond, geodex_os_.str(), __FILE__, __LINE__);     \
    }                                                                       \
  } while (false)

#if defined(GEODEX_ENABLE_CHECKS)
#define GEODEX_CHECK(cond, msg) GEODEX_REQUIRE(cond, msg)
#else
#define GEODEX_CHECK(cond, msg) \
  do {                          \
  } while (false)
#endif
