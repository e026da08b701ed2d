#pragma once
// The quaternion-FD modes' coordinates: the tangent-space reduction of the model's unknowns (free
// vertex displacements, one body rotation per segment) and the reduced mass, diagonal but for the
// 3×3 vertex blocks of a fluid's added mass. Internal to src/analysis.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "cosserat/lie/types.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"

namespace cosserat::detail {

/// The mass block of a vertex with a fluid's added mass: M = m I + m_a (I − t tᵀ), whose
/// eigenvalues are m (along t) and m + m_a (normal to it).
struct VertexMassBlock {
  int column;          ///< first reduced index of the vertex
  double mass, added;  ///< m, m_a, kg
  Vec3 t;              ///< the chord direction at the vertex (world, unit)
  Mat3 Power(double e) const;  ///< M^e
};

/// The tangent-space reduction of the quatfd unknowns: columns of T (full ← reduced) and rows
/// of P = T⁺ (reduced ← full), the reduced mass, and for the shapes which reduced index is what.
struct Reduction {
  Eigen::SparseMatrix<double> T, P;
  Eigen::VectorXd mass;                      ///< the reduced mass's diagonal (kg, kg·m²)
  std::vector<VertexMassBlock> mass_blocks;  ///< replace the diagonal at these vertices
  std::vector<int> vertex_column;            ///< first reduced index of x_n, −1 when prescribed
  std::vector<int> segment_column;           ///< first reduced index of θ_ν
};

/// The reduction at the state q (unit quaternions).
Reduction Reduce(const quatfd::QuatFdModel& model, const Eigen::VectorXd& q);

/// M^e X for the reduced mass M (e = 1 or ±½), `diagonal` = the diagonal's M^e: a row scaling
/// but for the vertex blocks of an added mass.
Eigen::MatrixXd MassTimes(const Reduction& red, const Eigen::VectorXd& diagonal, double e,
                          const Eigen::MatrixXd& X);

/// X M^e likewise (M is symmetric).
Eigen::MatrixXd TimesMass(const Reduction& red, const Eigen::VectorXd& diagonal, double e,
                          const Eigen::MatrixXd& X);

}  // namespace cosserat::detail
