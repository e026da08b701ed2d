#pragma once
/// \file
/// Gravity: a dead force ρ A g per unit length on the rod and m g on a tip body.

#include "cosserat/loads/load.hpp"

namespace cosserat {

class Gravity final : public Load {
 public:
  /// \param[in] acceleration_W acceleration of gravity, world frame, m/s²
  explicit Gravity(const Vec3& acceleration_W) : g_W_(acceleration_W) {}
  Vec3 DistributedForce_W(const LoadSite& site) const override { return site.mass * g_W_; }
  SplitWrench TipWrench(double tip_mass) const override {
    SplitWrench w;
    w.dead_W.tail<3>() = tip_mass * g_W_;
    return w;
  }

 private:
  Vec3 g_W_;
};

}  // namespace cosserat
