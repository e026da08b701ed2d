#include "cosserat/rod/chamber.hpp"

#include <cmath>

namespace cosserat {

double Chamber::EquivalentRadius() const { return std::sqrt(area / M_PI); }

bool Chamber::IsValid(double length, std::string* why) const {
  auto fail = [&](const char* message) {
    if (why) *why = message;
    return false;
  };
  if (!offset.allFinite()) return fail("offset must be finite (m)");
  if (!(std::isfinite(area) && area > 0)) return fail("area must be a finite number > 0 (m²)");
  if (!(std::isfinite(start) && std::isfinite(end) && start >= 0 && end <= length))
    return fail("from and to must lie within [0, L]");
  if (!(start < end)) return fail("from must be less than to");
  return true;
}

}  // namespace cosserat
