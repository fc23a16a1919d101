#pragma once
// Running another program for `geodex crosscheck`: a command template filled in and run through
// the shell, in its own process group, with a time limit that is always enforced (the whole
// group is killed), everything it prints captured into a file, never a pipe it could stall on.

#include <string>

namespace geodex::cli {

/// How one run of an external command ended.
struct ProgramRun {
  bool timedOut = false;  ///< killed (with its process group) at the time limit
  int exitStatus = 0;     ///< when it exited by itself
  int signal = 0;         ///< when a signal ended it (other than our kill at the time limit)
  double seconds = 0.0;   ///< wall time
  std::string output;     ///< what it printed on stdout and stderr, interleaved, at most kMaxCapturedOutput
  bool outputTruncated = false;

  /// Non-zero exit, a signal or the time limit.
  bool failed() const { return timedOut || exitStatus != 0 || signal != 0; }
  /// "exit status 0 after 0.012 s", "killed by signal 6 (Aborted) after …", "timed out after …".
  std::string describe(double timeLimitSeconds) const;
};

/// Bytes of a run's output kept (the rest is cut, and outputTruncated set).
inline constexpr std::size_t kMaxCapturedOutput = 64 * 1024;

/// Runs `command` with /bin/sh -c, stdin from /dev/null, stdout and stderr into `capturePath`
/// (created or truncated), in a new process group. Returns once the shell has exited, or at
/// `timeLimitSeconds`, when the process group is killed with SIGKILL. Whatever is left of the
/// group when the shell exits (background children) is killed too. Throws InputError when the
/// capture file cannot be created or the process cannot be started.
ProgramRun runProgram(const std::string& command, double timeLimitSeconds, const std::string& capturePath);

/// The command template's placeholders, each required: {mesh} (an OFF file), {source} (a 0-based
/// vertex index), {out} (where the program writes one distance per vertex).
/// Throws InputError ("usage") naming the missing one.
void checkCommandTemplate(const std::string& commandTemplate);

/// The template with every {mesh}, {source} and {out} replaced; paths with characters the shell
/// would interpret are single-quoted.
std::string fillCommandTemplate(const std::string& commandTemplate, const std::string& meshPath, unsigned source,
                                const std::string& outPath);

}  // namespace geodex::cli
