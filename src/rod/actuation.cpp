#include "cosserat/rod/actuation.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cosserat {

bool Actuation::IsValid(std::string* why, int tendon_count, int chamber_count) const {
  auto fail = [&](const std::string& message) {
    if (why) *why = message;
    return false;
  };
  auto usable = [](double x) { return std::isfinite(x) && x >= 0; };
  if (!usable(pressure)) return fail("pressure: expected a number >= 0 (Pa)");
  if (!(std::isfinite(stiffness_scale) && stiffness_scale > 0))
    return fail("stiffness_scale: expected a finite number > 0");
  for (int i = 0; i < kMaxTendons; ++i) {
    if (!usable(tendon_tension[i]))
      return fail("tendon_tension: expected finite tensions >= 0 (N)");
    if (i >= tendon_count && tendon_tension[i] != 0)
      return fail("tendon_tension[" + std::to_string(i) + "]: a tension on the tendon at index " +
                  std::to_string(i) + " (from 0), but the rod has " + std::to_string(tendon_count) +
                  (tendon_count == 1 ? " tendon" : " tendons"));
  }
  for (int j = 0; j < kMaxChambers; ++j) {
    const double p = chamber_pressure[j];
    if (!(std::isfinite(p) && p >= kVacuumGaugePressure))
      return fail("chamber_pressure: expected finite gauge pressures >= -101325 (Pa)");
    if (j >= chamber_count && p != 0)
      return fail("chamber_pressure[" + std::to_string(j) +
                  "]: a pressure in the chamber at index " + std::to_string(j) +
                  " (from 0), but the rod has " +
                  std::to_string(chamber_count) + (chamber_count == 1 ? " chamber" : " chambers"));
  }
  for (double p : jamming_pressure)
    if (!usable(p)) return fail("jamming_pressure: expected numbers >= 0 (Pa)");
  return true;
}

bool Actuation::AllFinite() const {
  auto finite = [](const auto& values) {
    for (double v : values)
      if (!std::isfinite(v)) return false;
    return true;
  };
  return std::isfinite(pressure) && std::isfinite(stiffness_scale) && finite(tendon_tension) &&
         finite(chamber_pressure) && finite(jamming_pressure);
}

void Actuation::Require(int tendon_count, int chamber_count) const {
  std::string why;
  if (!IsValid(&why, tendon_count, chamber_count))
    throw std::invalid_argument("actuation." + why);
}

}  // namespace cosserat
