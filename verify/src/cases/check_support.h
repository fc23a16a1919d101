#pragma once
// What every target's check uses to word its verdict: the first broken check wins (fail), numbers
// to 17 digits (fmt), an interval as text; whether a value survives a scaling by a power of two
// exactly, which the scale checks ask; and which degeneracies a seed missed. Private to
// verify/src/cases (hence namespace detail).

#include <string>
#include <vector>

#include "geodex/interval.h"
#include "geodex/verify/cases/fuzz_target.h"

namespace geodex::verify::detail {

/// Records check and message as v's failure unless an earlier check already failed; returns v.
Verdict& fail(Verdict& v, std::string check, std::string message);

/// x to 17 significant digits: enough to read the double back exactly.
std::string fmt(double x);

/// "[b0, b1] s=(x, y) sigma=σ side=τ", and " propagated" when it is.
std::string describeInterval(const Interval& w);

/// Whether x × k (k a power of two) is exact: x is zero, or x and the product are normal numbers.
bool scalesExactly(double x, double k);

/// "" when v counted every one of `kinds`, else "does not hit" and the ones it did not count.
std::string kindsNotHit(const Verdict& v, const std::vector<DegeneracyKind>& kinds);

}  // namespace geodex::verify::detail
