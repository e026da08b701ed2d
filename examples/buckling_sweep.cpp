// Design chart for a soft joint: the critical axial load of a column with one soft band
// (EI → α EI over 5 % of the length, a constrictive band), against the band's position
// and its factor α, for a cantilever and a pinned–pinned column. Also where the mode bends most.
//
//   build/examples/buckling_sweep [notebooks-data]
// writes <dir>/buckling_band_sweep.csv
//   (boundary,alpha,band_start,band_end,critical_load,critical_over_euler,mode_s_max), loads in N.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cosserat/analysis/buckling.hpp"
#include "cosserat/rod/section_profile.hpp"

int main(int argc, char** argv) {
  using namespace cosserat;
  const std::filesystem::path dir = argc > 1 ? argv[1] : "notebooks-data";
  const double L = 0.5, r = 0.001, width = 0.05 * L, pi = 3.14159265358979;
  const Material steel = Material::FromShearModulus(200e9, 80e9, 8000);
  const CrossSection circle = CrossSection::Circle(r);
  const double EI = steel.youngs_modulus * circle.I1;
  auto uniform = std::make_shared<UniformSection>(circle, steel);

  std::filesystem::create_directories(dir);
  std::ofstream out(dir / "buckling_band_sweep.csv");
  out << "boundary,alpha,band_start,band_end,critical_load,critical_over_euler,mode_s_max\n";
  out.precision(10);
  int failures = 0;
  for (ColumnEnds ends : {ColumnEnds::kClampedFree, ColumnEnds::kPinnedPinned}) {
    const double euler = (ends == ColumnEnds::kClampedFree ? 0.25 : 1.0) * pi * pi * EI / (L * L);
    BucklingOptions options;
    options.lambda_max = 1.2 * euler;
    options.scan_steps = 24;
    for (double alpha : {1.0, 0.6, 0.36, 0.2, 0.1}) {
      for (int k = 0; k < 19; ++k) {
        const double start = k * (L - width) / 18;
        RodModel model = RodModel::Uniform(L, circle, steel);
        model.section = std::make_shared<BandedSection>(
            uniform, std::vector<BandedSection::Band>{{start, start + width, alpha}});
        BucklingAnalysis analysis(model, 41, ends, lie::SE3{}, LoadPath::TipForce(Vec3(0, 0, -1)),
                                  options);
        const BucklingSummary b = analysis.FindCriticalLoad();
        if (!b.found()) ++failures;
        out << ToString(ends) << ',' << alpha << ',' << start << ',' << start + width << ','
            << b.critical_load << ',' << b.critical_load / euler << ','
            << (b.found() ? b.mode.s_max_curvature : NAN) << '\n';
        if (alpha == 1.0) break;  // no band: one row
      }
    }
  }
  std::cout << "wrote " << (dir / "buckling_band_sweep.csv").string() << '\n';
  return failures == 0 ? 0 : 1;
}
