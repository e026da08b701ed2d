#include "stability_warning.hpp"

namespace cosserat::run::detail {

std::string UnstableWarning(const StaticShootingSummary& s) {
  if (!s.converged() || s.stability_index <= 0) return "";
  return "cosserat: warning: this equilibrium is unstable (" + std::to_string(s.stability_index) +
         " unstable direction" + (s.stability_index > 1 ? "s" : "") +
         "): the loads or the actuation are past a critical point, and no stable equilibrium was "
         "reached from the unloaded rod; \"analysis\": \"buckling\" finds the critical load\n";
}

}  // namespace cosserat::run::detail
