// Name parsing and range checks of the integrator settings (settings.hpp).
#include "sim/integrate/settings.hpp"

#include "sim/core/errors.hpp"
#include "sim/integrate/settings_schema.hpp"

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
  // The ranges and relations of the config's integrator section (settings_schema.cpp), for
  // settings built in code (tests, benches); a config file gets the same rules with positions.
  if (const std::string problem = schema::check(integrator_schema(), &s); !problem.empty())
    throw InputError("integrator." + problem);
}

}  // namespace crumple
