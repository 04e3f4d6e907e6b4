#include "wings/loader/svg_clones.hpp"

#include <cmath>
#include <utility>

#include "wings/loader/input_error.hpp"

namespace flapsim::wings {

namespace {

using Vec = Eigen::Vector2d;

// The inverse of an affine map; false if it has none (a scale of 0).
bool invert(const SvgAffine& m, SvgAffine& inverse) {
  const Eigen::Matrix2d a = m.leftCols<2>();
  const double det = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0), size = a.cwiseAbs().maxCoeff();
  if (!(std::abs(det) > 1e-12 * size * size)) return false;
  inverse.leftCols<2>() << a(1, 1) / det, -a(0, 1) / det, -a(1, 0) / det, a(0, 0) / det;
  inverse.col(2) = -(inverse.leftCols<2>() * m.col(2));
  return true;
}

struct Resolver {
  const SvgCloneSource& source;
  const SvgDrawing& drawing;
  const std::string& key;
  std::size_t& points;  // of the drawing so far, each copy's added as it is made
  std::string why;      // why the last clone could not be drawn

  // The shapes clone c draws, in the drawing's frame; false (and why) if it cannot be drawn.
  bool draw(std::size_t c, int depth, std::vector<SvgShape>& out) {
    const SvgCloneSource::Clone& clone = source.clones[c];
    const std::string& href = clone.href;
    if (href.empty()) return fail("it has no href (the element it clones)");
    if (href.front() != '#') return fail("it clones '" + href + "', not an element of this drawing (#id)");
    const auto t = source.targets.find(href.substr(1));
    if (t == source.targets.end())
      return fail("the drawing has no element with the id '" + href.substr(1) + "'");
    const SvgCloneSource::Target& target = t->second;
    if (target.scaled_symbol)
      return fail(
          "it clones a <symbol> with a viewBox, whose scaling is not read (Edit > Clone > Unlink Clone)");
    if (depth >= kMaxCloneDepth)
      return fail("clones of clones more than " + std::to_string(kMaxCloneDepth) +
                  " deep (a clone of a group holding it?)");
    SvgAffine unplaced;
    if (!invert(target.parent, unplaced))
      return fail("the groups around '" + href.substr(1) + "' scale it to nothing");
    const SvgAffine map = svg_compose(clone.frame, unplaced);
    const bool one_shape = target.last == target.first + 1 && source.items[target.first].shape >= 0;
    std::vector<SvgShape> inner;
    for (std::size_t i = target.first; i < target.last; ++i) {
      const SvgCloneSource::Item& item = source.items[i];
      inner.clear();
      if (item.shape >= 0) {
        inner.push_back(source.shapes[static_cast<std::size_t>(item.shape)]);
        // Counted as it is copied: clones of groups of clones multiply (a few lines may ask
        // for 10^16 copies).
        points += inner.back().points.size();
        if (points > kMaxDrawingPoints)
          throw InputError(drawing.file, clone.use.line, key,
                           too_many_drawing_points() + " (with its clones)");
      } else if (!draw(static_cast<std::size_t>(item.clone), depth + 1, inner)) {
        return false;
      }
      for (SvgShape& s : inner) {
        for (Vec& p : s.points) p = svg_apply(map, p);
        if (s.clone_of.empty()) s.clone_of = s.describe();
        // The groups inside the original, after those around the clone and the clone itself.
        std::vector<std::string> groups = clone.use.group_names;
        if (!one_shape) {
          for (const std::string* n : {&clone.use.id, &clone.use.label})
            if (!n->empty()) groups.push_back(*n);
          if (s.group_names.size() > target.names_before)
            groups.insert(groups.end(),
                          s.group_names.begin() + static_cast<std::ptrdiff_t>(target.names_before),
                          s.group_names.end());
        }
        s.group_names = std::move(groups);
        s.id = one_shape ? clone.use.id : std::string();
        s.label = one_shape ? clone.use.label : std::string();
        s.line = clone.use.line;
        out.push_back(std::move(s));
      }
    }
    return true;
  }

  bool fail(std::string reason) {
    why = std::move(reason);
    return false;
  }
};

// Inserts each batch (position, shapes) before the shape at its position, in order.
void insert_at(std::vector<SvgShape>& shapes,
               std::vector<std::pair<std::size_t, std::vector<SvgShape>>>& batches) {
  if (batches.empty()) return;
  std::vector<SvgShape> merged;
  std::size_t b = 0;
  for (std::size_t i = 0; i <= shapes.size(); ++i) {
    for (; b < batches.size() && batches[b].first == i; ++b)
      for (SvgShape& s : batches[b].second) merged.push_back(std::move(s));
    if (i < shapes.size()) merged.push_back(std::move(shapes[i]));
  }
  shapes = std::move(merged);
}

}  // namespace

void add_svg_clones(const SvgCloneSource& source, SvgDrawing& drawing, std::size_t& points,
                    const std::string& key) {
  Resolver resolver{source, drawing, key, points, {}};
  std::vector<std::pair<std::size_t, std::vector<SvgShape>>> shown, hidden;
  for (std::size_t c = 0; c < source.clones.size(); ++c) {
    const SvgCloneSource::Clone& clone = source.clones[c];
    if (!clone.drawn) continue;
    std::vector<SvgShape> shapes;
    if (!resolver.draw(c, 0, shapes)) {
      drawing.unread_clones.push_back({clone.use, resolver.why});
      continue;
    }
    (clone.hidden ? hidden : shown).emplace_back(clone.position, std::move(shapes));
  }
  insert_at(drawing.shapes, shown);
  insert_at(drawing.hidden, hidden);
}

}  // namespace flapsim::wings
