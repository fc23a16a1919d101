#pragma once
// The colour map of `geodex render` and of the PLY output: viridis (van der Walt & Smith, the
// matplotlib default), perceptually uniform and readable in grey and by colour-blind viewers.
// The 256-entry table is computed at start-up from a published degree-6 polynomial fit of
// viridis (Matt Zucker, 2019; within 4/255 per channel of matplotlib's table at t = 0, ¼, ½, ¾,
// 1), not copied from a table.

#include <array>
#include <cstdint>

namespace geodex::render {

/// An 8-bit sRGB colour.
struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
};

/// A colour with channels in [0, 1] (sRGB-encoded, like the table).
struct Rgb {
  float r = 0.0f, g = 0.0f, b = 0.0f;
};

/// The 256 viridis colours, entry i for t = i / 255 (dark blue at 0, yellow at 1).
const std::array<Rgb, 256>& viridisTable();

/// viridis at t (clamped to [0, 1]), linearly interpolated between table entries. NaN gives
/// entry 0.
Rgb viridis(double t);

/// viridis(t) rounded to 8 bits.
Rgb8 viridis8(double t);

/// Channels clamped to [0, 1] and rounded to 8 bits.
Rgb8 toRgb8(const Rgb& c);

}  // namespace geodex::render
