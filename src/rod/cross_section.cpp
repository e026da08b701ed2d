#include "cosserat/rod/cross_section.hpp"

#include <algorithm>
#include <cmath>

namespace cosserat {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

CrossSection CrossSection::Circle(double radius) {
  CrossSection c;
  c.shape = SectionShape::kCircle;
  c.outer_radius = radius;
  c.area = kPi * radius * radius;
  c.I1 = c.I2 = kPi * std::pow(radius, 4) / 4.0;
  c.torsion_constant = c.I1 + c.I2;
  return c;
}

CrossSection CrossSection::Annulus(double outer_radius, double inner_radius) {
  CrossSection c;
  c.shape = SectionShape::kAnnulus;
  c.outer_radius = outer_radius;
  c.inner_radius = inner_radius;
  c.area = kPi * (outer_radius * outer_radius - inner_radius * inner_radius);
  c.I1 = c.I2 = kPi * (std::pow(outer_radius, 4) - std::pow(inner_radius, 4)) / 4.0;
  c.torsion_constant = c.I1 + c.I2;
  return c;
}

CrossSection CrossSection::Rectangle(double width, double height) {
  CrossSection c;
  c.shape = SectionShape::kRectangle;
  c.width = width;
  c.height = height;
  c.area = width * height;
  c.I1 = width * std::pow(height, 3) / 12.0;
  c.I2 = height * std::pow(width, 3) / 12.0;
  // Saint-Venant torsion constant of a solid rectangle with half-sides a >= b (Roark, Table 10.1):
  // J = a b³ (16/3 − 3.36 (b/a)(1 − b⁴/(12 a⁴))); error below 4 % for all aspect ratios.
  const double a = 0.5 * std::max(width, height);
  const double b = 0.5 * std::min(width, height);
  c.torsion_constant =
      a * b * b * b * (16.0 / 3.0 - 3.36 * (b / a) * (1.0 - std::pow(b / a, 4) / 12.0));
  return c;
}

CrossSection CrossSection::Explicit(double area, double I1, double I2, double torsion_constant,
                                    double shear_coefficient, double outer_diameter) {
  CrossSection c;
  c.outer_radius = 0.5 * outer_diameter;
  c.shape = SectionShape::kExplicit;
  c.area = area;
  c.I1 = I1;
  c.I2 = I2;
  c.torsion_constant = torsion_constant;
  c.explicit_shear_coefficient = shear_coefficient;
  return c;
}

double CrossSection::ShearCoefficient(double nu) const {
  switch (shape) {
    case SectionShape::kCircle:
      return 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
    case SectionShape::kAnnulus: {
      const double m = inner_radius / outer_radius;
      const double q = (1.0 + m * m) * (1.0 + m * m);
      return 6.0 * (1.0 + nu) * q / ((7.0 + 6.0 * nu) * q + (20.0 + 12.0 * nu) * m * m);
    }
    case SectionShape::kRectangle:
      return 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
    case SectionShape::kExplicit:
      return explicit_shear_coefficient;
  }
  return 1.0;
}

bool CrossSection::IsValid(std::string* why) const {
  auto bad = [&](const char* name) {
    if (why) *why = std::string(name) + " must be a finite positive number";
    return false;
  };
  auto ok = [](double v) { return std::isfinite(v) && v > 0.0; };
  // The sizes the fluid, contact and stress read: a negative radius gives positive A and I and
  // a negative diameter, which turns drag and buoyancy around.
  if ((shape == SectionShape::kCircle || shape == SectionShape::kAnnulus) && !ok(outer_radius))
    return bad(shape == SectionShape::kCircle ? "radius" : "outer_radius");
  if (shape == SectionShape::kRectangle && !ok(width)) return bad("width");
  if (shape == SectionShape::kRectangle && !ok(height)) return bad("height");
  if (shape == SectionShape::kExplicit && !(std::isfinite(outer_radius) && outer_radius >= 0.0)) {
    if (why) *why = "outer_diameter must be a finite number >= 0 (0: the disc of equal area)";
    return false;
  }
  if (shape == SectionShape::kAnnulus && !(inner_radius >= 0.0 && inner_radius < outer_radius)) {
    if (why) *why = "inner_radius must be >= 0 and smaller than outer_radius";
    return false;
  }
  if (!ok(area)) return bad("area");
  if (!ok(I1)) return bad("I1");
  if (!ok(I2)) return bad("I2");
  if (!ok(torsion_constant)) return bad("J");
  if (!ok(explicit_shear_coefficient)) return bad("shear_coefficient");
  return true;
}

double CrossSection::OuterDiameter() const {
  switch (shape) {
    case SectionShape::kCircle:
    case SectionShape::kAnnulus:
      return 2.0 * outer_radius;
    case SectionShape::kExplicit:
      if (outer_radius > 0.0) return 2.0 * outer_radius;
      break;
    case SectionShape::kRectangle:
      break;
  }
  return std::sqrt(4.0 * area / M_PI);
}

}  // namespace cosserat
