#pragma once
/// \file plate_wing_fixtures.hpp
/// \brief The flat-plate wing and the rotation-phase paper's kinematics (eq. 8) that the
/// coupling tests of tests/fsi drive.

#include "fem/structural_model.hpp"
#include "fem/structured_mesh.hpp"
#include "mbd/angle_units.hpp"
#include "mbd/chain_model.hpp"
#include "mbd/wing_kinematics.hpp"
#include "uvlm/planform_grid.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/fsi/fem_structure.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <algorithm>
#include <vector>

namespace flapsim::test {

// A flat rectangular wing, chord 10 mm, span 40 mm, leading edge at x = 2.5 mm (the
// flat plate of wings/flat_plate.toml), as a lattice grid in the wing frame.
inline uvlm::PlanformGrid plate_grid(int nc, int ns) {
  uvlm::PlanformGridOptions o;
  o.chordwise = nc;
  o.spanwise = ns;
  uvlm::PlanformGrid g = uvlm::make_rectangular_grid(0.010, 0.040, o);
  for (Eigen::Index k = 0; k < g.nodes.cols(); ++k) g.nodes(0, k) += 0.0025;
  return g;
}

// The same plate as shells (3 × 8 cells, each two triangles), root edge at y = 0: aluminium,
// ν = 0.3, ρ = 2700 kg/m³, E = 70 GPa unless given; thickness [m].
inline fem::StructuralModel plate_shells(double thickness, double youngs_modulus = 70e9) {
  fem::StructuralModel sm;
  sm.mesh = fem::rectangle_mesh(0.0025 - 0.010, 0.0, 0.010, 0.040, 3, 8);
  fem::ShellProperties shell;
  shell.thickness = thickness;
  shell.youngs_modulus = youngs_modulus;
  shell.poisson_ratio = 0.3;
  shell.density = 2700.0;
  sm.shell.assign(sm.mesh.triangles.size(), shell);
  return sm;
}

// The nodes of a plate_shells mesh on its root edge (y = 0): the clamped ones.
inline std::vector<int> plate_root_nodes(const fem::Mesh& mesh) {
  std::vector<int> root;
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (mesh.nodes[static_cast<std::size_t>(n)].y() < 1e-12) root.push_back(n);
  return root;
}

// The same upward force [N] on each of `panels` lattice panels (applied at the origin).
inline uvlm::PanelLoads uniform_panel_lift(int panels, double newtons) {
  uvlm::PanelLoads load;
  load.force = Eigen::Matrix3Xd::Zero(3, panels);
  load.force.row(2).setConstant(newtons);
  load.point = Eigen::Matrix3Xd::Zero(3, panels);
  return load;
}

inline mbd::WingKinematics eq8_kinematics(double rotation_phase) {
  // Eq. 8 of the rotation-phase paper: φ = 10° + 50° cos(2π(ft + δψ)), α = 90° − 45° sin(2πft).
  mbd::WingKinematics k;
  k.frequency = 26.1;
  k.rotation_phase = rotation_phase;
  k.sweep = mbd::PeriodicSignal::harmonic(10.0 * kDegToRad, {50.0 * kDegToRad}, {});
  k.deviation = mbd::PeriodicSignal::harmonic(0.0, {}, {});
  k.rotation = mbd::PeriodicSignal::harmonic(90.0 * kDegToRad, {}, {-45.0 * kDegToRad});
  return k;
}

// The plate as a rigid wing: one body welded to the base (mass and inertia for outputs only).
inline mbd::ChainModel rigid_plate_chain() {
  mbd::ChainModel c;
  mbd::ChainBody b;
  b.length = 0.040;
  b.mass = 1e-4;
  b.center_of_mass = Eigen::Vector3d(-0.0025, 0.02, 0.0);
  b.inertia = Eigen::Vector3d(1.3e-8, 1e-9, 1.4e-8).asDiagonal();
  b.outboard_joint = Eigen::Vector3d(0.0, 0.040, 0.0);
  c.bodies = {b};
  c.joints = {mbd::ChainJoint{}};
  return c;
}

// The plate's coupled model at eq. 8's 26.1 Hz: its nc × ns lattice (cores of 0.2 chord),
// a wake for `steps` steps, the coupling to τ = 1e-8.
inline fsi::FsiModel plate_fsi_model(std::shared_ptr<const fsi::StructureModel> structure, int nc, int ns,
                                     int steps) {
  fsi::FsiModel m;
  m.structure = std::move(structure);
  m.frequency = 26.1;
  m.lattice.chordwise = nc;
  m.lattice.spanwise = ns;
  m.lattice.core.radius = 0.2 * 0.010;
  m.lattice.wake_capacity = steps;
  m.coupling.tolerance = 1e-8;
  return m;
}

// A structure's model in vacuum (no lattice), its frequency 10 Hz.
inline fsi::FsiModel vacuum_fsi_model(std::shared_ptr<const fsi::StructureModel> structure) {
  fsi::FsiModel m;
  m.structure = std::move(structure);
  m.frequency = 10.0;
  m.air = false;
  return m;
}

// `steps` coupled steps of dt [s] of an FEM run from d's state: each step's lift [N] appended
// to `lift`, the FEM's node positions [m] to `x` (3 × nodes columns a step). Returns the
// largest coupling change of the steps.
inline double fly_fem_plate(const fsi::FsiModel& m, fsi::FsiData& d, int steps, double dt, std::vector<double>& lift,
                            Eigen::Matrix3Xd& x) {
  double worst = 0.0;
  for (int n = 0; n < steps; ++n) {
    fsi::coupled_step(m, d, dt);
    lift.push_back(d.lattice->loads.total_force.z());
    fsi::shed_wake(m, d);
    const auto& s = static_cast<const fsi::FemStructureData&>(*d.structure);
    const Eigen::Index nodes = s.trial_positions().cols();
    x.conservativeResize(3, x.cols() + nodes);
    x.rightCols(nodes) = s.trial_positions();
    worst = std::max(worst, d.last_change);
  }
  return worst;
}

}  // namespace flapsim::test
