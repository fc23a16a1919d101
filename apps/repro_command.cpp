// `geodex repro FILE [--target T] [--svg OUT]`
// Reads a corpus file (any fuzz target's bytes, or a text reproducer written by `geodex check`'s
// invariant checker), detects which target it belongs to unless --target says, prints the case
// readably, replays it with every check on and prints the verdict; --svg draws the local
// configuration. Exit 0 when every check passes, 1 when one fails, 2 for an unreadable file.

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "geodex/error.h"
#include "geodex/verify/repro.h"

namespace geodex::cli {

namespace {

struct ReproOptions {
  std::string path;
  std::string target;
  std::string svg;
};

int runReproCommand(const ReproOptions& o) {
  std::optional<verify::FuzzTarget> target;
  if (!o.target.empty()) {
    target = verify::parseFuzzTarget(o.target);
    if (!target) throw InputError("usage", "--target: unknown fuzz target '" + o.target + "'");
  }
  const std::optional<std::string> svg = o.svg.empty() ? std::nullopt : std::optional<std::string>(o.svg);
  const int verdict = verify::runRepro(o.path, target, svg, std::cout);
  return verdict == 0 ? kExitOk : verdict == 1 ? kExitCheckFailed : kExitBadInput;
}

}  // namespace

Command addReproCommand(CLI::App& app) {
  auto o = std::make_shared<ReproOptions>();
  CLI::App* sub = app.add_subcommand(
      "repro", "Replay a corpus or reproducer file with every check on and print the verdict");
  sub->add_option("FILE", o->path, "Corpus file (corpus/<target>/...) or reproducer")->required();
  sub->add_option("--target", o->target,
                  "fuzz_mesh_io, fuzz_predicates, fuzz_edge_update, fuzz_propagation, fuzz_two_faces or fuzz_solver "
                  "(default: detected from the path and content)");
  sub->add_option("--svg", o->svg, "Draw the local configuration to this SVG file");
  return {sub, [o] { return runReproCommand(*o); }};
}

}  // namespace geodex::cli
