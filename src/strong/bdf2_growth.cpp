// Growth of the BDF2 stepper's rod (an everting vine robot lengthens): new nodes beyond the old
// tip, the run's history carried onto them, and the plan of the shot's steps redone.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosserat/rod/grid.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat {

void Bdf2ShootingStepper::Grow(const RodModel& longer, int new_segments) {
  std::string why;
  if (!longer.IsValid(&why)) throw std::invalid_argument("Grow: " + why);
  const double L_old = model_.length, L_new = longer.length;
  if (!(L_new > L_old)) throw std::invalid_argument("Grow: the new length must exceed the old");
  if (new_segments < 1) throw std::invalid_argument("Grow: new_segments must be at least 1");
  if (longer.tendons.size() != model_.tendons.size())
    throw std::invalid_argument("Grow: the tendons must stay the same");
  // New nodes: evenly spaced on (L_old, L_new], plus the new model's breakpoints there.
  std::vector<double> added;
  for (int k = 1; k <= new_segments; ++k)
    added.push_back(L_old + (L_new - L_old) * k / new_segments);
  for (double b : longer.section->Breakpoints())
    if (b > L_old && b < L_new) added.push_back(b);
  std::sort(added.begin(), added.end());
  const int n_old = static_cast<int>(grid_.size());
  for (double s : added)
    if (s - grid_.back() > 1e-12 * L_new) grid_.push_back(s);
  grid_.back() = L_new;
  model_ = longer;
  const int n = static_cast<int>(grid_.size());
  SampleGrid();
  const int stages_old = stage_slots_;
  PlanSteps(n_old - 1);  // the old segments keep their steps (their history is at those stages)
  const int stages = stage_slots_;
  run_.model_fingerprint = ModelFingerprint();
  if (!junction_nodes_.empty()) PlaceJunctions();

  // New stages and nodes start with the old tip's history, placed along its tangent.
  const Mat3 R_tip = run_.state.rotation_WB.back();
  const Vec3 p_tip = run_.state.position_W.back();
  auto along = [&](double s) { return Vec3(p_tip + R_tip.col(2) * (s - L_old)); };
  const Vec3 v1 = R_tip * run_.tip_twist1.tail<3>(), v2 = R_tip * run_.tip_twist2.tail<3>();
  for (auto* v : {&strain_now_, &twist_now_, &strain_h_, &twist_h_}) v->resize(stages);
  for (auto* v : {&position_now_, &velocity_W_now_, &velocity_W_h_}) v->resize(stages);
  rotation_now_.resize(stages, R_tip);
  run_.strain1.resize(stages, run_.tip_strain1);
  run_.strain2.resize(stages, run_.tip_strain2);
  run_.twist1.resize(stages, run_.tip_twist1);
  run_.twist2.resize(stages, run_.tip_twist2);
  run_.rotation1.resize(stages, R_tip);
  run_.velocity_W1.resize(stages, v1);
  run_.velocity_W2.resize(stages, v2);
  run_.position1.resize(stages);
  for (int i = 0; i + 1 < n; ++i) {
    if (!StepStartsAt(i) || step_slot_[i] < stages_old) continue;
    const internal::SchemeTable& T = StepTable(i);
    for (int j = 0; j < T.stages; ++j)
      run_.position1[step_slot_[i] + j] =
          along(grid_[i] + T.step[j] * (grid_[i + StepSpan(i)] - grid_[i]));
  }
  RodState& st = run_.state;
  const RodState old = st;
  st.Resize(n);
  for (int i = 0; i < n; ++i) {
    st.s[i] = grid_[i];
    const int j = std::min(i, n_old - 1);
    st.position_W[i] = i < n_old ? old.position_W[i] : along(grid_[i]);
    st.rotation_WB[i] = old.rotation_WB[j];
    st.strain[i] = old.strain[j];
    st.wrench_B[i] = old.wrench_B[j];
    st.twist_B[i] = old.twist_B[j];
  }
  trial_ = st;
  history_ready_ = false;
  stage_strains_current_ = false;
  run_.jacobian_c0 = -1.0;  // another shot: start from its exact Jacobian
}

}  // namespace cosserat
