#pragma once
// The subcommands of the `geodex` tool. Each `add…Command` registers its options on the main
// CLI::App and returns what to run once parsing has selected it; geodex.cpp dispatches and maps
// exceptions to exit codes. Adding a subcommand: one file with one `add…Command`, one line here,
// one line in geodex.cpp's table.

#include <functional>

#include <CLI/CLI.hpp>

namespace geodex::cli {

struct Command {
  CLI::App* app = nullptr;  ///< the subcommand's parser (owned by the main app)
  std::function<int()> run;  ///< runs it; returns an ExitCode, throws on errors
};

Command addDistanceCommand(CLI::App& app);
Command addPathCommand(CLI::App& app);
Command addInfoCommand(CLI::App& app);
Command addCheckCommand(CLI::App& app);
Command addReproCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addCrossCheckCommand(CLI::App& app);

}  // namespace geodex::cli
