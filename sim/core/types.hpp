// Basic vector and matrix types used across crumple.
//
// Positions and velocities of n nodes are stored as one flat Eigen::VectorXd of length 3n
// (node i occupies entries 3i..3i+2), so the solver sees them as plain vectors and a node is
// reached with node(x, i).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <vector>

namespace crumple {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using VecX = Eigen::VectorXd;
using Index = std::int32_t;

/// Row-major sparse matrix: Eigen's CG multiplies it in parallel when OpenMP is linked.
using SpMat = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
/// Column-major sparse matrix (used for Hp = -dF/dp, one column per hinge).
using SpMatCol = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// The 3-vector of node i inside a flat 3n vector.
inline Eigen::Ref<Vec3> node(VecX& x, Index i) { return x.segment<3>(3 * i); }
inline Vec3 node(const VecX& x, Index i) { return x.segment<3>(3 * i); }

}  // namespace crumple
