// make_seeds: writes corpus/<target>/seed/ (and the regress files that can be described) from the
// readable descriptions each target keeps beside its format and check: predicateSeeds() in
// verify/src/cases/fuzz_predicates.cpp, and so on for every target (verify::seeds). Every file is
// checked before it is written: it decodes into a case its target tests, passes every check, and
// is what its name says (the Fig. 6 branch, the D-kinds, the reader's verdict, …).
//
//   make_seeds CORPUS_DIR           (re)writes CORPUS_DIR/<target>/seed/*
//   make_seeds --check CORPUS_DIR   verifies the committed seeds are exactly this output
//
// To add or change a seed, edit its target's seeds() and run make_seeds on corpus/.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "geodex/verify/repro.h"

namespace {

using namespace geodex::verify;

/// A target's seed, to write to corpus/<target>/<dir>/<name>.
struct TargetSeed {
  FuzzTarget target;
  Seed seed;
};

/// "" when the seed is what it should be, else why not.
std::string validate(FuzzTarget t, const Seed& s) {
  const auto c = decode(t, s.bytes);
  if (s.refusedNow) return c ? "the target no longer skips it: the input is accepted again" : "";
  if (!c) return "the target skips it";
  const Verdict v = check(*c);
  if (!s.openCheck.empty()) {
    // Any failure keeps it open: without GEODEX_CHECKS (release) an internal check's bug shows as
    // the invariant it breaks next instead.
    if (v.ok()) return "passes now: the bug is fixed; drop the open- prefix";
    return "";
  }
  if (!v.ok()) return "check '" + v.failed + "' fails: " + v.message;
  return s.expect ? s.expect(*c, v) : "";
}

std::vector<std::uint8_t> readAll(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const bool checkOnly = argc == 3 && std::string(argv[1]) == "--check";
  if (!(argc == 2 || checkOnly) || (argc == 2 && argv[1][0] == '-')) {
    std::cerr << "usage: make_seeds [--check] CORPUS_DIR\n";
    return 2;
  }
  const fs::path corpus = argv[argc - 1];
  std::vector<TargetSeed> all;
  for (FuzzTarget t : kFuzzTargets)
    for (Seed& s : seeds(t)) all.push_back({t, std::move(s)});

  int problems = 0;
  std::set<std::string> names;
  std::map<FuzzTarget, int> perTarget;
  for (const auto& [t, s] : all) {
    const std::string id = std::string(name(t)) + "/" + s.dir + "/" + s.name;
    if (!names.insert(id).second) {
      std::cerr << id << ": named twice\n";
      ++problems;
    }
    if (const std::string why = validate(t, s); !why.empty()) {
      std::cerr << id << ": " << why << "\n";
      ++problems;
    }
    if (s.dir == "seed") ++perTarget[t];
  }
  if (checkOnly) {
    for (const auto& [t, s] : all) {
      const fs::path p = corpus / name(t) / s.dir / s.name;
      if (!fs::exists(p)) {
        std::cerr << p.string() << ": missing (run make_seeds " << corpus.string() << ")\n";
        ++problems;
      } else if (readAll(p) != s.bytes) {
        std::cerr << p.string() << ": differs from its description (run make_seeds " << corpus.string() << ")\n";
        ++problems;
      }
    }
    for (FuzzTarget t : kFuzzTargets) {
      const fs::path dir = corpus / name(t) / "seed";
      if (!fs::exists(dir)) continue;
      for (const auto& e : fs::directory_iterator(dir))
        if (!names.count(std::string(name(t)) + "/seed/" + e.path().filename().string())) {
          std::cerr << e.path().string() << ": not made by make_seeds (describe it in its target's seeds(), or move it to regress/)\n";
          ++problems;
        }
    }
  } else if (problems == 0) {
    for (const auto& [t, s] : all) {
      const fs::path dir = corpus / name(t) / s.dir;
      fs::create_directories(dir);
      std::ofstream out(dir / s.name, std::ios::binary);
      out.write(reinterpret_cast<const char*>(s.bytes.data()), static_cast<std::streamsize>(s.bytes.size()));
    }
  }
  for (const auto& [t, count] : perTarget) std::cout << name(t) << ": " << count << " seeds\n";
  if (problems != 0) {
    std::cerr << problems << " problem(s)" << (checkOnly ? "" : "; nothing written") << "\n";
    return 1;
  }
  std::cout << (checkOnly ? "every seed is up to date and hits its case\n" : "seeds written\n");
  return 0;
}
