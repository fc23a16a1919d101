#pragma once
// The format readers, one file each (off_reader.cpp, obj_reader.cpp, ply_reader.cpp). Each reads
// a whole file's bytes into `builder` and throws InputError at the first malformed element.
//
// They never trust a count from the file: every reserve() is capped by what the bytes left could
// hold and every loop consumes input, so any bytes (the fuzzers feed readMeshFromMemory random
// ones) end in a soup or an InputError, never in a crash, a bad_alloc or a hang.
// Private to solver/src/mesh_io/.

#include <string_view>

#include "soup_builder.h"

namespace geodex::detail {

void parseOff(std::string_view bytes, SoupBuilder& builder);
void parseObj(std::string_view bytes, SoupBuilder& builder);
/// ASCII, binary little endian and binary big endian.
void parsePly(std::string_view bytes, SoupBuilder& builder);

}  // namespace geodex::detail
