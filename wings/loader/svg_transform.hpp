#pragma once
/// \file svg_transform.hpp
/// \brief The `transform` attribute of SVG (1.1, 7.6: matrix, translate, scale, rotate
/// with or without a centre, skewX, skewY, composed left to right) and lengths with CSS
/// units, for the drawing's reader (wings/loader/svg_drawing.hpp).

#include <Eigen/Core>
#include <optional>
#include <string_view>

namespace flapsim::wings {

/// An affine map of the plane, [A | t]: p ↦ A p + t.
using SvgAffine = Eigen::Matrix<double, 2, 3>;

SvgAffine svg_identity();
/// translate(x, y).
SvgAffine svg_translation(double x, double y);
/// a ∘ b: b first.
SvgAffine svg_compose(const SvgAffine& a, const SvgAffine& b);
Eigen::Vector2d svg_apply(const SvgAffine& m, const Eigen::Vector2d& p);

/// The map of a `transform` attribute's value.
/// \throws SvgSyntaxError (wings/loader/svg_numbers.hpp) naming what is wrong in it
SvgAffine parse_svg_transform(std::string_view text);

/// A length attribute (a number with an optional unit: px, mm, cm, in, pt, pc) in user
/// units (px; 96 a CSS inch); nullopt if it is none.
std::optional<double> parse_svg_length(std::string_view text);

}  // namespace flapsim::wings
