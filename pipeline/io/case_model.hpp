#pragma once
/// \file case_model.hpp
/// \brief What a simulation case is, after its file has been read and checked
/// (docs/case_file.md): the wing or chain it flaps, the base kinematics, the air,
/// the structure model, the numerics, outputs, extra point loads and markers.
/// All values SI; angles in radians.

#include <Eigen/Core>

#include <string>
#include <vector>

#include "mbd/periodic_signal.hpp"
#include "mbd/wing_kinematics.hpp"

namespace flapsim::io {

/// A prescribed force and moment on one body of the chain, periodic in the stroke phase.
struct PointLoad {
  int body = 1;                                  ///< 1-based body index in the chain
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< application point [m], body frame
  bool ground_frame = true;  ///< components in the ground frame (true) or the body frame
  mbd::PeriodicSignal force[3];   ///< [N] as functions of the phase s = f·t
  mbd::PeriodicSignal moment[3];  ///< [N m] as functions of the phase s = f·t
};

/// A point carried by a body whose trajectory goes into the output.
struct Marker {
  std::string name;
  int body = 1;                                     ///< 1-based body index
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< [m], body frame
};

struct Case {
  std::string file;        ///< path of the case file
  std::string name;        ///< short name (from the file, else the file stem)
  std::string wing_file;   ///< resolved path of the wing file (may be empty)
  std::string chain_file;  ///< resolved path of the chain file (may be empty)

  mbd::WingKinematics kinematics;  ///< base kinematics (frequency, φ, θ, α, δψ, β)

  struct Air {
    bool enabled = true;       ///< false: vacuum (`air = "none"`), no aerodynamic loads
    double density = 1.225;    ///< ρ [kg/m³]
    Eigen::Vector3d freestream = Eigen::Vector3d::Zero();  ///< U∞ [m/s], ground frame
  } air;

  struct Structure {
    enum class Kind { Rigid, Flexible };
    Kind kind = Kind::Rigid;
    int bodies = 1;  ///< number of chain bodies (1 for a rigid wing)
  } structure;

  struct Numerics {
    int steps_per_cycle = 100;
    int cycles = 3;
    int chordwise_panels = 6;
    int spanwise_panels = 10;
    std::string spacing = "uniform";        ///< panel spacing: "uniform" | "cosine"
    std::string core_model = "lamb_oseen";  ///< vortex core: "cutoff" | "lamb_oseen"
    double core_radius = 0.05;              ///< core radius as a fraction of the mean chord
    int wake_order = 1;                     ///< 1 | 2 (wake convection order)
    int wake_max_rows = 0;                  ///< 0 = keep all wake rows
    bool free_wake = true;                  ///< false: wake convected by U∞ and the body only
    int max_coupling_iterations = 50;       ///< strong-coupling sub-iterations per step
    double coupling_tolerance = 1e-6;       ///< relative change that ends the sub-iterations
  } numerics;

  struct Output {
    int vtk_every = 1;  ///< write VTK every n steps, 0 = never
  } output;

  std::vector<PointLoad> loads;
  std::vector<Marker> markers;
};

/// Reads and checks a case file.
/// \param path case file (TOML); wing and chain paths inside resolve against its folder
/// \throws flapsim::InputError naming file, line and key for any bad input
Case load_case_file(const std::string& path);

}  // namespace flapsim::io
