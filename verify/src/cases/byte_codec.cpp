// The fuzz targets' byte codec and field values (byte_codec.h).
#include "geodex/verify/cases/byte_codec.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "geodex/tolerance.h"

namespace geodex::verify {

// ===  Quantity ==================================================================================

double toleranceOf(Nudge n) {
  switch (n) {
    case Nudge::Coincide: return tol::kCoincideRel;
    case Nudge::Collinear: return tol::kCollinearSin;
    case Nudge::TinyInterval: return tol::kTinyIntervalRel;
    case Nudge::FlatFace: return tol::kFlatFaceRel;
    case Nudge::SnapParam: return tol::kSnapParam;
    case Nudge::FlatVertexAngle: return tol::kFlatVertexAngle;
    case Nudge::SameSource: return tol::kSameSourceRel;
    case Nudge::Continuity: return tol::kContinuityRel;
  }
  return 0.0;
}

Quantity Quantity::lattice(int n) {
  Quantity q;
  q.n = static_cast<std::int16_t>(n);
  return q;
}

Quantity Quantity::exact(double value) {
  Quantity q;
  q.flags = 0x80;
  q.raw = value;
  return q;
}

Quantity Quantity::nudged(int k, Nudge t, bool fineSteps) const {
  Quantity q = *this;
  q.nudge = static_cast<std::int8_t>(k);
  q.flags = static_cast<std::uint8_t>((q.flags & 0xF0) | static_cast<std::uint8_t>(t) |
                                      (fineSteps ? 0x08 : 0x00));
  return q;
}

Quantity Quantity::times8(int e) const {
  Quantity q = *this;
  q.flags = static_cast<std::uint8_t>((q.flags & 0x8F) | ((e & 7) << 4));
  return q;
}

// ===  Reading and writing =======================================================================

std::int16_t ByteReader::i16() {
  const std::uint16_t lo = u8();
  const std::uint16_t hi = u8();
  return static_cast<std::int16_t>(lo | (hi << 8));
}

double ByteReader::f64() {
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(u8()) << (8 * i);
  double d;
  std::memcpy(&d, &bits, sizeof d);
  return std::isfinite(d) ? d : 0.0;
}

Quantity ByteReader::quantity() {
  Quantity q;
  q.n = i16();
  q.nudge = i8();
  q.flags = u8();
  if (q.isRaw()) q.raw = f64();
  return q;
}

void ByteWriter::i16(std::int16_t v) {
  const auto u = static_cast<std::uint16_t>(v);
  u8(static_cast<std::uint8_t>(u & 0xFF));
  u8(static_cast<std::uint8_t>(u >> 8));
}

void ByteWriter::f64(double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  for (int i = 0; i < 8; ++i) u8(static_cast<std::uint8_t>(bits >> (8 * i)));
}

void ByteWriter::quantity(const Quantity& q) {
  i16(q.n);
  i8(q.nudge);
  u8(q.flags);
  if (q.isRaw()) f64(q.raw);
}

// ===  Field values ==============================================================================

int wrapInt(long v, long lo, long hi) {
  const long span = hi - lo + 1;
  return static_cast<int>(lo + ((v - lo) % span + span) % span);
}

double latticeValue(const Quantity& q, long lo, long hi) {
  const double mul = std::ldexp(1.0, 3 * q.exponent());
  if (q.isRaw()) return std::clamp(q.raw, lo * mul, hi * mul);
  return wrapInt(q.n, lo, hi) * mul;
}

double nudgeValue(const Quantity& q, double lengthScale) {
  return q.nudge * (q.fine() ? 1.0 / 16.0 : 1.0) * toleranceOf(q.nudgeKind()) * lengthScale;
}

double fieldValue(const Quantity& q, long lo, long hi, double unit, double lengthScale) {
  return latticeValue(q, lo, hi) * unit + nudgeValue(q, lengthScale);
}

double unitOf(std::int8_t unitExp) {
  const int e = unitExp >= -20 && unitExp <= 20 ? unitExp : std::clamp(8 * unitExp, -1000, 1000);
  return std::ldexp(1.0, e);
}

LatticeLength edgeLengthOf(const Quantity& q, double unit) {
  const double lat = latticeValue(q, 1, 64);
  const double length = lat * unit + nudgeValue(q, lat * unit);
  return {length, std::clamp(static_cast<long>(std::ceil(lat)), 1L, 1L << 24)};
}

}  // namespace geodex::verify
