// Name parsing and range checks of the integrator settings (settings.hpp).
#include "sim/integrate/settings.hpp"

#include "sim/core/errors.hpp"

namespace crumple {

IntegrationMode parse_integration_mode(const std::string& name) {
  if (name == "explicit") return IntegrationMode::Explicit;
  if (name == "implicit") return IntegrationMode::Implicit;
  throw InputError("unknown integrator mode '" + name + "'; valid: explicit, implicit");
}

LinearSolverKind parse_linear_solver(const std::string& name) {
  if (name == "block_jacobi") return LinearSolverKind::BlockJacobiCG;
  if (name == "cg") return LinearSolverKind::PlainCG;
  if (name == "incomplete_cholesky") return LinearSolverKind::IncompleteCholeskyCG;
  if (name == "ldlt") return LinearSolverKind::DirectLDLT;
  if (name == "two_level") return LinearSolverKind::TwoLevelCG;
  throw InputError("unknown linear solver '" + name +
                   "'; valid: two_level, block_jacobi, cg, incomplete_cholesky, ldlt");
}

std::string to_string(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::BlockJacobiCG: return "block_jacobi";
    case LinearSolverKind::PlainCG: return "cg";
    case LinearSolverKind::IncompleteCholeskyCG: return "incomplete_cholesky";
    case LinearSolverKind::DirectLDLT: return "ldlt";
    case LinearSolverKind::TwoLevelCG: return "two_level";
  }
  return "?";
}

void validate(const IntegratorSettings& s) {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw InputError(std::string("integrator: ") + what);
  };
  require(s.bdf_order >= 1 && s.bdf_order <= 4, "bdf_order must be 1..4");
  require(s.rtol > 0 && s.atol > 0 && s.explicit_rtol > 0, "tolerances must be > 0");
  require(s.h_min > 0 && s.h_init >= s.h_min && s.h_max >= s.h_init,
          "need 0 < h_min <= h_init <= h_max");
  require(s.max_growth > 1.0, "max_growth must be > 1");
  require(s.newton_tol > 0 && s.newton_max_iters >= 1, "newton_tol > 0, newton_max_iters >= 1");
  require(s.newton_target >= 1, "newton_target >= 1");
  require(s.block_size >= 1, "block_size must be >= 1");
  require(s.coarse_nodes >= 3, "coarse_nodes must be >= 3");
  require(s.cg_tol > 0 && s.cg_max_iters >= 1, "cg_tol > 0, cg_max_iters >= 1");
  require(s.cg_tol <= s.cg_tol_max && s.cg_tol_max < 1, "need cg_tol <= cg_tol_max < 1");
  require(s.switch_down < s.switch_up, "switch_down must be below switch_up");
  require(s.switch_window >= 1 && s.switch_min_steps >= 0, "switch_window >= 1");
  require(s.explicit_h_start > 0, "explicit_h_start must be > 0");
  require(s.plastic_c0 >= 0 && s.plastic_c0 < 2, "plastic_c0 must be in [0, 2)");
  require(s.plastic_gamma >= 0 && s.plastic_rate >= 0, "plastic_gamma, plastic_rate >= 0");
}

}  // namespace crumple
