#include "wings/loader/svg_transform.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "wings/loader/svg_numbers.hpp"

namespace flapsim::wings {

SvgAffine svg_identity() {
  SvgAffine m = SvgAffine::Zero();
  m(0, 0) = m(1, 1) = 1.0;
  return m;
}

SvgAffine svg_translation(double x, double y) {
  SvgAffine m = svg_identity();
  m.col(2) = Eigen::Vector2d(x, y);
  return m;
}

SvgAffine svg_compose(const SvgAffine& a, const SvgAffine& b) {
  SvgAffine m;
  m.leftCols<2>() = a.leftCols<2>() * b.leftCols<2>();
  m.col(2) = a.leftCols<2>() * b.col(2) + a.col(2);
  return m;
}

Eigen::Vector2d svg_apply(const SvgAffine& m, const Eigen::Vector2d& p) {
  return m.leftCols<2>() * p + m.col(2);
}

SvgAffine parse_svg_transform(std::string_view text) {
  SvgAffine m = svg_identity();
  std::size_t i = 0;
  const auto bad = [&](const std::string& why) {
    throw SvgSyntaxError("transform=\"" + std::string(text) + "\": " + why);
  };
  while (true) {
    while (i < text.size() && (std::isspace(static_cast<unsigned char>(text[i])) || text[i] == ',')) ++i;
    if (i >= text.size()) break;
    const std::size_t open = text.find('(', i), close = text.find(')', i);
    if (open == std::string_view::npos || close == std::string_view::npos || close < open)
      bad("expected name(numbers)");
    std::string name(text.substr(i, open - i));
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
    NumberScanner args(text.substr(open + 1, close - open - 1));
    std::vector<double> a;
    while (!args.at_end()) {
      const auto v = args.number();
      if (!v) bad("a number in " + name + "(...) is not a number");
      a.push_back(*v);
    }
    const auto count = [&](std::size_t lo, std::size_t hi) {
      if (a.size() < lo || a.size() > hi)
        bad(name + " takes " + std::to_string(lo) + (lo == hi ? "" : " to " + std::to_string(hi)) +
            " numbers");
    };
    SvgAffine t = svg_identity();
    const double deg = std::numbers::pi / 180.0;
    if (name == "matrix") {
      count(6, 6);
      t << a[0], a[2], a[4], a[1], a[3], a[5];
    } else if (name == "translate") {
      count(1, 2);
      t(0, 2) = a[0];
      t(1, 2) = a.size() > 1 ? a[1] : 0.0;
    } else if (name == "scale") {
      count(1, 2);
      t(0, 0) = a[0];
      t(1, 1) = a.size() > 1 ? a[1] : a[0];
    } else if (name == "rotate") {
      if (a.size() != 1 && a.size() != 3) bad("rotate takes 1 or 3 numbers");
      const double c = std::cos(a[0] * deg), s = std::sin(a[0] * deg);
      t << c, -s, 0.0, s, c, 0.0;
      if (a.size() == 3) {  // about (cx, cy): translate(c) rotate translate(−c)
        const Eigen::Vector2d centre(a[1], a[2]);
        t.col(2) = centre - t.leftCols<2>() * centre;
      }
    } else if (name == "skewX") {
      count(1, 1);
      t(0, 1) = std::tan(a[0] * deg);
    } else if (name == "skewY") {
      count(1, 1);
      t(1, 0) = std::tan(a[0] * deg);
    } else {
      bad("unknown transform '" + name + "'");
    }
    m = svg_compose(m, t);
    i = close + 1;
  }
  return m;
}

std::optional<double> parse_svg_length(std::string_view text) {
  NumberScanner s(text);
  const auto v = s.number();
  if (!v) return std::nullopt;
  std::string unit(text.substr(s.position()));
  unit.erase(std::remove_if(unit.begin(), unit.end(),
                            [](char c) { return std::isspace(static_cast<unsigned char>(c)); }),
             unit.end());
  // CSS: 1 in = 96 px = 2.54 cm = 72 pt = 6 pc.
  if (unit.empty() || unit == "px") return *v;
  if (unit == "mm") return *v * 96.0 / 25.4;
  if (unit == "cm") return *v * 96.0 / 2.54;
  if (unit == "in") return *v * 96.0;
  if (unit == "pt") return *v * 96.0 / 72.0;
  if (unit == "pc") return *v * 16.0;
  return std::nullopt;
}

}  // namespace flapsim::wings
