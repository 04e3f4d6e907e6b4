#include "pipeline/io/state_camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace flapsim::io {

namespace {

using Vec = std::array<double, 3>;

Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec normalized(Vec a) {
  const double n = std::sqrt(dot(a, a));
  for (double& x : a) x /= n;
  return a;
}

// Half extents of the box across (right), up and along the view, about its centre [m].
struct Extents {
  double across = 0.0, up = 0.0, depth = 0.0;
};
Extents extents(const std::array<double, 6>& box, const Vec& right, const Vec& up, const Vec& toward) {
  const Vec c = {0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]), 0.5 * (box[4] + box[5])};
  Extents e;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec p = {box[corner & 1] - c[0], box[2 + ((corner >> 1) & 1)] - c[1], box[4 + ((corner >> 2) & 1)] - c[2]};
    e.across = std::max(e.across, std::abs(dot(p, right)));
    e.up = std::max(e.up, std::abs(dot(p, up)));
    e.depth = std::max(e.depth, std::abs(dot(p, toward)));
  }
  return e;
}

}  // namespace

FramingCamera frame_box(const std::array<double, 6>& box, const ViewDirection& d, double aspect) {
  const Vec right = normalized(cross(d.up, d.toward));
  const Vec up = cross(d.toward, right);
  const Extents e = extents(box, right, up, d.toward);
  FramingCamera cam;
  cam.parallel_scale = std::max(1.05 * std::max(e.up, e.across / (aspect * kFramedWidth)), 1e-9);
  // The box's centre at kFramedWidth / 2 of the picture's width from its left edge: the
  // focal point (the picture's centre) that far to the right of it.
  const double shift = (0.5 - 0.5 * kFramedWidth) * 2.0 * cam.parallel_scale * aspect;
  const double distance = e.depth + 4.0 * cam.parallel_scale;
  for (int i = 0; i < 3; ++i) {
    const double c = 0.5 * (box[2 * i] + box[2 * i + 1]) + shift * right[i];
    cam.focal_point[i] = c;
    cam.position[i] = c + distance * d.toward[i];
    cam.up[i] = up[i];
  }
  return cam;
}

StateCameraChooser::StateCameraChooser() {
  constexpr double deg = std::numbers::pi / 180.0;
  for (double el : {0.0, 10.0, 20.0, 30.0, 45.0, 60.0})
    for (int az = 0; az < 360; az += 15)
      candidates_.push_back({{std::cos(el * deg) * std::cos(az * deg), std::cos(el * deg) * std::sin(az * deg),
                              std::sin(el * deg)},
                             {0.0, 0.0, 1.0}});
  smallest_area_.assign(candidates_.size(), std::numeric_limits<double>::infinity());
}

void StateCameraChooser::add_frame(const PolyDataMesh& wing) {
  for (Eigen::Index k = 0; k < wing.points.cols(); ++k) {
    if (!bounds_)
      bounds_ = std::array<double, 6>{wing.points(0, k), wing.points(0, k), wing.points(1, k),
                                      wing.points(1, k), wing.points(2, k), wing.points(2, k)};
    for (int i = 0; i < 3; ++i) {
      (*bounds_)[2 * i] = std::min((*bounds_)[2 * i], wing.points(i, k));
      (*bounds_)[2 * i + 1] = std::max((*bounds_)[2 * i + 1], wing.points(i, k));
    }
  }
  if (wing.polygons.empty()) return;
  any_frame_ = true;
  // Each polygon's area vector, ½ Σ p_i × p_{i+1} [m²]; its projection along d is |A·d|.
  std::vector<Vec> areas;
  areas.reserve(wing.polygons.size());
  for (const std::vector<int>& poly : wing.polygons) {
    Vec a{0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const auto p = wing.points.col(poly[i]);
      const auto q = wing.points.col(poly[(i + 1) % poly.size()]);
      const Vec c = cross({p.x(), p.y(), p.z()}, {q.x(), q.y(), q.z()});
      for (int j = 0; j < 3; ++j) a[j] += 0.5 * c[j];
    }
    areas.push_back(a);
  }
  for (std::size_t k = 0; k < candidates_.size(); ++k) {
    double projected = 0.0;
    for (const Vec& a : areas) projected += std::abs(dot(a, candidates_[k].toward));
    smallest_area_[k] = std::min(smallest_area_[k], projected);
  }
}

ViewDirection StateCameraChooser::best(const std::array<double, 6>& box, double aspect, double* share) const {
  std::size_t best = 0;
  double best_share = -1.0;
  for (std::size_t k = 0; any_frame_ && k < candidates_.size(); ++k) {
    const FramingCamera cam = frame_box(box, candidates_[k], aspect);
    const double picture = 4.0 * cam.parallel_scale * cam.parallel_scale * aspect;  // [m²]
    const double s = smallest_area_[k] / picture;
    if (s > best_share) best_share = s, best = k;
  }
  if (share) *share = std::max(best_share, 0.0);
  return candidates_[best];
}

}  // namespace flapsim::io
