// fuzz_mesh_io: bytes → readMeshFromMemory (a first byte 1, 2, 3 forces OFF, OBJ, PLY; otherwise
// the format is detected from the content) → a soup, or geodex::InputError and nothing else.
// validateMesh never throws; a soup it finds no error in builds a Mesh (edges of positive
// length, corner angles in [0, π] summing to π per face) and, written back as OFF with 17
// digits, reads back as the same soup.
// Format, check and seeds: verify/include/geodex/verify/cases/fuzz_mesh_io.h.
#include "decode.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geodex;
  const auto c = fuzz::decodeAs<verify::MeshIoCase>(fuzz::FuzzTarget::MeshIo, data, size);
  if (!c) return 0;
  fuzz::require(verify::checkMeshIo(*c), fuzz::FuzzTarget::MeshIo, data, size);
  return 0;
}
