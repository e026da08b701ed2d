#pragma once
/// \file
/// A force and a moment at the tip, each dead (world frame) or follower (tip body frame).

#include "cosserat/loads/load.hpp"

namespace cosserat {

class TipForce final : public Load {
 public:
  /// \param[in] force N, in `frame`
  TipForce(const Vec3& force, LoadFrame frame) : force_(force), frame_(frame) {}
  SplitWrench TipWrench(double tip_mass) const override {
    (void)tip_mass;
    SplitWrench w;
    (frame_ == LoadFrame::kWorld ? w.dead_W : w.follower_B).tail<3>() = force_;
    return w;
  }

 private:
  Vec3 force_;
  LoadFrame frame_;
};

class TipMoment final : public Load {
 public:
  /// \param[in] moment N·m, in `frame`
  TipMoment(const Vec3& moment, LoadFrame frame) : moment_(moment), frame_(frame) {}
  SplitWrench TipWrench(double tip_mass) const override {
    (void)tip_mass;
    SplitWrench w;
    (frame_ == LoadFrame::kWorld ? w.dead_W : w.follower_B).head<3>() = moment_;
    return w;
  }

 private:
  Vec3 moment_;
  LoadFrame frame_;
};

}  // namespace cosserat
