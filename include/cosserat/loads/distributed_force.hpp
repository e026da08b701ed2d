#pragma once
/// \file
/// A uniform dead force per unit length, fixed in the world frame (a steady wind or current
/// treated as a given load, a magnetic body force, a test load).

#include "cosserat/loads/load.hpp"

namespace cosserat {

class DistributedForce final : public Load {
 public:
  /// \param[in] force_W force per unit length, world frame, N/m
  explicit DistributedForce(const Vec3& force_W) : f_W_(force_W) {}
  Vec3 DistributedForce_W(const LoadSite& site) const override { return site.length * f_W_; }

 private:
  Vec3 f_W_;
};

}  // namespace cosserat
