#pragma once
/// \file state_camera.hpp
/// \brief The camera of a run's ParaView state (pvsm_state.hpp): the direction from which
/// the wing shows most of itself at its worst frame. A flapping wing turns edge-on to some
/// direction at some phase (seen from above, it is edge-on at the stroke reversals); so
/// over a set of candidate directions (azimuth every 15°, elevation 0° … 60° above the
/// stroke plane), this keeps for each the smallest projected area of the wing over the
/// frames written, and picks the direction whose smallest area is the largest share of a
/// picture that frames the wing's bounds over the run (parallel projection).

#include <array>
#include <optional>
#include <vector>

#include "pipeline/io/vtk_writers.hpp"

namespace flapsim::io {

/// A camera direction: unit vector from the focal point toward the camera, and up.
struct ViewDirection {
  std::array<double, 3> toward{0.0, 0.0, 1.0}, up{0.0, 1.0, 0.0};
};

/// A parallel-projection camera that frames a box.
struct FramingCamera {
  std::array<double, 3> position{}, focal_point{}, up{};
  double parallel_scale = 1.0;  ///< half the picture's height [m]
};

/// Share of the picture's width the framed box may use (the rest, on the right, holds
/// the scalar bars) [-].
inline constexpr double kFramedWidth = 0.84;

/// \brief The camera looking along -d.toward that frames \p box (xmin, xmax, ymin, ymax,
/// zmin, zmax) [m] in a picture of \p aspect (width / height) with 5 % margin, the box in
/// the left kFramedWidth of the picture.
FramingCamera frame_box(const std::array<double, 6>& box, const ViewDirection& d, double aspect);

class StateCameraChooser {
 public:
  StateCameraChooser();

  /// \brief Takes a frame of the wing (its polygons; lines and points are ignored for
  /// the area but count in the bounds).
  void add_frame(const PolyDataMesh& wing);

  /// The bounds of every frame's points, if any [m].
  const std::optional<std::array<double, 6>>& bounds() const { return bounds_; }

  /// \brief The direction whose smallest projected wing area over the frames is the
  /// largest share of the picture that frames \p box (the bounds, maybe grown) at \p aspect.
  /// \param share  if not null, set to that share [-]
  ViewDirection best(const std::array<double, 6>& box, double aspect, double* share = nullptr) const;

 private:
  std::vector<ViewDirection> candidates_;
  std::vector<double> smallest_area_;  ///< per candidate [m²]
  std::optional<std::array<double, 6>> bounds_;
  bool any_frame_ = false;
};

}  // namespace flapsim::io
