#include "crosscheck_trial.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "geodex/error.h"

namespace geodex::cli {

namespace {

/// A program's output file bigger than this is not read whole: at 64 bytes a line it is far
/// beyond any mesh crosscheck makes or loads.
constexpr std::size_t kMaxOutputFileBytes = std::size_t{1} << 30;

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.flush();
  if (!out) throw InputError("output", "cannot write '" + path + "'");
}

/// The whole file, or nullopt when there is none.
std::optional<std::string> readWhole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  std::string s = std::move(text).str();
  if (s.size() > kMaxOutputFileBytes) s.resize(kMaxOutputFileBytes);
  return s;
}

}  // namespace

CaseRunner::CaseRunner(std::string commandTemplate, double timeLimitSeconds, double tolerance, std::string workDir)
    : template_(std::move(commandTemplate)),
      timeLimit_(timeLimitSeconds),
      tolerance_(tolerance),
      meshPath_(workDir + "/mesh.off"),
      outPath_(workDir + "/got.txt"),
      capturePath_(workDir + "/output.txt") {}

Trial CaseRunner::run(const verify::CrossCheckCase& c) const {
  Trial t;
  t.c = c;
  t.reference = verify::referenceDistances(c);
  if (t.skipped()) return t;

  writeText(meshPath_, verify::offText(c.soup));
  // A stale file from the previous case must never be read as this one's output.
  std::remove(outPath_.c_str());
  t.command = fillCommandTemplate(template_, meshPath_, c.source, outPath_);
  t.run = runProgram(t.command, timeLimit_, capturePath_);
  const std::optional<std::string> written = readWhole(outPath_);
  t.outputFileWritten = written.has_value();
  t.outputFile = written.value_or("");

  if (t.run.timedOut) {
    t.kind = verify::FindingKind::Timeout;
    t.judgement.what = t.run.describe(timeLimit_);
  } else if (t.run.failed()) {
    t.kind = verify::FindingKind::Crash;
    t.judgement.what = t.run.describe(timeLimit_);
  } else {
    t.got = verify::parseDistances(t.outputFile);
    t.judgement = verify::judgeDistances(c, t.reference, t.got, tolerance_);
    t.kind = t.judgement.kind;
    if (!t.outputFileWritten) t.judgement.what = "no output file was written (" + t.judgement.what + ")";
  }
  return t;
}

}  // namespace geodex::cli
