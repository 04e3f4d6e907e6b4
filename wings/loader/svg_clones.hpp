#pragma once
/// \file svg_clones.hpp
/// \brief The `<use>` elements of an SVG drawing: Inkscape's clones (Edit > Clone > Create
/// Clone), drawn as copies of the element they refer to (SVG 1.1, 5.6), for the drawing's
/// reader (wings/loader/svg_drawing.hpp).
///
/// A `<use href="#id" x="…" y="…" transform="…">` draws the element `id` — a shape, or a group
/// and the shapes in it, wherever it is: drawn, hidden, or defined in `<defs>` or a
/// `<symbol>` — in the use's own frame: its transform and those of the groups around it, then
/// translate(x, y), then the referred element's own transform and those of the groups inside
/// it, not those of the groups around the original (SVG 1.1, 5.6). A clone of a clone is
/// followed, up to kMaxCloneDepth clones deep. A clone is drawn or hidden as its `<use>` is
/// (`display:none` on it or around it), whatever its original is.
///
/// Names: the clone of one shape is named as the `<use>` (its id and label: the clone an
/// outline_id or drawing_id names), the shapes of a clone of a group are found by the use's
/// name as the shapes of a group (find_svg_shapes); their own ids and labels stay the
/// originals' alone. A clone that cannot be drawn (its id not in the drawing, another file's,
/// a `<symbol>` scaled by its viewBox, nested deeper than kMaxCloneDepth) is not a shape; a name
/// that only it has is refused saying why (missing_shape_note).

#include "wings/loader/svg_drawing.hpp"
#include "wings/loader/svg_transform.hpp"

#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

namespace flapsim::wings {

/// How many clones deep a clone of a clone is followed (a clone of its own group never ends).
inline constexpr int kMaxCloneDepth = 16;

/// What the reader collects for the clones while it reads the drawing, in document order.
struct SvgCloneSource {
  /// One `<use>`.
  struct Clone {
    SvgShape use;              ///< element "use", its id, label, line and the groups around it
    std::string href;          ///< its href or xlink:href, as written
    SvgAffine frame;           ///< the use's transforms, the groups' around it, then translate(x, y)
    bool hidden = false;       ///< display:none on it or around it
    bool drawn = false;        ///< outside <defs> and <symbol> (else only a part of another clone)
    std::size_t position = 0;  ///< shapes (or hidden shapes) before it in the drawing
  };
  /// An element with an id: the items of it and inside it, items[first, last).
  struct Target {
    std::size_t first = 0, last = 0;
    SvgAffine parent;  ///< the transforms of the groups around it (not its own)
    /// Its shapes' group_names start with this many names: the groups' around it and its own.
    std::size_t names_before = 0;
    bool scaled_symbol = false;  ///< a <symbol> with a viewBox (its scaling is not applied: not drawn)
  };
  /// A shape or a clone, in document order: one of the two indices is ≥ 0.
  struct Item {
    int shape = -1, clone = -1;
  };
  std::vector<SvgShape> shapes;  ///< every shape (drawn, hidden, defined), in the drawing's frame
  std::vector<Clone> clones;
  std::vector<Item> items;
  std::unordered_map<std::string, Target> targets;  ///< by id (the first element of an id)
};

/// Adds the clones of \p source to \p drawing: a clone's shapes where its `<use>` is among the
/// shapes (or the hidden shapes), the clones that cannot be drawn to SvgDrawing::unread_clones.
/// \param points the points of the drawing's shapes so far; the clones' are added
/// \throws flapsim::InputError (at the use's line) past kMaxDrawingPoints
void add_svg_clones(const SvgCloneSource& source, SvgDrawing& drawing, std::size_t& points,
                    const std::string& key);

}  // namespace flapsim::wings
