#pragma once
/// \file panel_load_response.hpp
/// \brief The lattice's linearised added-mass response as a structure sees it: the change
/// of the panel forces for a change of the lattice nodes' velocities (uvlm/added_mass.hpp),
/// at the lattice's last solve. The coupled step hands it to the structure at the steps it
/// chooses (StructureData::linearise_panel_loads, coupled_step.cpp added_mass_due); the
/// structure turns it into its own matrix (docs/fsi.md, "Added mass in the coupling"). The
/// leading-edge force's part comes apart, to be evaluated anew at every step
/// (StructureData::refresh_panel_load_response).

#include <Eigen/Core>

#include "uvlm/added_mass.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::fsi {

class PanelLoadResponse {
 public:
  /// Views of the lattice and of scratch made for it (nothing allocated).
  PanelLoadResponse(const uvlm::VortexLatticeModel& model, const uvlm::VortexLatticeData& data,
                    uvlm::AddedMassScratch& scratch)
      : model_(model), data_(data), scratch_(scratch) {}
  /// δF [N] at points() (3 × panels) for the node velocity change \p dv [m/s] (3 × nodes),
  /// the leading-edge force's part left out: it is held in \p edge (when the lattice's
  /// leading edge has a response) and evaluated by edge_force_change at later solves.
  void force_change(const Eigen::Matrix3Xd& dv, Eigen::Matrix3Xd& df, uvlm::LeadingEdgeColumn& edge) {
    uvlm::added_mass_force_change(model_, data_, dv, scratch_, df, uvlm::AddedMassTerms::Pressure);
    if (edge_responds()) uvlm::hold_leading_edge_column(model_, data_, scratch_.dgamma, dv, scratch_.leading_edge, edge);
  }
  /// Whether the leading-edge force has a response (uvlm/leading_edge_response.hpp; not in
  /// the steady lattice, whose response is none: added_mass.hpp).
  bool edge_responds() const { return !model_.steady() && uvlm::leading_edge_responds(model_); }
  /// The leading-edge forces' change [N] at points() (3 × panels) for a held column, at the
  /// lattice's last solve.
  void edge_force_change(const uvlm::LeadingEdgeColumn& edge, Eigen::Matrix3Xd& df) const {
    df.setZero(3, model_.panels());
    uvlm::add_leading_edge_force_change(model_, data_, edge, df);
  }
  /// The panels' points of action of the last solve [m] (ground frame).
  const Eigen::Matrix3Xd& points() const { return data_.loads.point; }

 private:
  const uvlm::VortexLatticeModel& model_;
  const uvlm::VortexLatticeData& data_;
  uvlm::AddedMassScratch& scratch_;
};

}  // namespace flapsim::fsi
