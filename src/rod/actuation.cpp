#include "cosserat/rod/actuation.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace cosserat {

bool Actuation::IsValid(std::string* why, int tendon_count, int chamber_count) const {
  auto fail = [&](const std::string& message) {
    if (why) *why = message;
    return false;
  };
  auto usable = [](double x) { return std::isfinite(x) && x >= 0; };
  // "<field>[i]: expected <what>, got <value>": the entry among up to eight, and its value.
  auto entry = [&](const char* field, int i, const char* what, double value) {
    std::ostringstream text;
    text << field << '[' << i << "]: expected " << what << ", got " << value;
    return fail(text.str());
  };
  if (!usable(pressure)) return fail("pressure: expected a number >= 0 (Pa)");
  if (!(std::isfinite(stiffness_scale) && stiffness_scale > 0))
    return fail("stiffness_scale: expected a finite number > 0");
  for (int i = 0; i < kMaxTendons; ++i) {
    if (!usable(tendon_tension[i]))
      return entry("tendon_tension", i, "a finite tension >= 0 (N)", tendon_tension[i]);
    if (i >= tendon_count && tendon_tension[i] != 0)
      return fail("tendon_tension[" + std::to_string(i) + "]: a tension on the tendon at index " +
                  std::to_string(i) + " (from 0), but the rod has " + std::to_string(tendon_count) +
                  (tendon_count == 1 ? " tendon" : " tendons"));
  }
  for (int j = 0; j < kMaxChambers; ++j) {
    const double p = chamber_pressure[j];
    if (!(std::isfinite(p) && p >= kVacuumGaugePressure))
      return entry("chamber_pressure", j, "a finite gauge pressure >= -101325 (Pa)", p);
    if (j >= chamber_count && p != 0)
      return fail("chamber_pressure[" + std::to_string(j) +
                  "]: a pressure in the chamber at index " + std::to_string(j) +
                  " (from 0), but the rod has " +
                  std::to_string(chamber_count) + (chamber_count == 1 ? " chamber" : " chambers"));
  }
  for (int k = 0; k < static_cast<int>(jamming_pressure.size()); ++k)
    if (!usable(jamming_pressure[k]))
      return entry("jamming_pressure", k, "a finite pressure >= 0 (Pa)", jamming_pressure[k]);
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
