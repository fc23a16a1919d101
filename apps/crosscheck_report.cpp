#include "crosscheck_report.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_common.h"
#include "geodex/error.h"
#include "render/distance_render.h"
#include "render/png_writer.h"

namespace geodex::cli {

namespace {

// The picture: small enough to open in a CI artifact list, large enough to see a 2-face case.
constexpr int kPictureWidth = 800, kPictureHeight = 600;
/// A mesh whose z extent is at most this × its diagonal is drawn from above (+z), else from the
/// render command's default direction.
constexpr double kFlatExtentRel = 1e-6;

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.flush();
  if (!out) throw InputError("output", "cannot write '" + path + "'");
}

std::string formatTolerance(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

std::string distancesText(std::span<const double> d) {
  std::string text;
  for (double x : d) text += formatDistance(x) + "\n";
  return text;
}

std::string indent(const std::string& text, std::size_t maxLines = 200) {
  std::istringstream in(text);
  std::string out, line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    if (++n > maxLines) {
      out += "  … (" + std::to_string(maxLines) + " lines shown)\n";
      break;
    }
    out += "  " + line + "\n";
  }
  return out.empty() ? "  (nothing)\n" : out;
}

void writeWorstVertices(std::ostream& r, const Trial& t) {
  if (t.judgement.worst.empty()) return;
  r << "worst vertices (vertex: expected, got, |got − expected|, that over the largest distance):\n";
  for (const verify::VertexError& w : t.judgement.worst) {
    r << "  " << w.vertex << ": " << formatDistance(w.expected) << ", " << formatDistance(w.got) << ", "
      << formatDistance(w.error);
    if (t.judgement.largestDistance > 0.0 && std::isfinite(w.error)) r << ", " << w.error / t.judgement.largestDistance;
    r << "\n";
  }
}

std::string reportText(const Trial& t, const FindingOrigin& origin, const CaseRunner& runner) {
  std::ostringstream r;
  r.precision(17);
  const auto kindName = std::string(verify::name(*t.kind));
  r << "geodex crosscheck finding: " << kindName << "\n"
    << "what: " << t.judgement.what << "\n\n"
    << "case: " << origin.caseLabel << "\n"
    << "family: " << t.c.family << "\n"
    << "made by: " << t.c.recipe << "\n"
    << "minimized: " << origin.originalFaces << " faces, " << origin.originalVertices << " vertices -> "
    << t.c.soup.faces.size() << " faces, " << t.c.soup.positions.size() << " vertices in " << origin.trials
    << " trials (the same kind of finding at every step, no kind of mesh defect the case did not have)"
    << (origin.stoppedBy.empty() ? "" : "; stopped early by the " + origin.stoppedBy + " budget") << "\n"
    << "source: vertex " << t.c.source << " (0-based; source.txt)\n"
    << "before minimizing: original.off, source vertex " << origin.originalSource << "\n"
    << "tolerance: " << formatTolerance(runner.tolerance()) << " × the largest distance";
  double largest = 0.0;
  for (double d : t.reference.distances)
    if (std::isfinite(d)) largest = std::max(largest, d);
  r << " (" << largest << " here)\n\n";
  writeWorstVertices(r, t);
  if (!t.judgement.oracles.empty()) {
    r << "independent oracles on got.txt (relative tolerance max(--tolerance, " << formatTolerance(verify::kOracleRel)
      << ")):\n";
    for (const std::string& line : t.judgement.oracles) r << "  " << line << "\n";
  }
  r << "degeneracies the case exercises (counted by geodex's solve of this mesh):\n";
  for (const std::string& e : t.reference.exercised) r << "  " << e << "\n";
  if (t.reference.exercised.empty()) r << "  (none)\n";
  r << "\ncommand: " << t.command << "\n"
    << "ended: " << t.run.describe(runner.timeLimit()) << "\n"
    << "output file: " << (t.outputFileWritten ? std::to_string(t.outputFile.size()) + " bytes (got.txt)" : "not written")
    << "\n"
    << "what it printed (stdout and stderr" << (t.run.outputTruncated ? ", cut" : "") << "):\n"
    << indent(t.run.output) << "\n"
    << "replay, in this directory:\n  " << fillCommandTemplate(runner.commandTemplate(), "mesh.off", t.c.source, "got-again.txt")
    << "\n"
    << "picture.png: " << (t.judgement.error.empty()
                                ? "geodex's distances (no distances to compare), the source as a white disc"
                                : "|got − expected| per vertex where beyond the tolerance (viridis, 0 dark blue to the "
                                  "largest yellow; grey where one side says unreachable), the source a white disc, the "
                                  "worst vertex a red disc")
    << "\n";
  return r.str();
}

void writePicture(const std::string& path, const Trial& t) {
  const Mesh mesh(t.c.soup);
  render::RenderSettings settings;
  settings.width = kPictureWidth;
  settings.height = kPictureHeight;
  double zMin = INFINITY, zMax = -INFINITY;
  for (const Vec3& p : t.c.soup.positions) zMin = std::min(zMin, p.z()), zMax = std::max(zMax, p.z());
  if (zMax - zMin <= kFlatExtentRel * mesh.boundingBoxDiagonal()) settings.azimuthDeg = settings.elevationDeg = 0.0;

  const std::vector<Vec3> sources{mesh.position(t.c.source)};
  render::RenderMarks marks;
  marks.sources = sources;
  std::span<const double> field = t.reference.distances;
  std::vector<double> beyondTolerance;
  if (!t.judgement.error.empty()) {
    // Errors within the tolerance are drawn as none: scaled to the largest of them, rounding
    // noise would fill the colour range when the finding is only an unreachable vertex.
    for (double e : t.judgement.error) beyondTolerance.push_back(e > t.judgement.allowed ? e : 0.0);
    field = beyondTolerance;
    settings.isolineCount = 0;  // isolines of an error field would only add noise
    if (!t.judgement.worst.empty()) marks.target = mesh.position(t.judgement.worst.front().vertex);
  }
  OutputFile out(path);
  render::writePng(out.get(), render::renderDistanceField(mesh, field, marks, settings), path);
  out.commit();
}

}  // namespace

void writeFinding(const std::string& dir, const Trial& t, const FindingOrigin& origin, const CaseRunner& runner) {
  std::error_code error;
  if (!std::filesystem::create_directories(dir, error)) {
    throw InputError("output", "cannot create the finding directory '" + dir + "'" +
                                   (error ? ": " + error.message() : ": it exists already"));
  }
  writeFile(dir + "/mesh.off", verify::offText(t.c.soup));
  writeFile(dir + "/source.txt", std::to_string(t.c.source) + "\n");
  writeFile(dir + "/expected.txt", distancesText(t.reference.distances));
  writeFile(dir + "/got.txt", t.outputFile);
  writeFile(dir + "/report.txt", reportText(t, origin, runner));
  writeFile(dir + "/original.off", verify::offText(origin.originalSoup));
  writePicture(dir + "/picture.png", t);
}

}  // namespace geodex::cli
