#pragma once
// The bytes every binary fuzz target reads: little-endian integers, doubles and Quantity, the one
// number type of a case (a lattice value nudged by a few multiples of a tolerance), and what a
// Quantity stands for once a field gives it a range, a unit and a length scale. Our own reader
// rather than FuzzedDataProvider: it reads front to back, so seeds can be written from readable
// descriptions (each target's seeds()), and it builds with gcc too.
//
// Reading past the end gives zeros (like FuzzedDataProvider), so every prefix of a valid input is
// a valid input. Each target's spec (cases/<target>.h) is written field by field in the order
// its struct declares them; docs/fuzzing.md has the layouts side by side.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace geodex::verify {

/// The binary targets' input cap: longer inputs are skipped. The decoders cap what a case may ask
/// for, so that every input runs in bounded time (the fuzzing budget, docs/fuzzing.md);
/// fuzz_mesh_io has its own cap, kMaxMeshIoInputBytes.
inline constexpr std::size_t kMaxFuzzInputBytes = 4096;

// === Quantity ===================================================================================

/// Which tolerance a nudge is a multiple of (tolerance.h).
enum class Nudge : std::uint8_t {
  Coincide,         ///< tol::kCoincideRel
  Collinear,        ///< tol::kCollinearSin
  TinyInterval,     ///< tol::kTinyIntervalRel
  FlatFace,         ///< tol::kFlatFaceRel
  SnapParam,        ///< tol::kSnapParam
  FlatVertexAngle,  ///< tol::kFlatVertexAngle
  SameSource,       ///< tol::kSameSourceRel
  Continuity,       ///< tol::kContinuityRel
};
double toleranceOf(Nudge n);

/// One number of a case: a lattice value, or a raw double, times 8^exponent, plus a nudge of a
/// few multiples of a tolerance. 4 bytes on the wire (int16 n, int8 nudge, uint8 flags), 12
/// with a raw double. Each field of a case says which lattice range n is wrapped into, what the
/// lattice unit is, and what length the nudge's tolerance is relative to (fieldValue below).
///
///   flags bits 0–2  the Nudge kind           bit 3  fine: the nudge is in 1/16 steps
///         bits 4–6  exponent e (× 8^e)       bit 7  a raw double follows (replaces n)
struct Quantity {
  std::int16_t n = 0;
  std::int8_t nudge = 0;
  std::uint8_t flags = 0;
  double raw = 0.0;

  // Builders for readable seeds (each target's seeds()).
  static Quantity lattice(int n);
  /// A raw value in lattice units (clamped to the field's range × 8^e when decoded).
  static Quantity exact(double value);
  /// Adds k (k/16 when fine) multiples of the tolerance t × the field's length scale.
  Quantity nudged(int k, Nudge t, bool fine = false) const;
  Quantity times8(int e) const;

  bool isRaw() const { return (flags & 0x80) != 0; }
  bool fine() const { return (flags & 0x08) != 0; }
  int exponent() const { return (flags >> 4) & 7; }
  Nudge nudgeKind() const { return static_cast<Nudge>(flags & 7); }
};

// === Reading and writing ========================================================================

class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  std::uint8_t u8() { return pos_ < bytes_.size() ? bytes_[pos_++] : 0; }
  std::int8_t i8() { return static_cast<std::int8_t>(u8()); }
  std::int16_t i16();
  /// A raw double; non-finite values read as 0.
  double f64();
  Quantity quantity();
  bool atEnd() const { return pos_ >= bytes_.size(); }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
};

class ByteWriter {
 public:
  void u8(std::uint8_t v) { bytes_.push_back(v); }
  void i8(std::int8_t v) { bytes_.push_back(static_cast<std::uint8_t>(v)); }
  void i16(std::int16_t v);
  void f64(double v);
  void quantity(const Quantity& q);
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

// === Field values: what a Quantity stands for ===================================================
// Every spec starts with unitExp: its lattice unit is unitOf(unitExp), so every case also runs
// scaled. A field in world units is latticeValue × unit + nudgeValue (fieldValue); the specs'
// comments give each field's range in lattice units, where "nL" is the lattice extent of the
// case's edge length (edgeLengthOf).

/// v wrapped into [lo, hi].
int wrapInt(long v, long lo, long hi);

/// The lattice part of q: n wrapped into [lo, hi], or the raw value clamped into [lo, hi] × 8^e;
/// times 8^e. In lattice units.
double latticeValue(const Quantity& q, long lo, long hi);

/// The nudge of q: its multiple of the tolerance it names, × lengthScale.
double nudgeValue(const Quantity& q, double lengthScale);

/// A field: lattice value × unit + nudge × tolerance × lengthScale.
double fieldValue(const Quantity& q, long lo, long hi, double unit, double lengthScale);

/// The case's length unit 2^e: e = unitExp within ±20, beyond that 8 × unitExp up to ±1000, so
/// that the decoders reach every scale a double holds. Every field is a multiple of the unit, so
/// two units give the same case scaled exactly, and the solver decides it the same way bit for
/// bit (docs/numerics.md): the scale is a property under test, not a new configuration.
double unitOf(std::int8_t unitExp);

/// An edge length field: the length in world units and its lattice extent nL (the lattice value
/// rounded up), which the fields on that edge take their ranges from.
struct LatticeLength {
  double length;
  long n;
};
/// The edge length q stands for: a lattice value in [1, 64], nudged relative to itself.
LatticeLength edgeLengthOf(const Quantity& q, double unit);

}  // namespace geodex::verify
