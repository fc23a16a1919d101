#include "render/colormap.h"

#include <algorithm>
#include <cmath>

namespace geodex::render {

namespace {

/// Matt Zucker's least-squares polynomial fit of viridis, per channel (Shadertoy "WlfXRN",
/// 2019): c(t) = Σ_k coefficient[k] t^k for t in [0, 1].
constexpr double kViridisPolynomial[7][3] = {
    {0.2777273272234177, 0.005407344544966578, 0.3340998053353061},
    {0.1050930431085774, 1.404613529898575, 1.384590162594685},
    {-0.3308618287255563, 0.214847559468213, 0.09509516302823659},
    {-4.634230498983486, -5.799100973351585, -19.33244095627987},
    {6.228269936347081, 14.17993336680509, 56.69055260068105},
    {4.776384997670288, -13.74514537774601, -65.35303263337234},
    {-5.435455855934631, 4.645852612178535, 26.3124352495832},
};

std::array<Rgb, 256> makeViridisTable() {
  std::array<Rgb, 256> table;
  for (int i = 0; i < 256; ++i) {
    const double t = i / 255.0;
    double c[3];
    for (int channel = 0; channel < 3; ++channel) {
      double value = 0.0;  // Horner
      for (int k = 6; k >= 0; --k) value = value * t + kViridisPolynomial[k][channel];
      c[channel] = std::clamp(value, 0.0, 1.0);
    }
    table[i] = {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
  }
  return table;
}

}  // namespace

const std::array<Rgb, 256>& viridisTable() {
  static const std::array<Rgb, 256> table = makeViridisTable();
  return table;
}

Rgb viridis(double t) {
  const std::array<Rgb, 256>& table = viridisTable();
  if (!(t > 0.0)) return table.front();  // also NaN
  if (t >= 1.0) return table.back();
  const double x = t * 255.0;
  const int i = std::min(static_cast<int>(x), 254);
  const float f = static_cast<float>(x - i);
  const Rgb& a = table[i];
  const Rgb& b = table[i + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

Rgb8 toRgb8(const Rgb& c) {
  auto channel = [](float x) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f));
  };
  return {channel(c.r), channel(c.g), channel(c.b)};
}

Rgb8 viridis8(double t) { return toRgb8(viridis(t)); }

}  // namespace geodex::render
