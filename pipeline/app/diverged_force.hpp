#pragma once
/// \file diverged_force.hpp
/// \brief A run whose aerodynamic force leaves every physical range stops as diverged
/// (NumericalFailure, exit status 3) instead of finishing with a number that means nothing.
///
/// The bound is a force coefficient on the fastest speed any point of the undeformed wing
/// has through the air over a wingbeat, U_b = max over the cycle and the lattice's nodes of
/// |U∞ − v_pivot − ω × (R_GW x_W)|: |F| ≤ kDivergedForceCoefficient · ½ ρ U_b² S. A
/// revolving wing's force coefficient on its speed at r₂R peaks at about 3.5 (its drag at 90°
/// incidence in the fit of [Dickinson et al. 1999]), and U_b exceeds that speed (the tip,
/// the fastest instant: the hawkmoth hover's ½ρU_b²S is 9.7 times its ½ρU_ref²S, so its
/// largest force, C_L ≈ 9 on U_ref at the reversals, is about 0.9 on U_b). 20 is several
/// times any of these: no wing that the lattice still represents reaches it.
/// A free-wake lattice that has come apart does (a leading-edge sheet that folds onto the
/// wing, a wake vortex through a collocation point): its force grows without bound within
/// tens of steps (docs/fsi.md, "Failures"). The check starts at the second step: the first
/// carries the impulse of a wing started in moving air, ρ ∂Γ/∂t with Γ set up within one
/// step, which grows as 1/Δt (a flat plate at 45° started in a free stream: at 16 steps a
/// chord C_F = 19 at step 1, 3.4 at step 2; at 64 steps 72 and 3.0) [Katz & Plotkin 2001, ch. 13].

#include <Eigen/Core>

#include <string>

#include "mbd/base_motion.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

inline constexpr double kDivergedForceCoefficient = 20.0;

/// U_b [m/s] of the file comment: `nodes` the lattice's nodes in the wing frame W [m], the
/// base's motion sampled at `samples` instants of the run's first period [s] and as many of
/// its last (a run of `duration` [s]; 0: one period). A revolving wing that speeds up over
/// longer than a cycle (revolution.ramp_s) reaches its speed only later: sampled over the
/// first cycle alone its bound was that of a wing nearly at rest, and a valid run stopped
/// as diverged at 8e-7 N (ramp 0.5 s of a 26 Hz cycle, the Robofly case with a 2 s ramp).
/// The kinematics are periodic but for the revolution, whose rate only grows: the first and
/// last periods hold the largest speed.
double fastest_wing_point_speed(const mbd::BaseMotion& base, double period, const Eigen::Matrix3Xd& nodes,
                                const Eigen::Vector3d& free_stream, int samples = 400, double duration = 0.0);

/// a_b [m/s²]: the largest acceleration of a lattice node (`nodes` in W [m]) over the same
/// instants as fastest_wing_point_speed: |a_pivot + ω̇ × r + ω × (ω × r)|.
double fastest_wing_point_acceleration(const mbd::BaseMotion& base, double period,
                                       const Eigen::Matrix3Xd& nodes, int samples = 400,
                                       double duration = 0.0);

/// The largest aerodynamic force [N] a run may carry: kDivergedForceCoefficient (½ ρ U_b² S
/// + (π/4) ρ c̄ a_b S), the second term the added mass of a plate of chord c̄ (π/4 ρ c̄² a per
/// span) [Katz & Plotkin 2001, §13.8]: a wing that starts from rest carries the force of its
/// acceleration before it has any speed (a revolution ramped up over 5 s or 10⁶ s stopped as
/// diverged at step 2 with 1e-9 N against a bound of U_b alone of 1e-9 N, 1e-16 against 2e-25).
double diverged_force_limit(double rho, double fastest_speed, double area, double fastest_acceleration = 0.0,
                            double mean_chord = 0.0);

/// Throws NumericalFailure (with the step and time) when |force| exceeds `limit` [N].
void throw_if_force_diverged(const Eigen::Vector3d& force, double limit, long step, double time);

/// The largest change of the lift coefficient between two consecutive recorded steps [-], and
/// the later of the two (1-based step).
struct LiftJump {
  double size = 0.0;
  long step = 0;
};

/// What a user can change when a run with these numerics fails in its time loop (the force
/// bound above, its coupling, its structure): with leading_edge = "shed" the leading-edge
/// sheet comes apart near the wing (a hover at an advanced rotation phase, a forward flight,
/// docs/uvlm.md), its loads jumping from step to step (`jump`, the evidence the text quotes),
/// and the sheet's own core at half a mean chord keeps it together in more runs (the rigid
/// hawkmoth hover's rotation-phase study, 12 cycles: 6 of 7 phases run through against 4 of 7
/// with the wake's core; cases/bench_hover.toml with its sheet unmerged: 3 wingbeats through
/// against a stop at step 192; the flexible hover of cases/hover_flexible.toml in a 3 m/s
/// forward flight: 6 wingbeats through against a stop at step 190); "separated", the
/// default, sheds no sheet. Empty for the other leading-edge models. \p recorded_steps: the
/// steps history.csv holds; a jump into a later step (the one that failed, measured but in no
/// output) is said to be that step's.
std::string diverged_lattice_advice(const io::Case::Numerics& numerics, LiftJump jump, long recorded_steps);

}  // namespace flapsim::app
