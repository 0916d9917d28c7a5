#include "model/design/design_session.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "core/names.hpp"

namespace eco {
namespace {

std::vector<ControlPoint> pointsOf(const Polyline& line) {
  return {line.points().begin(), line.points().end()};
}

void requirePoint(const std::vector<ControlPoint>& points, LocalGraph graph, int index) {
  if (index < 0 || index >= static_cast<int>(points.size()))
    throw EditRefused(std::string(infoOf(graph).key) + " has no point " + std::to_string(index) +
                      " (it has " + std::to_string(points.size()) + ", counted from 0)");
}

double finiteOr(double value, double fallback) {
  return std::isfinite(value) ? value : fallback;
}

void movePoint(Species& species, const MovePoint& move) {
  Polyline& line = graphOf(species.strand.graphs, move.graph);
  std::vector<ControlPoint> points = pointsOf(line);
  requirePoint(points, move.graph, move.index);
  const LocalGraphInfo& info = infoOf(move.graph);
  const Range axis = orderAxis(info.over);
  const auto i = static_cast<std::size_t>(move.index);
  const double lo = i > 0 ? points[i - 1].x : axis.min;
  const double hi = i + 1 < points.size() ? points[i + 1].x : axis.max;
  points[i].x = std::clamp(finiteOr(move.x, points[i].x), lo, hi);
  points[i].y = info.values.clamp(finiteOr(move.y, points[i].y));
  line = Polyline(std::move(points));
}

void addPoint(Species& species, const AddPoint& add) {
  Polyline& line = graphOf(species.strand.graphs, add.graph);
  const LocalGraphInfo& info = infoOf(add.graph);
  const double x = orderAxis(info.over).clamp(finiteOr(add.x, 0.0));
  const double y = info.values.clamp(finiteOr(add.y.value_or(line(x)), line(x)));
  std::vector<ControlPoint> points = pointsOf(line);
  const auto after = std::upper_bound(points.begin(), points.end(), x,
                                      [](double v, const ControlPoint& p) { return v < p.x; });
  points.insert(after, {x, y});
  line = Polyline(std::move(points));
}

void removePoint(Species& species, const RemovePoint& remove) {
  Polyline& line = graphOf(species.strand.graphs, remove.graph);
  std::vector<ControlPoint> points = pointsOf(line);
  requirePoint(points, remove.graph, remove.index);
  if (points.size() == 1)
    throw EditRefused(std::string(infoOf(remove.graph).key) + ": a graph keeps at least one point");
  points.erase(points.begin() + remove.index);
  line = Polyline(std::move(points));
}

}  // namespace

void applyEdit(Species& species, const EditAction& edit) {
  std::visit(
      [&](const auto& e) {
        using E = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<E, SetGlobal>) {
          setValue(species, e.parameter, e.value);
        } else if constexpr (std::is_same_v<E, SetName>) {
          if (const std::string why = whyNotAPlainName(e.name); !why.empty())
            throw EditRefused("'" + e.name + "' cannot name a species: " + why);
          species.name = e.name;
        } else if constexpr (std::is_same_v<E, SetLeafDistribution>) {
          species.strand.leafDistribution = e.distribution;
        } else if constexpr (std::is_same_v<E, SetWindDirection>) {
          const double length = glm::length(e.direction);
          if (!(length > 0.0) || !std::isfinite(length))
            throw EditRefused("the wind direction w needs a direction: it cannot be zero");
          species.wind.direction = e.direction;
        } else if constexpr (std::is_same_v<E, MovePoint>) {
          movePoint(species, e);
        } else if constexpr (std::is_same_v<E, AddPoint>) {
          addPoint(species, e);
        } else {
          removePoint(species, e);
        }
      },
      edit);
}

DesignSession::DesignSession(Species species) : species_(std::move(species)) {
  if (species_.generator != TreeGenerator::Strand)
    throw InputError(
        SourceLocation(species_.file.string(), 0, "generator"),
        species_.name + " grows from an RL-system grammar; the designer edits strand species");
}

void DesignSession::apply(const EditAction& edit, std::uint64_t gesture) {
  Species edited = species_;
  applyEdit(edited, edit);  // throws before anything changes
  if (gesture == 0 || gesture != lastGesture_) {
    undo_.push_back(std::move(species_));
    redo_.clear();
  }
  lastGesture_ = gesture;
  species_ = std::move(edited);
  ++version_;
}

bool DesignSession::undo() {
  return stepBack(undo_, redo_);
}

bool DesignSession::redo() {
  return stepBack(redo_, undo_);
}

bool DesignSession::stepBack(std::vector<Species>& from, std::vector<Species>& to) {
  if (from.empty()) return false;
  to.push_back(std::move(species_));
  species_ = std::move(from.back());
  from.pop_back();
  lastGesture_ = 0;
  ++version_;
  return true;
}

}  // namespace eco
