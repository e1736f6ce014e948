// Every knob of the hybrid integrator (paper §3.2-3.4) in one struct with its default.
//
// The config's integrator section is this struct itself; its keys, ranges and meanings are
// declared once in settings_schema.cpp. Tolerances weight each component i by
// atol + rtol |y_i| (positions in length units, p dimensionless; the explicit mode also
// weights velocities this way, with explicit_rtol).
#pragma once

#include <string>

namespace crumple {

enum class IntegrationMode { Implicit = 0, Explicit = 1 };

enum class LinearSolverKind {
  BlockJacobiCG,         ///< "block_jacobi": CG + dense Cholesky of diagonal blocks (paper §3.3)
  PlainCG,               ///< "cg": CG without preconditioner
  IncompleteCholeskyCG,  ///< "incomplete_cholesky": CG + Eigen::IncompleteCholesky
  DirectLDLT,            ///< "ldlt": Eigen::SimplicialLDLT (direct, for comparison)
  TwoLevelCG,            ///< "two_level": CG + block Jacobi + patch rigid motions (two_level.hpp)
};

struct IntegratorSettings {
  IntegrationMode mode_initial = IntegrationMode::Implicit;
  int bdf_order = 4;         ///< highest BDF order (1..4); start-up climbs from 1
  double rtol = 1e-4;        ///< implicit (BDF) relative tolerance
  double atol = 1e-6;        ///< absolute tolerance (length units for x, also used for p, v)
  double h_init = 1e-4;      ///< first step, s
  double h_min = 1e-12;      ///< below this a failing step throws NumericalFailure, s
  double h_max = 1e-1;       ///< s
  /// largest ratio of consecutive quasistatic steps (orders 2-4: also bdf_growth_limit) and of
  /// the controller's step over the last one; after a step shortened to land on an interval's
  /// end the controller grows the step it had proposed, so the explicit step after it may be
  /// up to max_growth times that proposal (RK4 has no ratio limit)
  double max_growth = 2.0;
  double newton_tol = 0.1;   ///< converged when the weighted RMS of (dx, dp) <= newton_tol
  int newton_max_iters = 8;
  int newton_target = 2;     ///< an accepted step that needed more Newton iterations does not grow h
  LinearSolverKind linear_solver = LinearSolverKind::BlockJacobiCG;
  int block_size = 18;       ///< scalar rows per block-Jacobi block (18 = 6 nodes)
  int coarse_nodes = 32;     ///< nodes per patch of the two_level coarse space
  double cg_tol = 1e-2;      ///< CG relative residual |r| / |b|: first Newton iteration (forcing.hpp)
  double cg_tol_max = 1e-1;  ///< loosest, for later iterations close to convergence (= cg_tol: fixed)
  int cg_max_iters = 2000;
  double switch_up = 1e-3;   ///< <a_max/a_ref> above this: implicit -> explicit
  double switch_down = 1e-6; ///< <a_max/a_ref> below this: explicit -> implicit
  int switch_window = 10;    ///< accepted steps in the moving average
  int switch_min_steps = 20; ///< accepted steps in a mode before it may switch again
  double explicit_rtol = 1e-6;  ///< RK4(3) relative tolerance
  /// Largest first explicit step after a switch, in units of the in-plane spring time
  /// sqrt(m / ks). A quasistatic step that fails (not SPD, Newton) where its retry would be
  /// shorter than this is handed over to the explicit mode at once (integrator.hpp).
  double explicit_h_start = 0.2;
  bool plasticity = true;
  double plastic_c0 = 0.1;      ///< yield curvature (19)
  double plastic_gamma = 0.0;   ///< damage-rate constant (19)
  double plastic_rate = 1e4;    ///< 1/s, time scale of the flow (plasticity.hpp, docs/CONFIG.md)
};

/// "implicit" / "explicit"; throws InputError listing the valid names otherwise.
IntegrationMode parse_integration_mode(const std::string& name);
/// "two_level", "block_jacobi", "cg", "incomplete_cholesky", "ldlt"; throws InputError otherwise.
LinearSolverKind parse_linear_solver(const std::string& name);
std::string to_string(LinearSolverKind kind);
/// Throws InputError naming the key when a value is out of the range of integrator_schema().
void validate(const IntegratorSettings& s);

}  // namespace crumple
