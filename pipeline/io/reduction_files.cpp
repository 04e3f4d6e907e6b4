#include "pipeline/io/reduction_files.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <utility>
#include <sstream>
#include <vector>

#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "pipeline/io/summary_json.hpp"
#include "pipeline/io/vtk_writers.hpp"

namespace flapsim::io {

namespace fs = std::filesystem;

void write_beam_csv(const fs::path& path, const reduction::BeamProperties& beam) {
  std::vector<std::vector<double>> rows;
  for (const auto& st : beam.stations)
    rows.push_back({st.s, st.y, st.mass_per_length, st.x_cg, st.x_ea, st.n_cg, st.n_ea, st.EI, st.GJ,
                    st.I_alpha, st.in_tip_zone ? 1.0 : 0.0});
  write_csv(path,
            {"s_m", "y_m", "m_per_length_kg_per_m", "x_cg_m", "x_ea_m", "n_cg_m", "n_ea_m", "EI_N_m2",
             "GJ_N_m2", "I_alpha_kg_m", "in_tip_zone"},
            rows);
}

void write_reduction_vtk(const fs::path& dir, const reduction::BeamProperties& beam,
                         const reduction::LumpedChain& lc) {
  const auto& ax = beam.axis;
  const Eigen::Matrix3d r = ax.rotation();
  const int ns = static_cast<int>(beam.stations.size());
  const int nb = lc.chain.num_bodies();
  ensure_directory(dir / "reduction");

  PolyDataMesh stations;
  stations.points.resize(3, ns);
  Eigen::VectorXd s(ns), ei(ns), gj(ns), mpl(ns), ia(ns), nea(ns), ncg(ns), tip(ns);
  std::vector<int> axis_line;
  for (int k = 0; k < ns; ++k) {
    const auto& st = beam.stations[static_cast<std::size_t>(k)];
    stations.points.col(k) = ax.point(st.s, 0.0);
    s[k] = st.s;
    ei[k] = st.EI;
    gj[k] = st.GJ;
    mpl[k] = st.mass_per_length;
    ia[k] = st.I_alpha;
    nea[k] = st.n_ea;
    ncg[k] = st.n_cg;
    tip[k] = st.in_tip_zone ? 1.0 : 0.0;
    axis_line.push_back(k);
  }
  if (ns >= 2) stations.lines.push_back(axis_line);
  stations.point_data.add_scalar("EI_N_m2", ei);
  stations.point_data.add_scalar("GJ_N_m2", gj);
  stations.point_data.add_scalar("m_per_length_kg_per_m", mpl);
  stations.point_data.add_scalar("I_alpha_kg_m", ia);
  stations.point_data.add_scalar("n_ea_m", nea);
  stations.point_data.add_scalar("n_cg_m", ncg);
  stations.point_data.add_scalar("s_m", s);
  stations.point_data.add_scalar("in_tip_zone", tip);

  PolyDataMesh bodies;
  bodies.points.resize(3, nb + 1);
  for (int k = 0; k <= nb; ++k) bodies.points.col(k) = ax.point(lc.body_length * k, 0.0);
  Eigen::VectorXd body(nb), mass(nb), length(nb);
  for (int k = 0; k < nb; ++k) {
    const auto& b = lc.chain.bodies[static_cast<std::size_t>(k)];
    bodies.lines.push_back({k, k + 1});
    body[k] = k + 1;
    mass[k] = b.mass;
    length[k] = b.length;
  }
  bodies.cell_data.add_scalar("body", body);
  bodies.cell_data.add_scalar("mass_kg", mass);
  bodies.cell_data.add_scalar("length_m", length);

  // Joints with springs only: with a rigid root, body 1 is welded to the base (no joint 0).
  const int first = lc.chain.first_jointed_body();
  PolyDataMesh joints;
  joints.points.resize(3, nb - first);
  Eigen::VectorXd joint(nb - first), k_theta(nb - first), k_alpha(nb - first);
  for (int k = first; k < nb; ++k) {
    const int i = k - first;
    const auto& j = lc.chain.joints[static_cast<std::size_t>(k)];
    joints.points.col(i) = ax.point(lc.body_length * k, 0.0);
    joints.vertices.push_back(i);
    joint[i] = k + 1;
    k_theta[i] = j.bend_stiffness;
    k_alpha[i] = j.twist_stiffness;
  }
  joints.point_data.add_scalar("joint", joint);
  joints.point_data.add_scalar("k_theta_N_m_per_rad", k_theta);
  joints.point_data.add_scalar("k_alpha_N_m_per_rad", k_alpha);

  PolyDataMesh coms;
  coms.points.resize(3, nb);
  for (int k = 0; k < nb; ++k) {
    const auto& b = lc.chain.bodies[static_cast<std::size_t>(k)];
    coms.points.col(k) = ax.point(lc.body_length * k, 0.0) + r * b.center_of_mass;
    coms.vertices.push_back(k);
  }
  coms.point_data.add_scalar("body", body);
  coms.point_data.add_scalar("mass_kg", mass);

  const std::pair<const char*, const PolyDataMesh*> blocks[] = {
      {"stations", &stations}, {"bodies", &bodies}, {"joints", &joints}, {"centres_of_mass", &coms}};
  for (const auto& [name, mesh] : blocks) write_vtp(dir / "reduction" / (std::string(name) + ".vtp"), *mesh);
  write_file_atomically(dir / "reduction.vtm", [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
           "  <vtkMultiBlockDataSet>\n";
    int index = 0;
    for (const auto& [name, mesh] : blocks)
      out << "    <DataSet index=\"" << index++ << "\" name=\"" << name << "\" file=\"reduction/" << name
          << ".vtp\"/>\n";
    out << "  </vtkMultiBlockDataSet>\n"
           "</VTKFile>\n";
  });
}

std::string format_percent(double x) {
  if (!std::isfinite(x)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.2f %%", 100.0 * x);
  return buf;
}

std::string fitted_axis_note(const reduction::BeamProperties& beam) {
  if (!beam.fitted_axis_rejected) return "";
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "Note: the fitted axis (psi = %.4f rad) left the planform over most of the span (the elastic "
                "axes of sections cut along y scatter outside the wing, as on a swept wing); the chain's axis is "
                "the line through the pivot and the sections' mid-chords instead.",
                beam.fitted_psi_rejected);
  return buf;
}

std::string unidentified_stiffness_note(const reduction::BeamProperties& beam) {
  char buf[600];
  std::snprintf(
      buf, sizeof buf,
      "Note: beam.csv's EI is not identified at %d and GJ at %d of its %zu stations (NaN there): the "
      "sections turned against the unit moment or torque, as the film of a wing beyond its rods does "
      "(its sections' fit follows the film, which twists about the spar, not the spar that carries the "
      "moment). The chain's springs come from the stations' compliance, not from these columns "
      "(docs/reduction.md, \"Stiffness: per cell\").",
      beam.unidentified_ei, beam.unidentified_gj, beam.stations.size());
  return buf;
}

std::string reduction_report(const std::string& wing_file, const reduction::BeamProperties& beam,
                             const reduction::LumpedChain& lc, const reduction::ChainFemComparison& c) {
  std::ostringstream s;
  s << "# Reduction of " << wing_file << "\n\n"
    << "Method: docs/reduction.md. Flexural axis at psi = " << beam.axis.psi << " rad from y_W"
    << (beam.axis.offset != 0.0 ? ", " + std::to_string(beam.axis.offset * 1e3) + " mm from the pivot"
                                : std::string(" through the pivot"))
    << "; flexible span " << beam.s_root << " … " << beam.s_tip << " m; " << beam.stations.size()
    << " beam stations; " << lc.chain.num_bodies() << " bodies of " << lc.body_length << " m, root "
    << (lc.chain.root == mbd::RootAttachment::sprung ? "sprung" : "rigid") << ".\n\n"
    << (beam.fitted_axis_rejected ? fitted_axis_note(beam) + "\n\n" : std::string())
    << (beam.unidentified_ei + beam.unidentified_gj > 0 ? unidentified_stiffness_note(beam) + "\n\n"
                                                        : std::string())
    << "FEM mass " << c.fem_mass << " kg, strip sum " << beam.strip_mass_sum << " kg, chain mass "
    << c.chain_mass << " kg. Mean elastic axis from the tip twists: n = " << beam.n_ea_tip
    << " m from the axis. Bending–torsion coupling (twist under the unit moment / twist under "
       "the unit torque): "
    << beam.bend_twist_coupling
    << (lc.springs == reduction::SpringModel::full ? " (carried by the chain's full joint stiffness).\n\n"
                                                   : " (not represented by the diagonal springs).\n\n")
    << "## Chain vs FEM\n\n| quantity | FEM | chain | error | MAC |\n|---|---|---|---|---|\n";
  auto mode_row = [&](const char* name, const reduction::ModeMatch& m) {
    if (!m.found) {
      s << "| " << name << " | not found | | | |\n";
      return;
    }
    s << "| " << name << " [Hz] (FEM mode " << m.fem_mode + 1 << ", chain mode " << m.chain_mode + 1
      << ") | " << m.fem_hz << " | " << m.chain_hz << " | " << format_percent(m.relative_error) << " | " << m.mac
      << " |\n";
  };
  mode_row("first bending", c.bending);
  mode_row("first torsion", c.torsion);
  auto static_row = [&](const char* name, const reduction::StaticMatch& m) {
    s << "| " << name << " | " << m.fem << " | " << m.chain << " | " << format_percent(m.relative_error) << " | |\n";
  };
  static_row("tip deflection per unit tip force on the axis [m/N]", c.tip_deflection);
  static_row("bending rotation of the tip body per unit moment spread over it [rad/(N m)]",
             c.tip_bending_rotation);
  static_row("tip twist per unit tip torque [rad/(N m)]", c.tip_twist);
  s << "\nTip deflection and twist at s = " << c.measure_s
    << " m (mid-point of the outermost body clear of the loaded tip zone); the FEM load cases of the beam "
       "extraction, "
       "the same wrenches on the chain. Both read in the chain's coordinates: the FEM's station motion "
       "mapped to joint "
       "angles (the map that defines K), then the chain's kinematics at that point (docs/reduction.md, "
       "\"Checking the "
       "chain against the FEM\"). Bending rotation: the rotation conjugate to the moment on both sides "
       "(twice the "
       "strain energy over the moment, positive by construction), the moment spread by mass over the tip "
       "body's strip "
       "from s = "
    << c.bending_body_s
    << " m on the FEM and put on the tip body of the chain (docs/reduction.md, \"A tip moment on a film "
       "tip\"). "
       "The FEM's section fit (every node alike, camber terms) gives w = "
    << c.tip_deflection.fem_section_fit << " m/N and twist = " << c.tip_twist.fem_section_fit
    << " rad/(N m) there, theta = " << c.tip_bending_rotation.fem_section_fit
    << " rad/(N m) at the tip body's mid-span: far from the rows' FEM values where the sections are not "
       "rigid (film beyond "
       "a rod).\n\n"
    << "## FEM modes\n\nKind from the stations' motion (docs/reduction.md, \"Mode kinds from the "
       "stations\"); "
       "beam share: the share of the motion the stations' rigid sections carry; shape: the FEM's own "
       "shape classification.\n\n| mode | f [Hz] | kind | beam share | shape |\n|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < c.fem_hz.size(); ++i)
    s << "| " << i + 1 << " | " << c.fem_hz[i] << " | " << c.fem_kinds[i] << " | " << c.fem_beam_share[i] << " | "
      << c.fem_shape_kinds[i] << " |\n";
  s << "\n## FEM beam modes and the chain mode that correlates best\n\n"
       "| FEM mode | kind | FEM f [Hz] | chain mode | chain f [Hz] | error | MAC |\n|---|---|---|---|---|---|---|\n";
  for (const auto& p : c.beam_mode_pairs)
    s << "| " << p.fem_mode + 1 << " | " << c.fem_kinds[static_cast<std::size_t>(p.fem_mode)] << " | " << p.fem_hz
      << " | " << p.chain_mode + 1 << " | " << p.chain_hz << " | " << format_percent(p.relative_error) << " | "
      << p.mac << " |\n";
  s << "\n## Chain modes\n\n| mode | f [Hz] | kind |\n|---|---|---|\n";
  for (std::size_t i = 0; i < c.chain_hz.size() && i < 12; ++i)
    s << "| " << i + 1 << " | " << c.chain_hz[i] << " | " << c.chain_kinds[i] << " |\n";
  const Eigen::VectorXd kdiag = lc.chain.stiffness_diagonal();
  s << "\n## Joint stiffness\n\n"
    << (lc.springs == reduction::SpringModel::full
            ? "Full joint stiffness K = (T C T^T)^-1 from the stations' compliance C by reciprocity, T "
              "taking the stations' deflections and twists to the joint angles (chord slopes of the "
              "deflection between stations, twist differences; docs/reduction.md): bend-twist and "
              "joint-to-joint coupling kept; the chain's joint angles equal the FEM's T u under every joint "
              "load."
            : "Diagonal springs k = 1/(K^-1)_jj from the stations' compliance: coupling dropped "
              "(docs/reduction.md, \"Diagonal springs\").")
    << " Eigenvalues of K: " << lc.joint_stiffness.min_eigenvalue << " ... " << lc.joint_stiffness.max_eigenvalue
    << " N m/rad.\n\n"
    << "## Bodies (body frame: origin at the inboard joint, y along the axis, x toward the LE)\n\n"
    << "| body | length [m] | mass [kg] | com x, y, z [m] | I_xx, I_yy, I_zz about com [kg m²] | K_theta,theta "
       "[N m/rad] | K_alpha,alpha [N m/rad] | flexural axis n at mid-span [m] |\n|---|---|---|---|---|---|---|---|\n";
  for (int k = 0; k < lc.chain.num_bodies(); ++k) {
    const auto& b = lc.chain.bodies[static_cast<std::size_t>(k)];
    s << "| " << k + 1 << " | " << b.length << " | " << b.mass << " | " << b.center_of_mass.x() << ", "
      << b.center_of_mass.y() << ", " << b.center_of_mass.z() << " | " << b.inertia(0, 0) << ", "
      << b.inertia(1, 1) << ", " << b.inertia(2, 2) << " | ";
    const int d = lc.chain.dof_of_body(k);
    if (d < 0) {
      s << "welded | welded | |\n";
      continue;
    }
    s << kdiag[d] << " | " << kdiag[d + 1] << " | " << lc.flexural_axis_n[static_cast<std::size_t>(d / 2)] << " |\n";
  }
  return s.str();
}

void write_reduction_summary(const fs::path& path, const reduction::BeamProperties& beam,
                             const reduction::LumpedChain& lc, const reduction::ChainFemComparison& c) {
  SummaryJson j;
  j.set("num_bodies", c.num_bodies);
  j.set("num_stations", static_cast<int>(beam.stations.size()));
  j.set("axis_psi_rad", beam.axis.psi);
  j.set("axis_offset_m", beam.axis.offset);
  j.set("fitted_axis_rejected", beam.fitted_axis_rejected);
  j.set("root", lc.chain.root == mbd::RootAttachment::sprung ? "sprung" : "rigid");
  j.set("welded_bodies", lc.chain.root == mbd::RootAttachment::sprung ? 0 : lc.chain.welded_bodies);
  j.set("springs", lc.springs == reduction::SpringModel::full ? "full" : "diagonal");
  j.set("stiffness_min_eigenvalue_N_m_per_rad", lc.joint_stiffness.min_eigenvalue);
  j.set("stiffness_max_eigenvalue_N_m_per_rad", lc.joint_stiffness.max_eigenvalue);
  j.set("fem_mass_kg", c.fem_mass);
  j.set("chain_mass_kg", c.chain_mass);
  j.set("n_ea_tip_m", beam.n_ea_tip);
  j.set("bend_twist_coupling", beam.bend_twist_coupling);
  j.set("bending_found", c.bending.found);
  j.set("bending_fem_hz", c.bending.fem_hz);
  j.set("bending_chain_hz", c.bending.chain_hz);
  j.set("bending_relative_error", c.bending.relative_error);
  j.set("bending_mac", c.bending.mac);
  j.set("torsion_found", c.torsion.found);
  j.set("torsion_fem_hz", c.torsion.fem_hz);
  j.set("torsion_chain_hz", c.torsion.chain_hz);
  j.set("torsion_relative_error", c.torsion.relative_error);
  j.set("torsion_mac", c.torsion.mac);
  j.set("static_measure_s_m", c.measure_s);
  j.set("tip_deflection_fem_m_per_N", c.tip_deflection.fem);
  j.set("tip_deflection_chain_m_per_N", c.tip_deflection.chain);
  j.set("tip_deflection_relative_error", c.tip_deflection.relative_error);
  j.set("tip_rotation_body_s_m", c.bending_body_s);
  j.set("tip_rotation_fem_rad_per_N_m", c.tip_bending_rotation.fem);
  j.set("tip_rotation_chain_rad_per_N_m", c.tip_bending_rotation.chain);
  j.set("tip_rotation_relative_error", c.tip_bending_rotation.relative_error);
  j.set("tip_twist_fem_rad_per_N_m", c.tip_twist.fem);
  j.set("tip_twist_chain_rad_per_N_m", c.tip_twist.chain);
  j.set("tip_twist_relative_error", c.tip_twist.relative_error);
  j.set("tip_deflection_fem_section_fit_m_per_N", c.tip_deflection.fem_section_fit);
  j.set("tip_rotation_fem_section_fit_rad_per_N_m", c.tip_bending_rotation.fem_section_fit);
  j.set("tip_twist_fem_section_fit_rad_per_N_m", c.tip_twist.fem_section_fit);
  j.write(path);
}

}  // namespace flapsim::io
