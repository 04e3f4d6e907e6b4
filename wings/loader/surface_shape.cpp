#include "wings/loader/surface_shape.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "wings/loader/toml_reader.hpp"

namespace flapsim::wings {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}  // namespace

double naca_mean_line(double m, double p, double xi) {
  if (m == 0.0) return 0.0;
  if (xi < p) return m / (p * p) * (2.0 * p * xi - xi * xi);
  return m / ((1.0 - p) * (1.0 - p)) * ((1.0 - 2.0 * p) + 2.0 * p * xi - xi * xi);
}

double naca_mean_line_slope(double m, double p, double xi) {
  if (m == 0.0) return 0.0;
  if (xi < p) return 2.0 * m / (p * p) * (p - xi);
  return 2.0 * m / ((1.0 - p) * (1.0 - p)) * (p - xi);
}

double twist_at(const SurfaceShape& s, double y, double y_root, double y_tip) {
  if (!(y_tip > y_root)) return s.twist_root;
  const double t = std::clamp((y - y_root) / (y_tip - y_root), 0.0, 1.0);
  return s.twist_root + t * (s.twist_tip - s.twist_root);
}

Eigen::Vector3d shaped_point(const SurfaceShape& s, double x, double y, double x_le, double x_te,
                             double y_root, double y_tip) {
  const double c = x_le - x_te;
  if (!(c > 0.0)) return {x, y, 0.0};
  const double xi = (x_le - x) / c;
  const double z = c * naca_mean_line(s.camber, s.camber_position, xi);
  const double th = twist_at(s, y, y_root, y_tip), xa = x_le - s.twist_axis * c;
  const double xt = xa + (x - xa) * std::cos(th) - z * std::sin(th);
  const double zt = (x - xa) * std::sin(th) + z * std::cos(th);
  const double g = s.dihedral;
  return {xt, y * std::cos(g) - zt * std::sin(g), y * std::sin(g) + zt * std::cos(g)};
}

SurfaceShape read_surface_shape(const TomlTable& t) {
  t.expect_only({"twist_root_deg", "twist_tip_deg", "twist_axis", "camber", "camber_max", "camber_position",
                 "dihedral_deg"});
  SurfaceShape s;
  s.line = t.line();
  // ±30°: a twist beyond it is no washout a lattice of attached flow can carry (and a
  // value in radians written as degrees would read as a fraction of a degree: harmless).
  s.twist_root = t.get_double("twist_root_deg", 0.0, Bounds::closed(-30.0, 30.0)) * kDeg;
  s.twist_tip = t.get_double("twist_tip_deg", 0.0, Bounds::closed(-30.0, 30.0)) * kDeg;
  s.twist_axis = t.get_double("twist_axis", 0.25, Bounds::closed(0.0, 1.0));
  s.dihedral = t.get_double("dihedral_deg", 0.0, Bounds::closed(-45.0, 45.0)) * kDeg;
  if (t.has("camber")) {
    if (t.has("camber_max") || t.has("camber_position"))
      t.fail("camber", "give either camber = \"NACA mpxx\" or camber_max and camber_position, not both");
    // "NACA 2412", "naca2412" or "2412": m = 2 % of the chord at p = 40 %; the thickness
    // digits are read and ignored (the lattice is the mean surface).
    std::string digits;
    const std::string text = t.get_string("camber");
    std::string rest = text;
    while (!rest.empty() && std::isspace(static_cast<unsigned char>(rest.front()))) rest.erase(rest.begin());
    if (rest.size() >= 4 && (rest.compare(0, 4, "NACA") == 0 || rest.compare(0, 4, "naca") == 0)) rest.erase(0, 4);
    for (char ch : rest)
      if (!std::isspace(static_cast<unsigned char>(ch))) digits.push_back(ch);
    bool ok = digits.size() == 4;
    for (char ch : digits) ok = ok && std::isdigit(static_cast<unsigned char>(ch));
    if (!ok)
      t.fail("camber", "expected a NACA 4-digit section such as \"NACA 2412\" (camber in % of the chord, its "
                       "position in tenths, thickness), got \"" + text + "\"");
    s.camber = (digits[0] - '0') / 100.0;
    s.camber_position = (digits[1] - '0') / 10.0;
    if (s.camber > 0.0 && s.camber_position == 0.0)
      t.fail("camber", "\"" + text + "\": a cambered section needs its camber's position (second digit 1 ... 9)");
    if (s.camber == 0.0) s.camber_position = 0.4;
  } else {
    s.camber = t.get_double("camber_max", 0.0, Bounds::closed(-0.2, 0.2));
    s.camber_position = t.get_double("camber_position", 0.4, Bounds::open(0.0, 1.0));
    if (t.has("camber_position") && !t.has("camber_max"))
      t.fail("camber_position", "without camber_max it shapes nothing: give camber_max too");
  }
  return s;
}

}  // namespace flapsim::wings
