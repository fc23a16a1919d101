#pragma once
// Reading meshes from OFF, OBJ and PLY, and validating them. Every problem names the element
// (vertex or face index, 0-based) and the file line (1-based) where it was found.

#include <string>
#include <vector>

#include "geodex/mesh.h"

namespace geodex {

enum class Severity { Warning, Error };

/// One finding of the reader or the validator.
struct MeshIssue {
  Severity severity;
  std::string kind;     ///< stable short name: "nan-coordinate", "non-manifold-edge", ...
  std::string message;  ///< full sentence naming file, line and element
};

struct MeshReadResult {
  TriangleSoup soup;
  std::vector<MeshIssue> issues;  ///< warnings (e.g. fan-triangulated polygons) and errors
  bool ok() const;                ///< no issue of Severity::Error
};

/// Reads OFF, OBJ or PLY (ASCII and binary little/big endian) by extension, or by content when
/// the extension is unknown. Polygons with more than 3 corners are fan-triangulated (warning).
/// Syntax errors throw InputError naming file and line.
MeshReadResult readMesh(const std::string& path);
/// Same, from bytes already in memory (the fuzzers use this). `nameForMessages` is used in
/// messages; `formatHint` is "off", "obj", "ply" or "" to detect from the content.
MeshReadResult readMeshFromMemory(std::string_view bytes, const std::string& nameForMessages,
                                  const std::string& formatHint);

/// Checks a soup for everything the solver or the user should know, appending to `issues` one
/// issue per rule the soup breaks, whose kind is the rule's name (each rule is a function of the
/// same name in camelCase in solver/src/mesh_io/validate_mesh.cpp):
/// errors (the solver refuses the mesh): non-finite-coordinate, index-out-of-range,
/// repeated-index (in a face), zero-length-edge (in a face), edge-length-out-of-range and
/// edge-length-spread (lengths geodex cannot compute with), duplicate-face, non-manifold-edge
/// (more than two faces);
/// warnings (handled): zero-area-face, non-manifold-vertex, unreferenced-vertex (distance +inf),
/// duplicate-position, inconsistent-winding, components (several; +inf across).
void validateMesh(const TriangleSoup& soup, std::vector<MeshIssue>& issues);

/// readMesh + validateMesh + Mesh construction; throws InputError with the first error.
/// Warnings are appended to `warnings` when given.
Mesh loadMesh(const std::string& path, std::vector<MeshIssue>* warnings = nullptr);

}  // namespace geodex
