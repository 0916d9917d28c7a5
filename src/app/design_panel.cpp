#include "app/design_panel.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <imgui.h>

#include "model/local_params.hpp"
#include "render/scene/culling.hpp"

namespace eco {
namespace {

const ImVec2 kCanvas{190.0f, 84.0f};
constexpr float kHeatmapWidth = 84.0f;
constexpr float kPickPoint_px = 7.0f, kPickSegment_px = 5.0f;
const ImU32 kLine = IM_COL32(230, 230, 230, 255), kPoint = IM_COL32(255, 255, 255, 255),
            kHot = IM_COL32(255, 107, 13, 255), kGrid = IM_COL32(255, 255, 255, 28),
            kBack = IM_COL32(20, 24, 28, 230);

// Screen <-> graph coordinates of one canvas.
struct CanvasFrame {
  ImVec2 origin, size;
  Range xs, ys;
  ImVec2 pixel(double x, double y) const {
    return {origin.x + static_cast<float>((x - xs.min) / (xs.max - xs.min)) * size.x,
            origin.y + static_cast<float>((ys.max - y) / (ys.max - ys.min)) * size.y};
  }
  double x(float px) const { return xs.min + (px - origin.x) / size.x * (xs.max - xs.min); }
  double y(float py) const { return ys.max - (py - origin.y) / size.y * (ys.max - ys.min); }
};

float distanceToSegment(ImVec2 p, ImVec2 a, ImVec2 b) {
  const ImVec2 ab{b.x - a.x, b.y - a.y}, ap{p.x - a.x, p.y - a.y};
  const float length2 = ab.x * ab.x + ab.y * ab.y;
  const float t =
      length2 > 0.0f ? std::clamp((ap.x * ab.x + ap.y * ab.y) / length2, 0.0f, 1.0f) : 0.0f;
  const float dx = ap.x - t * ab.x, dy = ap.y - t * ab.y;
  return std::sqrt(dx * dx + dy * dy);
}

// A blue to yellow ramp for the combined values.
ImU32 rampColor(double t) {
  t = std::clamp(t, 0.0, 1.0);
  const auto c = [&](double a, double b) { return static_cast<int>(255.0 * (a + (b - a) * t)); };
  return IM_COL32(c(0.15, 0.99), c(0.20, 0.86), c(0.55, 0.15), 255);
}

// One graph: draws it and handles the pointer. Returns what the pointer is over.
std::optional<GraphFocus> graphCanvas(DesignSession& session, DesignPanelState& state,
                                      LocalGraph graph) {
  const LocalGraphInfo& info = infoOf(graph);
  const Polyline& line = graphOf(session.species().strand.graphs, graph);
  const auto points = line.points();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const CanvasFrame frame{ImGui::GetCursorScreenPos(), kCanvas, orderAxis(info.over), info.values};
  ImGui::InvisibleButton(info.key.data(), kCanvas,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  const bool hovered = ImGui::IsItemHovered();
  const ImVec2 mouse = ImGui::GetIO().MousePos;

  // What the pointer is over: a point, else a segment, else the graph.
  std::optional<GraphFocus> over;
  if (hovered) {
    over = GraphFocus{graph};
    float best = kPickPoint_px;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const ImVec2 p = frame.pixel(points[i].x, points[i].y);
      const float d = std::hypot(p.x - mouse.x, p.y - mouse.y);
      if (d < best) best = d, over->point = static_cast<int>(i);
    }
    if (over->point < 0)
      for (std::size_t i = 0; i + 1 < points.size(); ++i)
        if (distanceToSegment(mouse, frame.pixel(points[i].x, points[i].y),
                              frame.pixel(points[i + 1].x, points[i + 1].y)) < kPickSegment_px)
          over->segment = static_cast<int>(i);
  }

  // Start a drag on a point; a click on a segment adds a point there and drags it.
  if (over && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    if (over->point >= 0) {
      state.dragging = GraphFocus{graph, over->point};
      // The point keeps its place under the pointer instead of jumping to it.
      const ImVec2 p = frame.pixel(points[over->point].x, points[over->point].y);
      state.grabOffset = {p.x - mouse.x, p.y - mouse.y};
      ++state.gesture;
    } else if (over->segment >= 0) {
      const double x = frame.x(mouse.x);
      ++state.gesture;  // adding the point and dragging it are one undo step
      session.apply(AddPoint{graph, x, std::nullopt}, state.gesture);
      const auto now = graphOf(session.species().strand.graphs, graph).points();
      int index = 0;
      while (index + 1 < static_cast<int>(now.size()) && now[index + 1].x <= x) ++index;
      state.dragging = GraphFocus{graph, index};
      state.grabOffset = {0.0f, 0.0f};
    }
  }
  if (over && over->point >= 0 && points.size() > 1 &&
      ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
    session.apply(RemovePoint{graph, over->point});
    over->point = -1;
  }
  if (state.dragging && state.dragging->graph == graph) {
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      session.apply(MovePoint{graph, state.dragging->point, frame.x(mouse.x + state.grabOffset.x),
                              frame.y(mouse.y + state.grabOffset.y)},
                    state.gesture);
      over = state.dragging;
    } else {
      state.dragging.reset();
    }
  }

  // Drawing: background, whole orders, the zero line, the poly-line and its points.
  const auto& now = graphOf(session.species().strand.graphs, graph).points();
  const ImVec2 end{frame.origin.x + kCanvas.x, frame.origin.y + kCanvas.y};
  draw->AddRectFilled(frame.origin, end, kBack);
  const int step = info.over == BranchOrder::Gravelius ? 1 : 5;
  for (int o = 0; o <= static_cast<int>(frame.xs.max); o += step)
    draw->AddLine(frame.pixel(o, frame.ys.min), frame.pixel(o, frame.ys.max), kGrid);
  if (frame.ys.min < 0.0)
    draw->AddLine(frame.pixel(frame.xs.min, 0), frame.pixel(frame.xs.max, 0), kGrid);
  const GraphFocus* focus = state.pinned && state.pinned->graph == graph ? &*state.pinned
                            : over                                       ? &*over
                                                                         : nullptr;
  std::vector<ImVec2> pixels;
  pixels.push_back(frame.pixel(frame.xs.min, line(frame.xs.min)));
  for (const ControlPoint& p : now) pixels.push_back(frame.pixel(p.x, p.y));
  pixels.push_back(
      frame.pixel(frame.xs.max, graphOf(session.species().strand.graphs, graph)(frame.xs.max)));
  draw->PushClipRect(frame.origin, end, true);
  for (std::size_t i = 0; i + 1 < pixels.size(); ++i) {
    const bool hot = focus && focus->segment >= 0 && static_cast<int>(i) == focus->segment + 1;
    draw->AddLine(pixels[i], pixels[i + 1], hot ? kHot : kLine, hot ? 3.0f : 1.5f);
  }
  draw->PopClipRect();
  std::vector<glm::vec2>& reported = state.pointPixels[static_cast<int>(graph)];
  reported.clear();
  for (std::size_t i = 0; i < now.size(); ++i) {
    const ImVec2 p = frame.pixel(now[i].x, now[i].y);
    const bool hot = focus && focus->point == static_cast<int>(i);
    draw->AddCircleFilled(p, hot ? 5.5f : 3.5f, hot ? kHot : kPoint);
    reported.push_back({p.x, p.y});
  }
  draw->AddText({frame.origin.x + 4, frame.origin.y + 2}, kLine, info.symbol.data(),
                info.symbol.data() + info.symbol.size());
  draw->AddText({end.x - 62, end.y - 15}, kGrid | IM_COL32(0, 0, 0, 200),
                info.over == BranchOrder::Gravelius ? "g 0..15" : "w 0..50");
  if (over && over->point >= 0) {
    const ControlPoint& p = now[over->point];
    ImGui::SetTooltip("%s point %d: (%.3f, %.4g)\ndrag to move, right-click to remove",
                      info.key.data(), over->point, p.x, p.y);
  } else if (over && over->segment >= 0) {
    ImGui::SetTooltip("%s: click to add a point at %s = %.3f", info.key.data(),
                      info.over == BranchOrder::Gravelius ? "g" : "w", frame.x(mouse.x));
  }
  return over;
}

// The combined value of a pair over g (across) and w (down), as evaluateLocal() gives it.
constexpr int kHeatColumns = 16, kHeatRows = 26;  // g = 0..15, w = 0..50 in steps of 2

std::vector<double> combinedValues(const Species& species, const GraphPair& pair) {
  std::vector<double> values;
  for (int r = 0; r < kHeatRows; ++r)
    for (int g = 0; g < kHeatColumns; ++g)
      values.push_back(evaluateLocal(species.strand.graphs, g, 2 * r).*pair.value);
  return values;
}

void combinedHeatmap(const GraphPair& pair, const std::vector<double>& values) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy({kHeatmapWidth, kCanvas.y});
  const float cw = kHeatmapWidth / kHeatColumns, ch = kCanvas.y / kHeatRows;
  for (int r = 0; r < kHeatRows; ++r)
    for (int g = 0; g < kHeatColumns; ++g) {
      const double t = (values[r * kHeatColumns + g] - pair.combined.min) /
                       (pair.combined.max - pair.combined.min);
      draw->AddRectFilled({origin.x + g * cw, origin.y + r * ch},
                          {origin.x + (g + 1) * cw, origin.y + (r + 1) * ch}, rampColor(t));
    }
  if (ImGui::IsItemHovered()) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const int g = std::clamp(static_cast<int>((m.x - origin.x) / cw), 0, kHeatColumns - 1);
    const int r = std::clamp(static_cast<int>((m.y - origin.y) / ch), 0, kHeatRows - 1);
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    ImGui::SetTooltip("%s at g = %d, w = %d: %.4g\n(here %.4g .. %.4g; colours %g .. %g)",
                      pair.name.data(), g, 2 * r, values[r * kHeatColumns + g], *lo, *hi,
                      pair.combined.min, pair.combined.max);
  }
}

void globalsWindow(DesignSession& session, DesignPanelState& state, DesignPanelRequests& requests,
                   const PreviewStats& stats, const std::vector<std::string>& compared) {
  const Species& s = session.species();
  ImGui::SetNextWindowPos({8, 8}, ImGuiCond_FirstUseEver);
  ImGui::Begin("global parameters", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  char name[65];
  std::snprintf(name, sizeof name, "%s", s.name.c_str());
  ImGui::PushItemWidth(190);
  // The name is applied when the field is left, so each letter is not an undo step.
  ImGui::InputText("name", name, sizeof name);
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    try {
      session.apply(SetName{name});
    } catch (const EditRefused& refused) {
      state.status = refused.what();
    }
  }
  ImGui::PopItemWidth();
  if (!s.latinName.empty()) ImGui::TextUnformatted(s.latinName.c_str());
  ImGui::PushItemWidth(190);
  for (const GlobalParameterInfo& info : globalParameters()) {
    const std::string label = fmt::format("{}##{}", info.symbol, info.key);
    bool changed = false;
    double edited = 0.0;
    if (info.integer) {
      int value = static_cast<int>(valueOf(s, info.parameter));
      // Beyond the paper's slider (the pine's S = 6000) the value is typed: Ctrl+click.
      changed = ImGui::SliderInt(
          label.c_str(), &value, static_cast<int>(info.slider.min),
          static_cast<int>(std::max(info.slider.max, static_cast<double>(value))), "%d");
      edited = value;
    } else {
      float value = static_cast<float>(valueOf(s, info.parameter));
      changed = ImGui::SliderFloat(label.c_str(), &value, static_cast<float>(info.slider.min),
                                   static_cast<float>(info.slider.max), "%.4g");
      edited = value;
    }
    if (ImGui::IsItemActivated()) ++state.gesture;  // one slider drag is one undo step
    // The session clamps to the valid range; a typed value may leave the paper's slider.
    if (changed) session.apply(SetGlobal{info.parameter, edited}, state.gesture);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s: %s (slider %g .. %g; Ctrl+click to type)", info.key.data(),
                        info.meaning.data(), info.slider.min, info.slider.max);
  }
  int distribution = static_cast<int>(s.strand.leafDistribution);
  const char* names[] = {"spiral", "stacked", "staggered", "bunched", "coniferous"};
  if (ImGui::Combo("l_type", &distribution, names, 5))
    session.apply(SetLeafDistribution{kLeafDistributions[distribution]});
  float w[3] = {static_cast<float>(s.wind.direction.x), static_cast<float>(s.wind.direction.y),
                static_cast<float>(s.wind.direction.z)};
  const bool turned = ImGui::DragFloat3("w", w, 0.01f, -1.0f, 1.0f, "%.2f");
  if (ImGui::IsItemActivated()) ++state.gesture;
  if (turned && (w[0] != 0 || w[1] != 0 || w[2] != 0))
    session.apply(SetWindDirection{{w[0], w[1], w[2]}}, state.gesture);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("w, toward which the directed wind bends growth (x east, y up, z south)");
  ImGui::PopItemWidth();

  ImGui::Separator();
  ImGui::BeginDisabled(!session.canUndo());
  if (ImGui::Button("undo (Ctrl+Z)")) session.undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!session.canRedo());
  if (ImGui::Button("redo (Ctrl+Y)")) session.redo();
  ImGui::EndDisabled();
  requests.save = ImGui::Button("save (Ctrl+S)");
  ImGui::SameLine();
  requests.exportTree = ImGui::Button("export");
  ImGui::SameLine();
  requests.screenshot = ImGui::Button("screenshot");
  if (!state.status.empty()) ImGui::TextWrapped("%s", state.status.c_str());

  ImGui::Separator();
  ImGui::PushItemWidth(190);
  int seed = static_cast<int>(state.preview.seed);
  if (ImGui::InputInt("seed", &seed) && seed >= 1)
    state.preview.seed = static_cast<std::uint64_t>(seed);
  float age = static_cast<float>(state.preview.age);
  if (ImGui::SliderFloat("age", &age, 0.0f, 1.0f, "%.2f")) state.preview.age = age;
  ImGui::PopItemWidth();
  const char* levels[] = {"LOD0", "LOD1", "LOD2", "impostor"};
  for (int level = 0; level < kLevelCount; ++level) {
    if (level > 0) ImGui::SameLine();
    ImGui::RadioButton(levels[level], &state.preview.level, level);
  }
  requests.frameTree = ImGui::Button("frame tree");
  ImGui::SameLine();
  requests.frameRow = ImGui::Button("frame row");
  ImGui::SameLine();
  ImGui::Checkbox("wind", &state.windPlaying);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the species' own sway, w_s (1 - k_f): with k_f = 1 a tree stands still");
  ImGui::SameLine();
  ImGui::Checkbox(compared.empty() ? "variants and ages" : "variants, ages and compared",
                  &state.row);
  if (!compared.empty()) {
    std::string names = "compared:";
    for (const std::string& name : compared) names += " " + name;
    ImGui::TextUnformatted(names.c_str());
  }
  ImGui::Text("%zu segments, %zu leaves, %zu triangles", stats.segments, stats.leaves,
              stats.triangles);
  ImGui::Text("height %.2f m, crown radius %.2f m, built in %.1f ms", stats.height_m,
              stats.crownRadius_m, stats.buildMs);
  if (state.windowFps > 0.0)
    ImGui::Text("window %.0f frames/s, preview %.0f ms a picture", state.windowFps,
                state.previewMs);
  ImGui::End();
}

}  // namespace

HintInterval hintOf(const GraphFocus& focus, const Species& species) {
  const Polyline& line = graphOf(species.strand.graphs, focus.graph);
  const int count = static_cast<int>(line.points().size());
  if (focus.point >= 0 && focus.point < count)
    return pointInfluence(focus.graph, line, focus.point);
  if (focus.segment >= 0 && focus.segment + 1 < count)
    return segmentSpan(focus.graph, line, focus.segment);
  return wholeGraph(focus.graph);
}

void applyShortcuts(const std::vector<Shortcut>& shortcuts, DesignSession& session,
                    DesignPanelRequests& requests) {
  for (const Shortcut& s : shortcuts) {
    if (s.letter == 'Z' && !s.shift) session.undo();
    if ((s.letter == 'Z' && s.shift) || s.letter == 'Y') session.redo();
    if (s.letter == 'S') requests.save = true;
  }
}

DesignPanelRequests drawDesignPanels(DesignSession& session, DesignPanelState& state,
                                     const PreviewStats& stats,
                                     const std::vector<std::string>& compared, glm::vec2 display) {
  DesignPanelRequests requests;
  globalsWindow(session, state, requests, stats, compared);

  const float width = 2 * kCanvas.x + kHeatmapWidth + 4 * ImGui::GetStyle().ItemSpacing.x + 16;
  ImGui::SetNextWindowPos({display.x - width - 8, 8}, ImGuiCond_FirstUseEver);
  ImGui::Begin("local parameters", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  if (state.combinedVersion != session.version()) {
    state.combined.clear();
    for (const GraphPair& pair : graphPairs())
      state.combined.push_back(combinedValues(session.species(), pair));
    state.combinedVersion = session.version();
  }
  std::optional<GraphFocus> over;
  for (const GraphPair& pair : graphPairs()) {
    ImGui::TextUnformatted(pair.name.data(), pair.name.data() + pair.name.size());
    for (LocalGraph graph : {pair.overG, pair.overW}) {
      if (std::optional<GraphFocus> o = graphCanvas(session, state, graph)) over = o;
      ImGui::SameLine();
    }
    combinedHeatmap(pair, state.combined[&pair - graphPairs().data()]);
  }
  ImGui::End();

  if (state.pinned)
    requests.hint = hintOf(*state.pinned, session.species());
  else if (state.dragging)
    requests.hint = hintOf(*state.dragging, session.species());
  else if (over)
    requests.hint = hintOf(*over, session.species());
  return requests;
}

}  // namespace eco
