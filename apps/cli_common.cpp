#include "cli_common.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <iostream>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "geodex/error.h"
#include "geodex/mesh_io.h"

namespace geodex::cli {

unsigned defaultThreads() { return std::thread::hardware_concurrency() >= 2 ? 2 : 1; }

void checkThreads(unsigned threads) {
  if (threads < 1) throw InputError("usage", "--threads must be 1 or more, not 0");
}

void addThreadsOption(CLI::App* sub, unsigned& threads) {
  sub->add_option("--threads", threads,
                  "Threads for the wavefront, 1 or 2 (more count as 2; default 2 on a machine "
                  "with two cores or more): the results are the same to the bit")
      ->type_name("N");
}

Mesh loadMeshWithWarnings(const std::string& path, std::size_t maxWarnings) {
  std::vector<MeshIssue> warnings;
  Mesh mesh = loadMesh(path, &warnings);
  for (std::size_t i = 0; i < warnings.size() && i < maxWarnings; ++i) {
    std::cerr << "warning: " << warnings[i].message << '\n';
  }
  if (warnings.size() > maxWarnings) {
    std::cerr << "warning: " << (warnings.size() - maxWarnings)
              << " more warnings (`geodex info " << path << "` lists all)\n";
  }
  return mesh;
}

std::vector<SurfacePoint> parseSurfacePoints(const std::vector<std::string>& specs,
                                             const std::string& optionName) {
  std::vector<SurfacePoint> points;
  points.reserve(specs.size());
  for (const std::string& spec : specs) {
    try {
      points.push_back(parseSurfacePoint(spec));
    } catch (const InputError& e) {
      // Say which option the bad spec came from; parseSurfacePoint already names the spec.
      throw InputError(e.kind(), optionName + ": " + e.what());
    }
  }
  return points;
}

void checkPointsOnMesh(const Mesh& mesh, const std::vector<SurfacePoint>& points,
                       const std::string& optionName) {
  for (const SurfacePoint& p : points) {
    try {
      resolve(mesh, p);
    } catch (const InputError& e) {
      const std::string spec = formatSurfacePoint(p);
      const std::string message = e.what();
      // Name the option, and the point unless the message already does.
      const std::string prefix = message.find(spec) == std::string::npos
                                     ? optionName + " " + spec + ": "
                                     : optionName + ": ";
      throw InputError(e.kind(), prefix + message);
    }
  }
}

std::string formatDistance(double d) {
  if (std::isinf(d) && d > 0) return "inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", d);
  return buffer;
}

// ===  OutputFile ================================================================================

namespace {

std::string systemMessage(int errnum) { return std::strerror(errnum); }

}  // namespace

OutputFile::OutputFile(const std::string& path) : path_(path) {
  if (path_.empty()) {
    file_ = stdout;
    return;
  }
  // mkstemp in the target's directory, so rename() is atomic (same file system).
  std::string pattern = path_ + ".tmp.XXXXXX";
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0) {
    throw InputError("output", "cannot create output file '" + path_ + "': " +
                                   systemMessage(errno));
  }
  tempPath_ = pattern;
  // mkstemp creates 0600; give the result the permissions a plain fopen would (0666 & ~umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  file_ = ::fdopen(fd, "w");
  if (file_ == nullptr) {
    const int err = errno;
    ::close(fd);
    ::unlink(tempPath_.c_str());
    throw InputError("output", "cannot write output file '" + path_ + "': " + systemMessage(err));
  }
  std::setvbuf(file_, nullptr, _IOFBF, 1 << 16);
}

OutputFile::~OutputFile() {
  if (file_ == nullptr || file_ == stdout) return;
  std::fclose(file_);
  if (!committed_) ::unlink(tempPath_.c_str());
}

void OutputFile::commit() {
  if (file_ == stdout) {
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
      throw InputError("output", "cannot write to standard output: " + systemMessage(errno));
    }
    committed_ = true;
    return;
  }
  const bool writeFailed = std::fflush(file_) != 0 || std::ferror(file_);
  const int writeErrno = errno;
  const bool closeFailed = std::fclose(file_) != 0;
  const int closeErrno = errno;
  file_ = nullptr;
  if (writeFailed || closeFailed) {
    ::unlink(tempPath_.c_str());
    throw InputError("output", "cannot write output file '" + path_ + "': " +
                                   systemMessage(writeFailed ? writeErrno : closeErrno));
  }
  if (std::rename(tempPath_.c_str(), path_.c_str()) != 0) {
    const int err = errno;
    ::unlink(tempPath_.c_str());
    throw InputError("output", "cannot rename output into place as '" + path_ + "': " +
                                   systemMessage(err));
  }
  committed_ = true;
}

}  // namespace geodex::cli
