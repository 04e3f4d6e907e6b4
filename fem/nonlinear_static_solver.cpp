#include "fem/nonlinear_static_solver.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/SparseLU>

namespace flapsim::fem {

NonlinearStaticResult solve_nonlinear_static(const CorotationalModel& model, const Constraints& constraints,
                                             const Eigen::VectorXd& F, CorotationalState& state,
                                             const NonlinearStaticOptions& opt) {
  if (F.size() != model.num_dofs())
    throw std::invalid_argument("solve_nonlinear_static: load vector size does not match the DOF count");
  NonlinearAssembler asmb(model, constraints, TangentForm::Consistent);
  const std::vector<int>& free = asmb.free_dofs();
  const Eigen::Index nf = static_cast<Eigen::Index>(free.size());
  Eigen::VectorXd f_int(model.num_dofs()), r(nf), dx(nf), du = Eigen::VectorXd::Zero(model.num_dofs());
  double Fnorm = 0.0;
  for (int d : free) Fnorm += F(d) * F(d);
  Fnorm = std::sqrt(Fnorm);
  NonlinearStaticResult res;
  if (nf == 0) {
    res.converged = true;
    return res;
  }
  // The consistent (non-symmetric) tangent with sparse LU: quadratic Newton
  // convergence under applied moments, and no trouble where an iterate's
  // tangent is indefinite.
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> llt;
  llt.analyzePattern(asmb.tangent());
  CorotationalState last = state;
  for (int step = 1; step <= opt.load_steps; ++step) {
    const double lambda = static_cast<double>(step) / opt.load_steps;
    bool ok = false;
    for (int it = 0; it < opt.max_iterations; ++it) {
      res.strain_energy = asmb.evaluate(state, f_int, true);
      for (Eigen::Index i = 0; i < nf; ++i) r(i) = lambda * F(free[i]) - f_int(free[i]);
      res.residual = Fnorm > 0.0 ? r.norm() / Fnorm : r.norm();
      if (!std::isfinite(res.residual)) break;
      if (res.residual <= opt.tolerance) {
        ok = true;
        break;
      }
      llt.factorize(asmb.tangent());
      if (llt.info() != Eigen::Success) {
        res.failure = "load step " + std::to_string(step) + ", iteration " + std::to_string(it) +
                      ": the tangent stiffness is singular";
        state = last;
        return res;
      }
      dx = llt.solve(r);
      ++res.total_iterations;
      du.setZero();
      for (Eigen::Index i = 0; i < nf; ++i) du(free[i]) = dx(i);
      apply_increment(state, du);
    }
    if (!ok) {
      if (res.failure.empty())
        res.failure = "load step " + std::to_string(step) + ": Newton did not converge in " +
                      std::to_string(opt.max_iterations) + " iterations (relative residual " +
                      std::to_string(res.residual) + ")";
      state = last;
      return res;
    }
    last = state;
    res.load_steps_done = step;
  }
  res.converged = true;
  return res;
}

}  // namespace flapsim::fem
