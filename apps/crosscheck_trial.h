#pragma once
// One case of `geodex crosscheck` run through the other program and judged: geodex's reference
// (verify/crosscheck_judge.h), the program's run (external_program.h), its output read and
// compared. The same trial serves the first run of a case and every step of its minimization.

#include <optional>
#include <string>

#include "external_program.h"
#include "geodex/verify/crosscheck_cases.h"
#include "geodex/verify/crosscheck_judge.h"

namespace geodex::cli {

struct Trial {
  verify::CrossCheckCase c;
  verify::Reference reference;
  std::string command;  ///< as run
  ProgramRun run;
  bool outputFileWritten = false;
  std::string outputFile;  ///< what the program wrote to {out}
  verify::ProgramDistances got;
  verify::Judgement judgement;
  std::optional<verify::FindingKind> kind;  ///< none: the program agrees (or the case was skipped)

  /// geodex's own checks failed on the case: it is not judged.
  bool skipped() const { return !reference.problem.empty(); }
};

class CaseRunner {
 public:
  /// @param[in] workDir  an existing directory for the case's files (mesh, output, capture)
  CaseRunner(std::string commandTemplate, double timeLimitSeconds, double tolerance, std::string workDir);

  /// Writes the case's mesh, runs the program on it and judges what it did.
  Trial run(const verify::CrossCheckCase& c) const;

  double timeLimit() const { return timeLimit_; }
  double tolerance() const { return tolerance_; }
  const std::string& commandTemplate() const { return template_; }

 private:
  std::string template_;
  double timeLimit_;
  double tolerance_;
  std::string meshPath_, outPath_, capturePath_;
};

}  // namespace geodex::cli
