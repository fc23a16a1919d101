#include "render/png_writer.h"

#include <cstring>

#include <png.h>

#include "geodex/error.h"

namespace geodex::render {

static_assert(sizeof(Rgb8) == 3, "RgbImage pixels must be packed RGB bytes for libpng");

void writePng(std::FILE* file, const RgbImage& image, const std::string& pathForMessages) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  // The simplified API reports errors through its return value and png.message (no longjmp
  // crosses our frames).
  const int ok = png_image_write_to_stdio(&png, file, /*convert_to_8_bit=*/0,
                                          image.pixels.data(), /*row_stride=*/0,
                                          /*colormap=*/nullptr);
  const std::string message = png.message;
  png_image_free(&png);
  if (ok == 0) {
    throw InputError("output", "cannot write PNG '" + pathForMessages + "': " + message);
  }
}

}  // namespace geodex::render
