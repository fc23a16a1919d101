// `geodex info MESH`: sizes, boundary, components, pseudo-source vertices, bounding-box diagonal
// and every finding of the reader and the validator. A mesh the solver refuses gets all its
// errors listed (not only the first) and exit code 2.

#include <cstdio>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cli_common.h"
#include "commands.h"
#include "geodex/mesh_io.h"

namespace geodex::cli {

namespace {

struct InfoOptions {
  std::string meshPath;
};

int runInfo(const InfoOptions& o) {
  MeshReadResult read = readMesh(o.meshPath);
  std::vector<MeshIssue> issues = std::move(read.issues);
  validateMesh(read.soup, issues);
  // The reader and the validator may both report the same problem; list each once.
  std::set<std::pair<std::string, std::string>> seen;
  std::erase_if(issues, [&](const MeshIssue& i) { return !seen.insert({i.kind, i.message}).second; });

  std::size_t errors = 0;
  for (const MeshIssue& issue : issues) {
    if (issue.severity == Severity::Error) {
      std::cerr << "error: " << issue.message << '\n';
      ++errors;
    }
  }
  if (errors > 0) {
    std::cerr << "error: " << o.meshPath << ": " << errors
              << (errors == 1 ? " error" : " errors") << "; the solver refuses this mesh\n";
    return kExitBadInput;
  }

  const Mesh mesh(std::move(read.soup));  // throws InputError if the validator missed something
  std::size_t boundaryEdges = 0;
  for (Index e = 0; e < mesh.numEdges(); ++e) {
    if (mesh.edge(e).face[1] == kNoIndex) ++boundaryEdges;
  }
  std::size_t pseudoSources = 0, boundaryVertices = 0, saddles = 0, unreferenced = 0;
  for (Index v = 0; v < mesh.numVertices(); ++v) {
    if (!mesh.isReferenced(v)) {
      ++unreferenced;
      continue;
    }
    if (mesh.isBoundaryVertex(v)) ++boundaryVertices;
    if (!mesh.isPseudoSourceVertex(v)) continue;
    ++pseudoSources;
    if (!mesh.isBoundaryVertex(v)) ++saddles;  // angle sum >= 2π (flat vertices count)
  }

  OutputFile out("");
  std::FILE* f = out.get();
  std::fprintf(f, "file: %s\n", o.meshPath.c_str());
  std::fprintf(f, "vertices: %zu\n", mesh.numVertices());
  std::fprintf(f, "faces: %zu\n", mesh.numFaces());
  std::fprintf(f, "edges: %zu\n", mesh.numEdges());
  std::fprintf(f, "boundary edges: %zu\n", boundaryEdges);
  std::fprintf(f, "components: %zu\n", mesh.numComponents());
  std::fprintf(f, "boundary vertices: %zu\n", boundaryVertices);
  std::fprintf(f, "unreferenced vertices: %zu\n", unreferenced);
  std::fprintf(f, "pseudo-source vertices: %zu (%zu boundary, %zu saddle)\n", pseudoSources,
               pseudoSources - saddles, saddles);
  std::fprintf(f, "bounding-box diagonal: %.17g\n", mesh.boundingBoxDiagonal());
  std::fprintf(f, "warnings: %zu\n", issues.size());
  for (const MeshIssue& issue : issues) {
    std::fprintf(f, "warning: [%s] %s\n", issue.kind.c_str(), issue.message.c_str());
  }
  out.commit();
  return kExitOk;
}

}  // namespace

Command addInfoCommand(CLI::App& app) {
  auto o = std::make_shared<InfoOptions>();
  CLI::App* sub = app.add_subcommand(
      "info", "Mesh summary: sizes, boundary, components, pseudo-source vertices, "
              "bounding-box diagonal and all validation warnings");
  sub->add_option("MESH", o->meshPath, "Triangle mesh (OFF, OBJ or PLY)")->required();
  return {sub, [o] { return runInfo(*o); }};
}

}  // namespace geodex::cli
