#pragma once
// GEODEX_RC_GTEST_PROP: RapidCheck's RC_GTEST_PROP, running `weight` × RC_PARAMS's max_success
// cases. The suite's budget (RC_PARAMS max_success, one seed) is set by the whole-solve
// properties, which cost milliseconds per case; the local properties (one Fig. 6 decision, one
// Algorithm 2 run) cost microseconds and get more cases in the same time. Everything else —
// the seed, shrinking, RC_PARAMS="reproduce=…" (keyed by "Suite/Name" as RC_GTEST_PROP does),
// the printed distribution — is RapidCheck's own.

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <iostream>
#include <sstream>

namespace geodex::proptest {

/// The weight of the local (one-decision, one-edge) properties.
inline constexpr int kLocalPropertyWeight = 10;

template <typename Testable>
void checkGTestWeighted(Testable&& testable, int weight) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  rc::detail::TestMetadata metadata;
  metadata.id = std::string(info->test_case_name()) + "/" + std::string(info->name());
  metadata.description = std::string(info->name());
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  params.maxSuccess *= weight;
  const auto result = rc::detail::checkProperty(
      rc::detail::toProperty(std::forward<Testable>(testable)), metadata, params);
  if (result.template is<rc::detail::SuccessResult>()) {
    const auto success = result.template get<rc::detail::SuccessResult>();
    if (!success.distribution.empty()) {
      rc::detail::printResultMessage(result, std::cout);
      std::cout << std::endl;
    }
  } else {
    std::ostringstream ss;
    rc::detail::printResultMessage(result, ss);
    FAIL() << ss.str() << std::endl;
  }
}

}  // namespace geodex::proptest

#define GEODEX_RC_GTEST_PROP(TestCase, Name, Weight, ArgList)                                   \
  void rapidCheck_propImpl_##TestCase##_##Name ArgList;                                         \
  TEST(TestCase, Name) {                                                                        \
    ::geodex::proptest::checkGTestWeighted(&rapidCheck_propImpl_##TestCase##_##Name, (Weight)); \
  }                                                                                             \
  void rapidCheck_propImpl_##TestCase##_##Name ArgList
