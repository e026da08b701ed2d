#pragma once
/// \file
/// Geometric properties of a rod's cross-section, in the body frame (x, y in the section plane,
/// z along the centreline). Units: m, m², m⁴.

#include <string>

namespace cosserat {

enum class SectionShape { kCircle, kAnnulus, kRectangle, kExplicit };

struct CrossSection {
  SectionShape shape = SectionShape::kCircle;
  double area = 0.0;            ///< A, m²
  double I1 = 0.0;              ///< second moment of area about body x, m⁴
  double I2 = 0.0;              ///< second moment of area about body y, m⁴
  double torsion_constant = 0;  ///< J (Saint-Venant), m⁴; equals I1 + I2 for circles and annuli
  /// Shape dimensions, kept for the shear coefficient (m); an explicit section's outer_radius is
  /// half its outer_diameter. Zero where not used.
  double outer_radius = 0.0, inner_radius = 0.0, width = 0.0, height = 0.0;
  /// Shear coefficient of an explicit section (dimensionless); ignored for the other shapes.
  double explicit_shear_coefficient = 1.0;

  static CrossSection Circle(double radius);
  static CrossSection Annulus(double outer_radius, double inner_radius);
  /// width along body x, height along body y: I1 = w h³/12, I2 = h w³/12.
  static CrossSection Rectangle(double width, double height);
  /// outer_diameter (m): the outline's, for the fluid, contact and stress; 0: the disc of
  /// equal area.
  static CrossSection Explicit(double area, double I1, double I2, double torsion_constant,
                               double shear_coefficient = 1.0, double outer_diameter = 0.0);

  /// Diameter of the disc the section displaces and touches with, m: 2 r for circles and the
  /// outer 2 r_o of annuli; an explicit section's outer_diameter when given; the disc of equal
  /// area for rectangles and other explicit sections.
  double OuterDiameter() const;

  /// Polar second moment I1 + I2 (m⁴), used for rotary inertia about the centreline.
  double PolarMoment() const { return I1 + I2; }

  /// Timoshenko shear coefficient κ (dimensionless) for Poisson ratio ν, after Cowper (1966):
  /// circle 6(1+ν)/(7+6ν); annulus with m = ri/ro 6(1+ν)(1+m²)²/((7+6ν)(1+m²)² + (20+12ν)m²);
  /// rectangle 10(1+ν)/(12+11ν); explicit: the value given.
  double ShearCoefficient(double poisson_ratio) const;

  /// True if every property is finite and positive; otherwise writes the reason.
  bool IsValid(std::string* why) const;
};

}  // namespace cosserat
