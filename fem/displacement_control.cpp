#include "fem/displacement_control.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/SparseLU>

namespace flapsim::fem {

DisplacementControlResult solve_displacement_controlled(const CorotationalModel& model,
                                                        const Constraints& constraints, int controlled_dof,
                                                        double value, CorotationalState& state,
                                                        const DisplacementControlOptions& opt) {
  if (controlled_dof < 0 || controlled_dof >= model.num_dofs() || controlled_dof % kDofsPerNode >= 3)
    throw std::invalid_argument("solve_displacement_controlled: the controlled DOF must be a translation");
  if (constraints.is_fixed(controlled_dof))
    throw std::invalid_argument("solve_displacement_controlled: the controlled DOF is fixed");
  Constraints c = constraints;
  c.fix_dof(controlled_dof);
  NonlinearAssembler asmb(model, c, TangentForm::Consistent);
  const std::vector<int>& free = asmb.free_dofs();
  const Eigen::Index nf = static_cast<Eigen::Index>(free.size());
  Eigen::VectorXd f_int(model.num_dofs()), r(nf), dx(nf), du = Eigen::VectorXd::Zero(model.num_dofs());
  const CorotationalState start = state;
  const int node = controlled_dof / kDofsPerNode, d = controlled_dof % kDofsPerNode;
  state.position[static_cast<size_t>(node)][d] = model.reference_positions[static_cast<size_t>(node)][d] + value;
  Eigen::Vector3d lo = model.reference_positions[0], hi = lo;
  for (const Eigen::Vector3d& p : model.reference_positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double size = (hi - lo).norm();  // [m]
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  lu.analyzePattern(asmb.tangent());
  DisplacementControlResult res;
  for (int it = 0; it <= opt.max_iterations; ++it) {
    asmb.evaluate(state, f_int, true);
    for (Eigen::Index i = 0; i < nf; ++i) r(i) = -f_int(free[static_cast<size_t>(i)]);
    const double scale = f_int.norm();
    res.residual = scale > 0.0 ? r.norm() / scale : r.norm();
    res.reaction = f_int(controlled_dof);
    if (!std::isfinite(res.residual)) {
      res.failure = "iteration " + std::to_string(it) + ": the residual is not finite";
      break;
    }
    if (res.residual <= opt.tolerance || r.norm() == 0.0) {
      res.converged = true;
      return res;
    }
    if (it == opt.max_iterations) break;
    lu.factorize(asmb.tangent());
    if (lu.info() != Eigen::Success) {
      res.failure = "iteration " + std::to_string(it) + ": the tangent stiffness is singular";
      break;
    }
    dx = lu.solve(r);
    ++res.iterations;
    double max_t = 0.0, max_r = 0.0;
    for (Eigen::Index i = 0; i < nf; ++i) {
      const int g = free[static_cast<size_t>(i)];
      du(g) = dx(i);
      double& m = g % kDofsPerNode < 3 ? max_t : max_r;
      m = std::max(m, std::abs(dx(i)));
    }
    apply_increment(state, du);
    if (max_t <= opt.increment_tolerance * size && max_r <= opt.increment_tolerance) {
      asmb.evaluate(state, f_int, false);
      res.reaction = f_int(controlled_dof);
      res.converged = true;
      return res;
    }
  }
  if (res.failure.empty())
    res.failure = "Newton did not converge in " + std::to_string(opt.max_iterations) +
                  " iterations (relative residual " + std::to_string(res.residual) + ")";
  state = start;
  return res;
}

}  // namespace flapsim::fem
