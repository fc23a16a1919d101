#include "external_program.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <thread>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "geodex/error.h"

namespace geodex::cli {

namespace {

/// A program's output files may not grow past this (RLIMIT_FSIZE; beyond it the program gets
/// SIGXFSZ, a crash): a runaway program must not fill the disk within its time limit.
constexpr rlim_t kMaxProgramFileBytes = rlim_t{1} << 30;
/// Waiting for the shell polls at intervals growing from the first to the last: short runs end
/// without delay, long ones cost no CPU.
constexpr std::chrono::microseconds kFirstPoll{200}, kLastPoll{20000};

std::string formatSeconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g s", s);
  return buffer;
}

/// In the child: its own process group, stdin from /dev/null, both outputs into the capture
/// file, the file size limit; then the shell. Only async-signal-safe calls after fork.
[[noreturn]] void execShell(const std::string& command, int captureFd) {
  ::setpgid(0, 0);
  const int devNull = ::open("/dev/null", O_RDONLY);
  if (devNull >= 0) ::dup2(devNull, STDIN_FILENO);
  ::dup2(captureFd, STDOUT_FILENO);
  ::dup2(captureFd, STDERR_FILENO);
  const rlimit limit{kMaxProgramFileBytes, kMaxProgramFileBytes};
  ::setrlimit(RLIMIT_FSIZE, &limit);
  ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
  ::_exit(127);
}

/// The process group of the command running now (0: none), for the signal handler below.
volatile std::sig_atomic_t runningGroup = 0;

/// On SIGINT, SIGTERM or SIGHUP (Ctrl-C, a CI job cancelled) the command's process group, which
/// is not in ours and so did not get the signal, is killed before we end as the signal says.
extern "C" void killRunningGroupAndEnd(int signalNumber) {
  if (runningGroup != 0) ::kill(-static_cast<pid_t>(runningGroup), SIGKILL);
  ::signal(signalNumber, SIG_DFL);
  ::raise(signalNumber);
}

void installSignalHandlersOnce() {
  static const bool installed = [] {
    struct sigaction action {};
    action.sa_handler = killRunningGroupAndEnd;
    sigemptyset(&action.sa_mask);
    for (int signalNumber : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signalNumber, &action, nullptr);
    return true;
  }();
  (void)installed;
}

/// Whether the child has ended, without reaping it: its pid (and so its process-group id) stays
/// taken until we reap, so killing the group afterwards cannot hit an unrelated process.
bool hasEnded(pid_t pid) {
  siginfo_t info{};
  const int rc = ::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT);
  return rc == 0 && info.si_pid == pid;
}

std::string readCapture(const std::string& path, bool& truncated) {
  std::ifstream in(path, std::ios::binary);
  std::string text(kMaxCapturedOutput + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  truncated = text.size() > kMaxCapturedOutput;
  if (truncated) text.resize(kMaxCapturedOutput);
  return text;
}

/// `text` as one shell word: itself when it has only characters the shell leaves alone.
std::string shellWord(const std::string& text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || std::strchr("/._-+,:=@%", ch) != nullptr;
  });
  if (plain) return text;
  std::string quoted = "'";
  for (char ch : text) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

}  // namespace

std::string ProgramRun::describe(double timeLimitSeconds) const {
  if (timedOut) {
    return "timed out: still running after the time limit of " + formatSeconds(timeLimitSeconds) +
           "; its process group was killed";
  }
  if (signal != 0) {
    const char* what = ::strsignal(signal);
    return "killed by signal " + std::to_string(signal) + " (" + (what ? what : "?") + ") after " + formatSeconds(seconds);
  }
  std::string note;
  if (exitStatus == 127) note = " (command not found?)";
  // The shell reports a command a signal ended as 128 + the signal's number.
  if (exitStatus > 128 && exitStatus < 128 + NSIG) {
    const char* what = ::strsignal(exitStatus - 128);
    note = " (from the shell: its command was killed by signal " + std::to_string(exitStatus - 128) + ", " +
           (what ? what : "?") + ")";
  }
  return "exit status " + std::to_string(exitStatus) + note + " after " + formatSeconds(seconds);
}

ProgramRun runProgram(const std::string& command, double timeLimitSeconds, const std::string& capturePath) {
  using Clock = std::chrono::steady_clock;
  const int captureFd = ::open(capturePath.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (captureFd < 0) {
    throw InputError("output", "cannot create '" + capturePath + "': " + std::strerror(errno));
  }
  // Flushed so that the child does not inherit (and write out again) our buffered output.
  std::fflush(nullptr);
  const Clock::time_point start = Clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(captureFd);
    throw InputError("system", std::string("cannot start the command: fork: ") + std::strerror(errno));
  }
  if (pid == 0) execShell(command, captureFd);
  ::close(captureFd);
  ::setpgid(pid, pid);  // also here, so the group exists before we may need to kill it
  installSignalHandlersOnce();
  runningGroup = static_cast<std::sig_atomic_t>(pid);

  ProgramRun run;
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeLimitSeconds));
  std::chrono::microseconds pause = kFirstPoll;
  while (!hasEnded(pid)) {
    if (Clock::now() >= deadline) {
      run.timedOut = true;
      break;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(kLastPoll, 2 * pause);
  }
  // The whole group, also after a normal exit: a background child must not outlive the case
  // (it could still write the next case's output file).
  ::kill(-pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  runningGroup = 0;
  run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (!run.timedOut) {
    if (WIFEXITED(status)) run.exitStatus = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
  }
  run.output = readCapture(capturePath, run.outputTruncated);
  return run;
}

void checkCommandTemplate(const std::string& commandTemplate) {
  for (const char* placeholder : {"{mesh}", "{source}", "{out}"}) {
    if (commandTemplate.find(placeholder) == std::string::npos) {
      throw InputError("usage", std::string("--solver '") + commandTemplate + "' has no " + placeholder +
                                    ": the command template needs {mesh} (an OFF file), {source} (a 0-based "
                                    "vertex index) and {out} (the file to write one distance per vertex to)");
    }
  }
}

std::string fillCommandTemplate(const std::string& commandTemplate, const std::string& meshPath, unsigned source,
                                const std::string& outPath) {
  const std::pair<std::string, std::string> replacements[] = {
      {"{mesh}", shellWord(meshPath)}, {"{source}", std::to_string(source)}, {"{out}", shellWord(outPath)}};
  std::string command;
  for (std::size_t i = 0; i < commandTemplate.size();) {
    bool replaced = false;
    for (const auto& [placeholder, value] : replacements) {
      if (commandTemplate.compare(i, placeholder.size(), placeholder) == 0) {
        command += value;
        i += placeholder.size();
        replaced = true;
        break;
      }
    }
    if (!replaced) command += commandTemplate[i++];
  }
  return command;
}

}  // namespace geodex::cli
