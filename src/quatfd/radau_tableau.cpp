#include "cosserat/quatfd/radau_tableau.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>

namespace cosserat::quatfd {
namespace {

RadauIIA3Tableau Build() {
  RadauIIA3Tableau k;
  const double s6 = std::sqrt(6.0);
  k.c[0] = (4 - s6) / 10;
  k.c[1] = (4 + s6) / 10;
  k.c[2] = 1;
  const double a[3][3] = {{(88 - 7 * s6) / 360, (296 - 169 * s6) / 1800, (-2 + 3 * s6) / 225},
                          {(296 + 169 * s6) / 1800, (88 + 7 * s6) / 360, (-2 - 3 * s6) / 225},
                          {(16 - s6) / 36, (16 + s6) / 36, 1.0 / 9}};
  Eigen::Matrix3d Am;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) k.A[i][j] = Am(i, j) = a[i][j];
  const Eigen::Matrix3d Ai = Am.inverse();
  Eigen::EigenSolver<Eigen::Matrix3d> es(Ai);
  int real = 0, cplx = 0;
  for (int e = 0; e < 3; ++e) {
    if (std::abs(es.eigenvalues()[e].imag()) < 1e-12) real = e;
    if (es.eigenvalues()[e].imag() < -1e-12) cplx = e;  // λ = α − iβ gives the [[α, −β], [β, α]] block
  }
  Eigen::Matrix3d Tm;
  Tm.col(0) = es.eigenvectors().col(real).real();
  Tm.col(1) = es.eigenvectors().col(cplx).real();
  Tm.col(2) = es.eigenvectors().col(cplx).imag();
  const Eigen::Matrix3d Tinv = Tm.inverse();
  const Eigen::Matrix3d L = Tinv * Ai * Tm;
  k.gamma = L(0, 0);
  k.alpha = L(1, 1);
  k.beta = L(2, 1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) k.T[i][j] = Tm(i, j), k.Ti[i][j] = Tinv(i, j), k.Ainv[i][j] = Ai(i, j);
  k.dd[0] = -(13 + 7 * s6) / 3;
  k.dd[1] = (-13 + 7 * s6) / 3;
  k.dd[2] = -1.0 / 3;
  return k;
}

}  // namespace

const RadauIIA3Tableau& RadauIIA3() {
  static const RadauIIA3Tableau k = Build();
  return k;
}

}  // namespace cosserat::quatfd
