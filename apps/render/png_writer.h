#pragma once
// PNG output for `geodex render`, through Debian's libpng (its "simplified" write API).

#include <cstdio>
#include <string>

#include "render/rasterizer.h"

namespace geodex::render {

/// Writes `image` as an 8-bit RGB PNG to `file` (an open, writable stream; the caller makes the
/// write atomic with cli::OutputFile). Throws InputError ("output") naming `pathForMessages`
/// when libpng fails.
void writePng(std::FILE* file, const RgbImage& image, const std::string& pathForMessages);

}  // namespace geodex::render
