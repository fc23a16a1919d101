// regress/open-* files reproduce bugs not fixed yet: they are left out of the corpus replay (which
// must pass) and checked here instead, through the same decoders and checks as the fuzz targets
// (verify::replay, every check on): each must still fail. One that passes means its bug is fixed:
// drop the open- prefix so the replay holds it from then on.
// Usage: geodex_corpus_open_findings CORPUS_DIR

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <vector>

#include "geodex/verify/repro.h"

int main(int argc, char** argv) {
  using namespace geodex::verify;
  if (argc != 2) {
    std::cerr << "usage: " << argv[0] << " CORPUS_DIR\n";
    return 2;
  }
  int open = 0, fixed = 0;
  for (FuzzTarget t : kFuzzTargets) {
    const auto dir = std::filesystem::path(argv[1]) / name(t) / "regress";
    if (!std::filesystem::exists(dir)) continue;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().filename().string().starts_with("open-")) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      ++open;
      const Verdict v = replay(t, readFileBytes(f.string()));
      if (v.interesting && !v.ok()) {
        std::cout << "still open: " << f.string() << ": fails '" << v.failed << "'\n";
      } else {
        std::cout << "FIXED? " << f.string() << " now passes (" << v.summary
                  << "): drop the open- prefix from its name\n";
        ++fixed;
      }
    }
  }
  std::cout << open << " open finding(s), " << fixed << " of them passing now\n";
  return fixed == 0 ? 0 : 1;
}
