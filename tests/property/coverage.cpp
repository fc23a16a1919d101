#include "coverage.h"

#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

namespace geodex::proptest {
namespace {

using Table =
    std::array<std::array<std::uint64_t, static_cast<std::size_t>(CoverageSource::kCount)>,
               kNumDegeneracyKinds>;

Table& table() {
  static Table t{};
  return t;
}

std::uint64_t& cell(DegeneracyKind k, CoverageSource s) {
  return table()[static_cast<std::size_t>(k)][static_cast<std::size_t>(s)];
}

std::map<std::string, double>& accuracy() {
  static std::map<std::string, double> a;
  return a;
}

void add(const DegeneracyCounters& c, CoverageSource s) {
  for (std::size_t k = 0; k < kNumDegeneracyKinds; ++k)
    cell(static_cast<DegeneracyKind>(k), s) += c.count[k];
}

// Why the gate should not judge this run ("" if it should).
std::string reasonNotToJudge() {
  if (const char* force = std::getenv("GEODEX_COVERAGE_GATE");
      force != nullptr && std::strcmp(force, "force") == 0)
    return "";
  const std::string filter = GTEST_FLAG_GET(filter);
  if (filter != "*") return "only the tests matching --gtest_filter=" + filter + " ran";
  if (!rc::detail::configuration().reproduce.empty())
    return "RapidCheck is replaying failures (RC_PARAMS=reproduce=...)";
  return "";
}

}  // namespace

void recordLocal(Fig6Branch branch) {
  if (const auto kind = degeneracyOf(branch)) ++cell(*kind, CoverageSource::Local);
}
void recordAlgorithm2(const DegeneracyCounters& counters) {
  add(counters, CoverageSource::Algorithm2);
}
void recordSolve(const DegeneracyCounters& counters) { add(counters, CoverageSource::Solve); }

void recordAccuracy(const char* check, double relativeError) {
  double& worst = accuracy()[check];
  worst = std::max(worst, relativeError);
}

std::uint64_t coverageCount(DegeneracyKind kind, CoverageSource source) {
  return cell(kind, source);
}

void CoverageGate::SetUp() {
  table() = {};
  accuracy().clear();
}

void CoverageGate::TearDown() {
  std::printf(
      "\n[ coverage ] degenerate cases reached by this run (gate: each of G1-G5, D1-D4 >= %llu)\n",
      static_cast<unsigned long long>(kMinHitsPerCase));
  std::printf("[ coverage ] %-5s %12s %12s %12s %12s\n", "case", "local", "algorithm2", "solves",
              "total");
  std::string missing;
  for (std::size_t k = 0; k < kNumDegeneracyKinds; ++k) {
    const auto kind = static_cast<DegeneracyKind>(k);
    const auto& row = table()[k];
    const std::uint64_t total = row[0] + row[1] + row[2];
    std::printf("[ coverage ] %-5s %12llu %12llu %12llu %12llu%s\n",
                std::string(name(kind)).c_str(), static_cast<unsigned long long>(row[0]),
                static_cast<unsigned long long>(row[1]), static_cast<unsigned long long>(row[2]),
                static_cast<unsigned long long>(total),
                total < kMinHitsPerCase ? "   <-- below the gate" : "");
    if (total < kMinHitsPerCase) missing += (missing.empty() ? "" : ", ") + std::string(name(kind));
  }
  for (const auto& [check, worst] : accuracy())
    std::printf("[ accuracy ] %-40s worst error %.3g x bbox diagonal\n", check.c_str(), worst);
  std::fflush(stdout);
  const std::string reason = reasonNotToJudge();
  if (!reason.empty()) {
    std::printf("[ coverage ] gate not judged: %s\n", reason.c_str());
    return;
  }
  if (missing.empty()) {
    std::printf("[ coverage ] gate passed\n");
    return;
  }
  ADD_FAILURE() << "CoverageGate: " << missing << " reached fewer than " << kMinHitsPerCase
                << " times by the property suite's generators (table above). A generator no "
                   "longer reaches the case it is named after: fix the generator, do not lower "
                   "the gate.";
}

}  // namespace geodex::proptest
