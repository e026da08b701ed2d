// The constitutive law every solver shares (constitutive/section_law.hpp): its values against the
// closed-form section properties, and the one refusal of a coupled section in every solver.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include "cosserat/analysis/frequency_shooting.hpp"
#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/rod/grid.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.002, kE = 200e9, kNu = 0.3, kRho = 7800;

RodModel SteelWire(double length = 0.5) {
  return RodModel::Uniform(length, CrossSection::Circle(kRadius),
                           Material::FromPoissonRatio(kE, kNu, kRho));
}

// The uniform section with a bending–shear coupling K(0, 4) = K(4, 0) = 0.1 sqrt(K00 K44).
class CoupledSection final : public SectionProfile {
 public:
  explicit CoupledSection(const RodModel& rod) : base_(rod.section) {}
  SectionProperties At(double s, const Actuation& a) const override {
    SectionProperties p = base_->At(s, a);
    const double c = 0.1 * std::sqrt(p.stiffness(0, 0) * p.stiffness(4, 4));
    p.stiffness(0, 4) = p.stiffness(4, 0) = c;
    return p;
  }
  bool IsValid(double length, std::string* why) const override {
    return base_->IsValid(length, why);
  }

 private:
  std::shared_ptr<const SectionProfile> base_;
};

TEST(SectionLaw, UniformCircleMatchesClosedForm) {
  // K = diag(EI, EI, GJ, κGA, κGA, EA), M = ρ diag(I, I, 2I, A, A, A) with I = π r⁴/4, J = 2I and
  // Cowper's κ = 6(1 + ν)/(7 + 6ν) for a circle (Cowper 1966). Exact formulas: 1e-14 relative is
  // round-off of a few products.
  const RodModel rod = SteelWire();
  const SectionLaw law = SectionLaw::At(rod, 0.2, Actuation{});
  const double A = kPi * kRadius * kRadius, I = kPi * std::pow(kRadius, 4) / 4;
  const double G = kE / (2 * (1 + kNu)), kappa = 6 * (1 + kNu) / (7 + 6 * kNu);
  const Vec6 K(kE * I, kE * I, G * 2 * I, kappa * G * A, kappa * G * A, kE * A);
  const Vec6 M(kRho * I, kRho * I, kRho * 2 * I, kRho * A, kRho * A, kRho * A);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(law.stiffness(i) / K(i), 1.0, 1e-14) << i;
    EXPECT_NEAR(law.mass(i) / M(i), 1.0, 1e-14) << i;
  }
  EXPECT_EQ(law.rest_strain, StraightRestStrain());
  EXPECT_DOUBLE_EQ(law.mass_per_length(), kRho * A);
}

TEST(SectionLaw, StaticStrainInvertsTheWrenchAndDampingAddsTheRate) {
  // W(ξ(W), 0) = W: K (ξ* + K⁻¹ W − ξ*) = W to round-off (1e-15 relative per entry, one division
  // and one product); with a strain rate the Kelvin–Voigt term D ξ̇ adds exactly.
  SectionLaw law;
  law.stiffness << 2.0, 3.0, 1.5, 40.0, 40.0, 90.0;
  law.damping << 0.1, 0.1, 0.05, 0.0, 0.0, 0.3;
  law.rest_strain << 0.5, 0.0, 0.0, 0.0, 0.0, 1.0;
  const Vec6 W(0.3, -0.2, 0.1, 1.0, -2.0, 5.0);
  const Vec6 back = law.Wrench(law.StaticStrain(W), Vec6::Zero());
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(back(i), W(i), 1e-15 * (1 + std::abs(W(i))));
  const Vec6 rate(1, 2, 3, 4, 5, 6);
  const Vec6 damped = law.Wrench(law.StaticStrain(W), rate);
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(damped(i) - back(i), law.damping(i) * rate(i), 1e-14) << i;
}

// Every solver refuses a coupled section with the one message of PrincipalAxesSectionAt.
void ExpectRefused(const std::function<void()>& build, const char* who) {
  try {
    build();
    ADD_FAILURE() << who << " accepted a coupled section";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sections must be principal-axes"), std::string::npos)
        << who << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find("stiffness"), std::string::npos) << who;
  }
}

TEST(SectionLaw, CoupledSectionRefusedByEverySolver) {
  RodModel rod = SteelWire();
  rod.section = std::make_shared<CoupledSection>(SteelWire());
  ExpectRefused([&] { StaticShootingSolver solver(rod, 21); }, "StaticShootingSolver");
  ExpectRefused([&] { Bdf2ShootingStepper stepper(rod, 21); }, "Bdf2ShootingStepper");
  ExpectRefused([&] { quatfd::QuatFdModel model(rod, lie::SE3{}, quatfd::QuatFdOptions{}); },
                "QuatFdModel");
  ExpectRefused(
      [&] {
        FrequencyShooting f(rod, MakeGrid(rod.length, 21, {}), lie::SE3{}, StaticLoads{},
                            Vec6::Zero());
      },
      "FrequencyShooting");
  // The plain rod is accepted by all of them.
  const RodModel plain = SteelWire();
  EXPECT_NO_THROW(StaticShootingSolver(plain, 21));
  EXPECT_NO_THROW(Bdf2ShootingStepper(plain, 21));
}

}  // namespace
}  // namespace cosserat
