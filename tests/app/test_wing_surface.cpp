// Twist, camber and dihedral from the wing file's [surface] table on the vortex lattice
// (issue 29): the lattice of `flapsim run` (the planform grid of the wing's outline, moved by
// app::shape_lattice_surface) solved steady, against a steady horseshoe vortex lattice
// written here (Katz & Plotkin 2001, §12.3: a horseshoe per panel, its bound vortex on the
// panel's quarter chord and its legs along x to infinity, flow tangency at the
// three-quarter-chord point, Kutta–Joukowski lift ρ V∞ × Γ l). Its geometry is built here
// from the analytic formulas, not by the code under test: twist and camber enter the
// planar lattice of linear theory through the boundary condition (w = −U sin(θ − atan z_c')),
// dihedral through the panels themselves. The half wing of the file is mirrored about its
// root (y = 0) into the whole wing. docs/uvlm.md, "Twist, camber and dihedral".
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/lattice_surface.hpp"
#include "uvlm/planform_grid.hpp"
#include "uvlm/vortex_lattice.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/surface_shape.hpp"
#include "wings/loader/wing_file.hpp"

namespace {

using namespace flapsim;
constexpr double kDeg = M_PI / 180.0;
constexpr double kChord = 0.010, kHalfSpan = 0.030;  // [m]: the whole wing AR 6

/// A rectangular half wing (leading edge x = 0, trailing edge x = −c, root y = 0) with the
/// [surface] lines given, written to \p dir and read back.
wings::Wing surface_wing(const test::ScratchDir& dir, const std::string& surface) {
  const auto path = dir / "wing.toml";
  std::ofstream(path) << "name = \"surface\"\nlength_unit = \"mm\"\n"
                         "[planform]\noutline = [[0, 0], [0, 30], [-10, 30], [-10, 0]]\nclamp_y = 0\n"
                         "[materials.pet]\nyoungs_modulus = 4e9\npoisson_ratio = 0.38\ndensity = 1390\n"
                         "[membrane]\nthickness = 0.2\nmaterial = \"pet\"\n"
                         "[surface]\n"
                      << surface;
  return wings::load_wing_file(path.string());
}

/// Velocity of a straight vortex segment a → b of unit circulation at p (Katz & Plotkin
/// eq. 2.68), zero on the segment's line.
Eigen::Vector3d segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d r1 = p - a, r2 = p - b, r0 = b - a, c = r1.cross(r2);
  const double c2 = c.squaredNorm();
  if (c2 < 1e-20 * r0.squaredNorm() * r0.squaredNorm()) return Eigen::Vector3d::Zero();
  return c / (4.0 * M_PI * c2) * r0.dot(r1 / r1.norm() - r2 / r2.norm());
}

/// Steady horseshoe lattice on the whole wing's panel corners \p nodes (node (i, j) at column
/// i + (nc + 1) j, leading edge i = 0; legs along V∞, as the lattice's steady wake), free
/// stream \p v (ρ = 1), the extra incidence
/// incidence(i, j) [rad] of linear theory in the boundary condition; CL along \p lift on
/// the area \p area.
double horseshoe_cl(const Eigen::Matrix3Xd& nodes, int nc, int ns, const Eigen::Vector3d& v,
                    const std::function<double(int, int)>& incidence, const Eigen::Vector3d& lift, double area) {
  const int n = nc * ns;
  auto node = [&](int i, int j) -> Eigen::Vector3d { return nodes.col(i + (nc + 1) * j); };
  auto at = [&](int i, int j, double f) -> Eigen::Vector3d { return node(i, j) + f * (node(i + 1, j) - node(i, j)); };
  const Eigen::Vector3d far = 1e4 * kHalfSpan * v.normalized();  // legs downstream along V∞
  Eigen::MatrixXd a(n, n);
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < nc; ++i)
    for (int j = 0; j < ns; ++j) {
      const int row = i + nc * j;
      const Eigen::Vector3d p = 0.5 * (at(i, j, 0.75) + at(i, j + 1, 0.75));
      const Eigen::Vector3d nrm = (node(i, j + 1) - node(i + 1, j)).cross(node(i + 1, j + 1) - node(i, j)).normalized();
      rhs(row) = -v.dot(nrm) - v.norm() * std::sin(incidence(i, j));
      for (int k = 0; k < nc; ++k)
        for (int l = 0; l < ns; ++l) {
          const Eigen::Vector3d b0 = at(k, l, 0.25), b1 = at(k, l + 1, 0.25);
          a(row, k + nc * l) = (segment(p, b0 + far, b0) + segment(p, b0, b1) + segment(p, b1, b1 + far)).dot(nrm);
        }
    }
  const Eigen::VectorXd g = a.partialPivLu().solve(rhs);
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (int k = 0; k < nc; ++k)
    for (int l = 0; l < ns; ++l) force += g(k + nc * l) * v.cross(at(k, l + 1, 0.25) - at(k, l, 0.25));
  return force.dot(lift) / (0.5 * v.squaredNorm() * area);
}

/// The flat whole wing's panel corners: nc × 2ns, the file's half wing mirrored.
Eigen::Matrix3Xd flat_whole_wing(int nc, int ns) {
  Eigen::Matrix3Xd x(3, (nc + 1) * (2 * ns + 1));
  for (int j = 0; j <= 2 * ns; ++j)
    for (int i = 0; i <= nc; ++i)
      x.col(i + (nc + 1) * j) = Eigen::Vector3d(-kChord * i / nc, kHalfSpan * (j - ns) / ns, 0.0);
  return x;
}

struct LatticeCl {
  double kj = 0.0, bernoulli = 0.0;
};

/// The lattice of a run of \p wing (nc × ns on the half wing, shaped), mirrored about y = 0,
/// steady in the free stream \p v (ρ = 1); CL along \p lift on the area \p area, both routes.
LatticeCl lattice_cl(const wings::Wing& wing, int nc, int ns, const Eigen::Vector3d& v, const Eigen::Vector3d& lift,
                     double area) {
  uvlm::PlanformGridOptions o;
  o.chordwise = nc;
  o.spanwise = ns;
  uvlm::PlanformGrid half = uvlm::make_planform_grid(wing.outline, o);
  EXPECT_NEAR(half.y_root, 0.0, 1e-12);
  EXPECT_NEAR(half.y_tip, kHalfSpan, 1e-12);
  app::shape_lattice_surface(wing, half);
  uvlm::VortexLatticeModel m;
  m.chordwise = nc;
  m.spanwise = 2 * ns;
  m.wake_capacity = 2;
  m.wake_model = uvlm::WakeModel::Prescribed;
  m.core = {uvlm::CoreModel::LambOseen, 1e-6 * kChord};
  m.leading_edge = uvlm::LeadingEdge::None;
  uvlm::VortexLatticeData d(m);
  Eigen::Matrix3Xd nodes(3, m.nodes());
  for (int j = 0; j <= 2 * ns; ++j)
    for (int i = 0; i <= nc; ++i) {
      Eigen::Vector3d p = half.nodes.col(i + (nc + 1) * std::abs(j - ns));
      if (j < ns) p.y() = -p.y();
      nodes.col(m.node(i, j)) = p;
    }
  uvlm::solve_steady(m, d, nodes, v, 1.0, 1e4 * kHalfSpan);
  const double q = 0.5 * v.squaredNorm() * area;
  LatticeCl c;
  uvlm::compute_kutta_joukowski_loads(m, d);
  c.kj = d.loads.total_force.dot(lift) / q;
  uvlm::compute_bernoulli_loads(m, d);
  c.bernoulli = d.loads.total_force.dot(lift) / q;
  return c;
}

constexpr int kNc = 4, kNs = 12;  // on the half wing: 4 × 24 panels on the whole

TEST(WingSurface, ATwistedWingFromTheFileMatchesAnIndependentHorseshoeLattice) {
  // AR 6 rectangle, twist 4° at the root (mid-span) to 0° at the tips, linear, about the
  // quarter chord (twist_axis default 0.25), in a stream along the root chord's plane.
  // Bound 0.5 % (issue 29); the rings on the twisted surface and the exact boundary
  // condition differ from linear theory by O(θ²). Measured: KJ −0.140 %, Bernoulli −0.135 %.
  const test::ScratchDir dir("wing_surface_twist");
  const wings::Wing w = surface_wing(dir, "twist_root_deg = 4.0\ntwist_tip_deg = 0.0\n");
  const Eigen::Vector3d v(-1.0, 0.0, 0.0), up = Eigen::Vector3d::UnitZ();
  const double area = 2.0 * kHalfSpan * kChord;
  const double ref = horseshoe_cl(flat_whole_wing(kNc, kNs), kNc, 2 * kNs, v, [](int, int j) {
    const double y = kHalfSpan * (j + 0.5 - kNs) / kNs;  // panel centre
    return 4.0 * kDeg * (1.0 - std::abs(y) / kHalfSpan);
  }, up, area);
  const LatticeCl c = lattice_cl(w, kNc, kNs, v, up, area);
  std::printf("[ value ] twisted AR 6: CL KJ %.5f, Bernoulli %.5f, horseshoe %.5f (%+.3f %%, %+.3f %%)\n", c.kj,
              c.bernoulli, ref, 100 * (c.kj / ref - 1), 100 * (c.bernoulli / ref - 1));
  EXPECT_GT(ref, 0.1);
  EXPECT_NEAR(c.kj / ref, 1.0, 5e-3);
  EXPECT_NEAR(c.bernoulli / ref, 1.0, 5e-3);
}

TEST(WingSurface, ACamberedWingFromTheFileMatchesAnIndependentHorseshoeLattice) {
  // camber = "NACA 2412" at zero incidence: in linear theory's boundary condition the
  // incidence −atan s of each panel, s the slope of its chord on the mean line, (z_c(ξ_{i+1})
  // − z_c(ξ_i))/Δξ (a lattice's panel is flat between its nodes; the slope at the
  // collocation point instead differs by O(Δξ) and is another lattice). Bound 0.5 %.
  const test::ScratchDir dir("wing_surface_camber");
  const wings::Wing w = surface_wing(dir, "camber = \"NACA 2412\"\n");
  const Eigen::Vector3d v(-1.0, 0.0, 0.0), up = Eigen::Vector3d::UnitZ();
  const double area = 2.0 * kHalfSpan * kChord;
  const double ref = horseshoe_cl(flat_whole_wing(kNc, kNs), kNc, 2 * kNs, v, [](int i, int) {
    const double p = 0.4, m = 0.02;  // Abbott & von Doenhoff §6.4
    auto zc = [&](double xi) { return xi < p ? m / (p * p) * (2 * p * xi - xi * xi)
                                             : m / ((1 - p) * (1 - p)) * ((1 - 2 * p) + 2 * p * xi - xi * xi); };
    return -std::atan((zc((i + 1.0) / kNc) - zc(static_cast<double>(i) / kNc)) * kNc);
  }, up, area);
  const LatticeCl c = lattice_cl(w, kNc, kNs, v, up, area);
  std::printf("[ value ] NACA 2412 AR 6: CL KJ %.5f, Bernoulli %.5f, horseshoe %.5f (%+.3f %%, %+.3f %%)\n", c.kj,
              c.bernoulli, ref, 100 * (c.kj / ref - 1), 100 * (c.bernoulli / ref - 1));
  EXPECT_GT(ref, 0.1);
  EXPECT_NEAR(c.kj / ref, 1.0, 5e-3);
  EXPECT_NEAR(c.bernoulli / ref, 1.0, 5e-3);
}

TEST(WingSurface, ADihedralWingFromTheFileMatchesAnIndependentHorseshoeLattice) {
  // dihedral_deg = 10 with a uniform 4° twist (the incidence; the stream along the root
  // chord): the reference's panels are the flat wing's corners turned by Γ about the root
  // chord, (x, y cos Γ, |y| sin Γ), the twist in the boundary condition as above (a section
  // twisted, then turned, sees V∞ · n = U sin θ). Bound 0.5 % on both routes; measured
  // Bernoulli −0.014 %, Kutta–Joukowski +0.24 % (the side-edge force of the tip chords, which
  // the dihedral turns partly into lift: docs/uvlm.md "Twist, camber and dihedral"). KJ gave
  // +2.5 % while each bound segment's own velocity at its rounded midpoint, inside its
  // 1e-11 m core, was left in the sum (uvlm/lattice_internal.hpp, induced_at_bound_midpoints).
  const test::ScratchDir dir("wing_surface_dihedral");
  const wings::Wing w = surface_wing(dir, "twist_root_deg = 4.0\ntwist_tip_deg = 4.0\ndihedral_deg = 10.0\n");
  const double g = 10.0 * kDeg;
  const Eigen::Vector3d v(-1.0, 0.0, 0.0), up = Eigen::Vector3d::UnitZ();
  const double area = 2.0 * kHalfSpan * kChord;
  Eigen::Matrix3Xd x = flat_whole_wing(kNc, kNs);
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    const double y = x(1, k);
    x(1, k) = y * std::cos(g);
    x(2, k) = std::abs(y) * std::sin(g);
  }
  const double ref = horseshoe_cl(x, kNc, 2 * kNs, v, [](int, int) { return 4.0 * kDeg; }, up, area);
  const LatticeCl c = lattice_cl(w, kNc, kNs, v, up, area);
  std::printf("[ value ] dihedral 10 deg, twist 4 deg, AR 6: CL KJ %.5f, Bernoulli %.5f, horseshoe %.5f (%+.3f %%, %+.3f %%)\n",
              c.kj, c.bernoulli, ref, 100 * (c.kj / ref - 1), 100 * (c.bernoulli / ref - 1));
  EXPECT_GT(ref, 0.1);
  EXPECT_NEAR(c.kj / ref, 1.0, 5e-3);
  EXPECT_NEAR(c.bernoulli / ref, 1.0, 5e-3);
  // Less than the flat wing's at the same incidence (the dihedral turns the lift sideways):
  // the V-wing's reference below the twisted planar one's, and the lattice too.
  const double planar = horseshoe_cl(flat_whole_wing(kNc, kNs), kNc, 2 * kNs, v, [](int, int) { return 4.0 * kDeg; },
                                     up, area);
  EXPECT_LT(ref, planar);
  EXPECT_LT(c.bernoulli, planar);
}

TEST(WingSurface, TheShapedNodesLieOnTheMeanLineTwistedAndTurned) {
  // The formulas of wings/loader/surface_shape.hpp at points whose answer is known in closed form:
  // the NACA mean line's crest z_c(p) = m (Abbott & von Doenhoff §6.4) and its ends at 0;
  // a twist of θ about the quarter chord puts the leading edge at z = (c/4) sin θ; a
  // dihedral Γ puts a flat point (x, y) at (x, y cos Γ, y sin Γ).
  wings::SurfaceShape s;
  s.camber = 0.04;
  s.camber_position = 0.3;
  EXPECT_NEAR(wings::naca_mean_line(0.04, 0.3, 0.3), 0.04, 1e-15);
  EXPECT_EQ(wings::naca_mean_line(0.04, 0.3, 0.0), 0.0);
  EXPECT_NEAR(wings::naca_mean_line(0.04, 0.3, 1.0), 0.0, 1e-16);
  EXPECT_NEAR(wings::naca_mean_line_slope(0.04, 0.3, 0.3), 0.0, 1e-16);
  EXPECT_NEAR(wings::shaped_point(s, -0.3, 0.5, 0.0, -1.0, 0.0, 1.0).z(), 0.04, 1e-15);
  wings::SurfaceShape t;
  t.twist_root = 6.0 * kDeg;
  t.twist_tip = 2.0 * kDeg;
  const Eigen::Vector3d le = wings::shaped_point(t, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0);
  EXPECT_NEAR(le.z(), 0.25 * std::sin(6.0 * kDeg), 1e-15);
  EXPECT_NEAR(wings::twist_at(t, 0.5, 0.0, 1.0), 4.0 * kDeg, 1e-15);
  wings::SurfaceShape d;
  d.dihedral = 20.0 * kDeg;
  const Eigen::Vector3d p = wings::shaped_point(d, -0.4, 2.0, 0.0, -1.0, 0.0, 2.0);
  EXPECT_NEAR(p.x(), -0.4, 1e-15);
  EXPECT_NEAR(p.y(), 2.0 * std::cos(20.0 * kDeg), 1e-15);
  EXPECT_NEAR(p.z(), 2.0 * std::sin(20.0 * kDeg), 1e-15);
}

TEST(WingSurface, BadSurfaceValuesNameFileLineAndKey) {
  const test::ScratchDir dir("wing_surface_bad");
  const struct {
    const char* text;
    const char* key;
  } bad[] = {
      {"twist_root_deg = 40.0\n", "surface.twist_root_deg"},
      {"twist_axis = 1.5\n", "surface.twist_axis"},
      {"camber = \"NACA 24\"\n", "surface.camber"},
      {"camber = \"NACA 2012\"\n", "surface.camber"},
      {"camber = \"NACA 2412\"\ncamber_max = 0.02\n", "surface.camber"},
      {"camber_position = 0.4\n", "surface.camber_position"},
      {"camber_max = 0.02\ncamber_position = 1.0\n", "surface.camber_position"},
      {"dihedral_deg = \"ten\"\n", "surface.dihedral_deg"},
      {"washout = 3\n", "surface.washout"},
  };
  for (const auto& b : bad) {
    try {
      surface_wing(dir, b.text);
      ADD_FAILURE() << "accepted: " << b.text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), b.key) << b.text;
      EXPECT_GE(e.line(), 13) << b.text;  // the [surface] table starts on line 13
      EXPECT_NE(e.file().find("wing.toml"), std::string::npos) << b.text;
    }
  }
}

TEST(WingSurface, AShapedWingOnTheFlatFemIsRefusedNamingTheSurfaceTable) {
  // Lattice-only: the FEM's shell is the flat planform, so structure.kind = "fem" refuses a
  // [surface] that is not flat (exit 2 at the wing file's [surface] line, line 13 here); the
  // same wing as a rigid wing is accepted.
  const test::ScratchDir dir("wing_surface_fem");
  surface_wing(dir, "twist_root_deg = 3.0\n");
  const std::string head = "name = \"fem_twist\"\nwing = \"wing.toml\"\n[kinematics]\nfrequency_hz = 20.0\n"
                           "sweep = { cos_deg = [40.0] }\ndeviation = 0.0\n"
                           "rotation = { mean_deg = 90.0, sin_deg = [-40.0] }\n[air]\ndensity = 1.225\n"
                           "freestream = [0.0, 0.0, 0.0]\n[numerics]\nsteps_per_cycle = 20\ncycles = 1\n"
                           "[structure]\nkind = ";
  std::ofstream(dir / "fem.toml") << head << "\"fem\"\n";
  std::ofstream(dir / "rigid.toml") << head << "\"rigid\"\n";
  const auto fem = test::run_flapsim_capturing_stderr(dir.path(), "check '" + (dir / "fem.toml").string() + "'");
  EXPECT_EQ(fem.status, 2) << fem.err;
  EXPECT_NE(fem.err.find("wing.toml:13: key 'surface'"), std::string::npos) << fem.err;
  EXPECT_EQ(test::run_flapsim("check '" + (dir / "rigid.toml").string() + "'"), 0);
}

}  // namespace
