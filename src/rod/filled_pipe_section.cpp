#include "cosserat/rod/filled_pipe_section.hpp"

#include <cmath>
#include <utility>

namespace cosserat {

FilledPipeSection::FilledPipeSection(std::shared_ptr<const SectionProfile> pipe,
                                     double contents_mass_per_length)
    : pipe_(std::move(pipe)), contents_(contents_mass_per_length) {}

SectionProperties FilledPipeSection::At(double s, const Actuation& actuation) const {
  SectionProperties p = pipe_->At(s, actuation);
  for (int i = 3; i < 6; ++i) p.mass(i, i) += contents_;  // translation only
  return p;
}

bool FilledPipeSection::IsValid(double length, std::string* why) const {
  if (!pipe_) {
    if (why) *why = "a filled pipe needs the pipe's section";
    return false;
  }
  if (!(std::isfinite(contents_) && contents_ >= 0)) {
    if (why) *why = "the contents' mass per length must be finite and >= 0 (kg/m)";
    return false;
  }
  return pipe_->IsValid(length, why);
}

}  // namespace cosserat
