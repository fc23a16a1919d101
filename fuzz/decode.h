#pragma once
// What every fuzz target shares: turning libFuzzer's bytes into a case and a failed check into a
// finding. The byte layouts, decoders and property checks themselves live in verify/, one header
// per target in verify/include/geodex/verify/cases/ (layout summary in docs/fuzzing.md), so that
// `geodex repro FILE` and tests/corpus replay a corpus file exactly as the fuzzer ran it. The
// bytes are read with verify's ByteReader rather than FuzzedDataProvider (cases/byte_codec.h says
// why).

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <span>
#include <string>
#include <variant>

#include "geodex/verify/repro.h"

namespace geodex::fuzz {

using verify::FuzzTarget;

inline std::span<const std::uint8_t> bytesOf(const std::uint8_t* data, std::size_t size) {
  return {data, size};
}

/// The case the target tests in these bytes, or nullopt for input it skips (input size is capped
/// by the decoders: kMaxFuzzInputBytes, kMaxMeshIoInputBytes; mesh size by kMaxFuzzFaces).
template <typename Case>
std::optional<Case> decodeAs(FuzzTarget t, const std::uint8_t* data, std::size_t size) {
  auto c = verify::decode(t, bytesOf(data, size));
  if (!c) return std::nullopt;
  return std::get<Case>(std::move(*c));
}

/// Whether the environment asks to let this check's failures pass: GEODEX_FUZZ_SKIP_CHECKS is a
/// comma-separated list of check names (e.g. "path-length,pointwise-min"), for fuzzing on past a
/// known open bug (corpus/<target>/regress/open-*) to find the next one. Unset in CTest.
/// GEODEX_FUZZ_ONLY_CHECKS, the opposite: only these checks' failures are findings (scripts/fuzz.sh
/// minimizes a crash with it, so that the minimized input still fails the same check).
inline bool listed(const char* variable, const std::string& check) {
  const char* env = std::getenv(variable);
  if (env == nullptr || *env == '\0') return false;
  const std::string list = std::string(",") + env + ",";
  return list.find("," + check + ",") != std::string::npos;
}
inline bool skipped(const std::string& check) {
  const char* only = std::getenv("GEODEX_FUZZ_ONLY_CHECKS");
  if (only != nullptr && *only != '\0' && !listed("GEODEX_FUZZ_ONLY_CHECKS", check)) return true;
  return listed("GEODEX_FUZZ_SKIP_CHECKS", check);
}

/// A failed check is a finding: print the check, what broke and the case, then abort so that
/// libFuzzer saves the input (the replay main reports the file).
inline void require(const verify::Verdict& v, FuzzTarget t, const std::uint8_t* data, std::size_t size) {
  if (v.ok() || skipped(v.failed)) return;
  std::cerr << "\n=== " << verify::name(t) << ": check '" << v.failed << "' failed\n"
            << v.message << "\n=== the case:\n";
  verify::describe(t, bytesOf(data, size), std::cerr);
  std::cerr << "=== reproduce with: geodex repro FILE --target " << verify::name(t) << "\n";
  std::cerr.flush();
  std::abort();
}

}  // namespace geodex::fuzz
