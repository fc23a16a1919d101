// The `geodex` command-line tool: exact geodesic distances and paths on triangle meshes.
//
// Exit codes (also in README.md and `geodex --help`):
//   0  success
//   1  a check found a problem (`check`), or `crosscheck` found the other program wrong
//   2  bad input or usage: "error: …" on stderr (the message names file, line and element)
//   3  internal error: an invariant inside geodex failed — a bug, please report it with the
//      command line and the mesh; "internal error: …" on stderr
//
// Subcommands live in one file each (distance_command.cpp, …); main only parses, dispatches and
// maps exceptions to exit codes.

#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_common.h"
#include "commands.h"
#include "geodex/check.h"
#include "geodex/error.h"

namespace {

constexpr const char* kFooter = R"(SPEC (a point on the surface):
  v:I          vertex I
  e:I,J,T      the point at fraction T (0..1) from vertex I to vertex J on their edge
  f:F,A,B,C    the point of face F with barycentric coordinates A,B,C (sum 1)
Vertex and face indices are 0-based, in file order.

Exit codes: 0 success, 1 a check failed (check, crosscheck), 2 bad input or usage (error: on stderr),
3 internal error (a bug in geodex: please report it).)";

/// The subcommand to suggest `--help` for: the one the parser got to, if any.
std::string helpHint(const CLI::App& app) {
  const std::vector<CLI::App*> parsed = app.get_subcommands();
  if (!parsed.empty()) return "run 'geodex " + parsed.front()->get_name() + " --help' for usage";
  return "run 'geodex --help' for usage";
}

int runMain(int argc, char** argv) {
  using namespace geodex::cli;
  CLI::App app{"geodex: exact geodesic distances and paths on triangle meshes", "geodex"};
  app.require_subcommand(1);
  app.footer(kFooter);

  const std::vector<Command> commands{addDistanceCommand(app), addPathCommand(app),
                                      addInfoCommand(app), addCheckCommand(app), addReproCommand(app),
                                      addRenderCommand(app), addCrossCheckCommand(app)};

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help / --help-all: CLI11 prints and returns 0. Every other parse error: exit code 2
    // (CLI11's own codes, 105–115, are not ours).
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    std::cerr << "error: " << e.what() << "\n" << helpHint(app) << '\n';
    return kExitBadInput;
  }

  for (const Command& command : commands) {
    if (command.app->parsed()) return command.run();
  }
  std::cerr << "error: no subcommand given\n" << helpHint(app) << '\n';
  return kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace geodex::cli;
  // Every exception ends here: bad input is the user's (2), anything else is ours (3).
  try {
    return runMain(argc, argv);
  } catch (const geodex::InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory\n";
    return kExitBadInput;
  } catch (const geodex::InternalError& e) {
    std::cerr << "internal error: " << e.what() << '\n';
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "internal error: unexpected exception: " << e.what() << '\n';
    return kExitInternal;
  } catch (...) {
    std::cerr << "internal error: unknown exception\n";
    return kExitInternal;
  }
}
