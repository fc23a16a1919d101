// Wording a verdict (check_support.h).
#include "check_support.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace geodex::verify::detail {

Verdict& fail(Verdict& v, std::string check, std::string message) {
  if (v.failed.empty()) {
    v.failed = std::move(check);
    v.message = std::move(message);
  }
  return v;
}

std::string fmt(double x) {
  std::ostringstream os;
  os << std::setprecision(17) << x;
  return os.str();
}

std::string describeInterval(const Interval& w) {
  std::ostringstream os;
  os << std::setprecision(17) << "[" << w.b0 << ", " << w.b1 << "] s=(" << w.source.x() << ", "
     << w.source.y() << ") sigma=" << w.sigma << " side=" << int(w.side);
  if (w.fullyPropagated()) os << " propagated";
  return os.str();
}

bool scalesExactly(double x, double k) { return x == 0.0 || (std::isnormal(x) && std::isnormal(x * k)); }

std::string kindsNotHit(const Verdict& v, const std::vector<DegeneracyKind>& kinds) {
  // Appended in place: gcc 12 takes `"…" + missing` for an overlapping memcpy (-Wrestrict).
  std::string why = "does not hit";
  const std::size_t prefix = why.size();
  for (DegeneracyKind k : kinds) {
    if (v.degeneracies[k] != 0) continue;
    why += ' ';
    why += name(k);
  }
  return why.size() == prefix ? std::string() : why;
}

}  // namespace geodex::verify::detail
