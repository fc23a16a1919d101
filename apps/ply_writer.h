#pragma once
// `geodex distance … --out FILE.ply`: the mesh as an ASCII PLY with the distance field on its
// vertices, for viewers such as MeshLab, ParaView or Blender.
//
//   element vertex: float x, y, z; float distance (−1 where unreachable, i.e. +inf: PLY readers
//                   handle "inf" poorly); uchar red, green, blue (viridis from 0 to the largest
//                   finite distance, grey where unreachable)
//   element face:   list uchar int vertex_indices
//
// The header's comments say so, and name the sources.

#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "geodex/mesh.h"

namespace geodex::cli {

/// True if `path` ends in ".ply" (any case).
bool hasPlyExtension(const std::string& path);

/// Writes the PLY described above to `file` (the caller checks for write errors).
/// @param[in] vertexDistance  #V distances, +inf where unreachable
/// @param[in] sourceSpecs     the sources as the user gave them, for a header comment
void writeDistancePly(std::FILE* file, const Mesh& mesh, std::span<const double> vertexDistance,
                      const std::vector<std::string>& sourceSpecs);

}  // namespace geodex::cli
