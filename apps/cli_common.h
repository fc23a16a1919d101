#pragma once
// Pieces the `geodex` subcommands share: exit codes, mesh loading with warnings on stderr,
// parsing SPEC lists, the --threads option, number formatting, and output files that appear whole
// or not at all.

#include <cstdio>
#include <string>
#include <vector>

#include "geodex/mesh.h"
#include "geodex/surface_point.h"

namespace CLI {
class App;
}

namespace geodex::cli {

/// The tool's exit codes (documented in README.md and `geodex --help`).
enum ExitCode : int {
  kExitOk = 0,
  kExitCheckFailed = 1,  ///< a check found a problem (`check`), or `crosscheck` found the program wrong
  kExitBadInput = 2,     ///< bad input or usage; "error: …" on stderr
  kExitInternal = 3,     ///< a bug in geodex (an internal check failed); "internal error: …"
};

/// geodex::loadMesh, printing its warnings to stderr as "warning: …" (at most `maxWarnings`,
/// then a count of the rest). Throws InputError naming file, line and element.
Mesh loadMeshWithWarnings(const std::string& path, std::size_t maxWarnings = 20);

/// parseSurfacePoint for each spec (throws InputError naming the spec and the option).
std::vector<SurfacePoint> parseSurfacePoints(const std::vector<std::string>& specs,
                                             const std::string& optionName);

/// geodex::resolve for each point, so that a point outside the mesh is reported before the solve
/// and with the option it came from. Throws InputError.
void checkPointsOnMesh(const Mesh& mesh, const std::vector<SurfacePoint>& points,
                       const std::string& optionName);

/// `--threads N` on a solving subcommand, into `threads`; its default, defaultThreads(): 2 where
/// the machine runs two threads at once, else 1 (the results are the same to the bit).
/// checkThreads refuses 0 (InputError "usage").
void addThreadsOption(CLI::App* sub, unsigned& threads);
unsigned defaultThreads();
void checkThreads(unsigned threads);

/// `%.17g`, or "inf" for +inf (unreachable). Round-trips through strtod.
std::string formatDistance(double d);

/// Writes to stdout, or to a temporary file beside `path` that is renamed onto `path` by
/// commit(), so that a failure never leaves partial output (nor clobbers an existing file).
class OutputFile {
 public:
  /// Empty path: stdout. Throws InputError when the temporary file cannot be created.
  explicit OutputFile(const std::string& path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::FILE* get() const { return file_; }
  /// Flushes and checks for write errors; for a file, renames it into place. Throws InputError.
  void commit();

 private:
  std::string path_;
  std::string tempPath_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

}  // namespace geodex::cli
