#pragma once
/// \file phase_analysis.hpp
/// \brief Reading a run's time series the way the rotation-phase paper does: Euler
/// angles of a body in the stroke-plane frame, cycle means, and the rotation phase of
/// base and tip from the α = 90° crossings (the paper's point A, Fig. 10).
///
/// Euler angles are those of the base convention R_SW = Rz(φ) · Rx(θ) · Ry(−α)
/// (mbd::stroke_rotation and its inverse mbd::stroke_angles, docs/kinematics.md).
/// For a body of the chain the frame compared is R_GS^T R_GB R_WR^T: the body's rotation
/// relative to the chain's undeformed orientation, so the tip's angles equal the base's
/// when the wing does not deform.

#include <Eigen/Core>
#include <Eigen/Core>

#include <optional>
#include <vector>

#include "mbd/chain_data.hpp"
#include "mbd/chain_model.hpp"
#include "mbd/wing_kinematics.hpp"

namespace flapsim::fsi {

/// \brief Euler angles of body \p body (0-based) of the chain relative to the chain's
/// undeformed orientation, in the stroke-plane frame: mbd::stroke_angles(R_GSᵀ R_GB R_WRᵀ) with
/// R_GS = Ry(β). They equal the base's angles when the wing does not deform.
/// \param stroke_plane_angle  β [rad]
mbd::StrokeAngles body_angles(const mbd::ChainModel& chain, const mbd::ChainData& data,
                        double stroke_plane_angle, int body);

/// \brief The "outer" body (0-based): the one holding the point at 5/6 of the chain's
/// length, the middle of the outer third of the span (the third body of the paper's
/// three-body wing). With many bodies the last one is a small piece of the rounded tip;
/// this one is a section an experimenter's wing-tip marker would follow.
int outer_body(const mbd::ChainModel& chain);

/// \brief Times [s] where a sampled signal crosses \p level, by linear interpolation
/// between samples; \p direction +1 rising, −1 falling, 0 both.
std::vector<double> crossing_times(const std::vector<double>& t, const std::vector<double>& x,
                                   double level, int direction);

/// \brief Mean of x over [t_begin, t_end] by the trapezoidal rule on the samples in it
/// (the samples are assumed to cover the window).
double window_mean(const std::vector<double>& t, const std::vector<double>& x, double t_begin,
                   double t_end);

/// \brief Mean time shift of the crossings of \p x relative to those of \p reference
/// within a window, as a fraction of the period [-]: for each crossing of the
/// reference (same level and direction) the crossing of x nearest it in time (the same
/// cycle's; none if it is more than half a period away), shift in [−½, ½]. Positive: x
/// crosses later (lags). nullopt if either has no crossing.
/// Both the rising and the falling crossings are used.
std::optional<double> crossing_lag(const std::vector<double>& t, const std::vector<double>& x,
                                   const std::vector<double>& reference, double level,
                                   double period, double t_begin, double t_end);

/// \brief Rotation phase of a wing section [-] in the paper's sense (δψ of eq. 8):
/// time of the α = 90° crossing minus the time of the stroke reversal it belongs to
/// (φ maximum before the falling crossing, φ minimum before the rising one), as a
/// fraction of the period, averaged over both half-strokes in the window as phases on a
/// circle (the direction of the mean of (cos 2πf, sin 2πf)), in (−½, ½]; negative =
/// rotation ahead of the reversal (advanced); ±½ are the same timing. nullopt if no
/// crossing is found.
/// \param alpha  α samples [rad]; \param sweep  φ samples [rad]
std::optional<double> rotation_phase(const std::vector<double>& t, const std::vector<double>& sweep,
                                     const std::vector<double>& alpha, double period,
                                     double t_begin, double t_end);

}  // namespace flapsim::fsi
