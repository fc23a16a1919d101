#pragma once
// fuzz_mesh_io: a file through the readers and the validator. Bytes → readMeshFromMemory → a
// soup or InputError (nothing else escapes); validateMesh never throws; a soup without errors
// builds a Mesh (edges of positive length, corner angles in [0, π] summing to π) and round-trips
// through OFF exactly. Its libFuzzer main is fuzz/fuzz_mesh_io.cpp.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "geodex/verify/cases/fuzz_target.h"

namespace geodex::verify {

/// Longer inputs are skipped: the decoders cap what a case may ask for, so that every input runs
/// in bounded time (the fuzzing budget, docs/fuzzing.md).
inline constexpr std::size_t kMaxMeshIoInputBytes = 1u << 16;

/// The bytes are the file, after an optional first byte 1, 2 or 3 that forces OFF, OBJ or PLY
/// (any other first byte is the file's own; the format is then detected from the content).
struct MeshIoCase {
  std::string bytes;       ///< the file, without the format byte
  std::string formatHint;  ///< "" (detect), "off", "obj" or "ply": a first byte 1, 2 or 3 says
};

/// nullopt only for inputs over kMaxMeshIoInputBytes: every file is a case.
std::optional<MeshIoCase> decodeMeshIo(std::span<const std::uint8_t> bytes);

/// The reader's verdict, the validator's, and for a soup without errors the Mesh's geometry and
/// the OFF round trip.
Verdict checkMeshIo(const MeshIoCase& c);

/// The first 40 lines of the file, non-printable bytes as \xNN.
void describe(const MeshIoCase& c, std::ostream& out);
/// The mesh read, projected onto its two widest axes (or the reader's error).
void writeSvg(const MeshIoCase& c, std::ostream& out);

/// The committed corpus (corpus/fuzz_mesh_io/): files of every format and flavour the readers
/// take, and files each reader error and validator issue is named after, and the regress files
/// that can be described.
std::vector<Seed> meshIoSeeds();

}  // namespace geodex::verify
