#include "app/view_panel.hpp"

#include <fmt/format.h>
#include <imgui.h>

namespace eco {

bool ViewState::advance(double dt_s) {
  if (!playing || (playClock_s += dt_s) <= 1.0) return false;
  playClock_s = 0.0;
  yearIndex = (yearIndex + 1) % static_cast<int>(years.size());
  return true;
}

PanelChanges drawViewPanel(ViewState& state, const std::vector<std::string>& speciesNames,
                           RenderOptions& options, CameraController& controller,
                           const FrameStats& stats, const LodBudget* budget) {
  PanelChanges changed;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::Begin("ecoforest", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  if (state.hasRun) {
    changed.year =
        ImGui::SliderInt("snapshot", &state.yearIndex, 0, static_cast<int>(state.years.size()) - 1,
                         fmt::format("year {}", state.years[state.yearIndex]).c_str());
    if (ImGui::Button(state.playing ? "pause" : "play")) state.playing = !state.playing;
  }
  for (std::size_t s = 0; s < speciesNames.size(); ++s) {
    bool on = state.shown[s];
    if (ImGui::Checkbox(speciesNames[s].c_str(), &on)) state.shown[s] = on, changed.species = true;
  }
  float directed = static_cast<float>(options.wind.directed_wg),
        sway = static_cast<float>(options.wind.sway_ws);
  float from = static_cast<float>(options.wind.fromBearing_deg);
  ImGui::SliderFloat("wind w_g", &directed, 0.0f, 10.0f);
  ImGui::SliderFloat("sway w_s", &sway, 0.0f, 10.0f);
  ImGui::SliderFloat("wind from", &from, 0.0f, 360.0f, "%.0f deg");
  options.wind.directed_wg = directed, options.wind.sway_ws = sway,
  options.wind.fromBearing_deg = from;
  float hour = static_cast<float>(options.sun.solarHour);
  ImGui::SliderFloat("solar hour", &hour, 0.0f, 24.0f);
  options.sun.solarHour = hour;
  ImGui::SliderFloat("speed m/s", &controller.speed_mps(), 1.0f, 200.0f);
  bool walking = controller.walking();
  if (ImGui::Checkbox("walk (G)", &walking)) controller.setWalking(walking);
  ImGui::Checkbox("shadows", &options.shadows);
  ImGui::Checkbox("impostors", &options.lod.impostors);
  if (!state.overlayName.empty())
    changed.overlay = ImGui::Checkbox(("overlay " + state.overlayName).c_str(), &state.showOverlay);
  const auto& n = stats.forest.instances;
  ImGui::Text("LOD0 %zu  LOD1 %zu  LOD2 %zu  impostors %zu", n[0], n[1], n[2], n[3]);
  ImGui::Text("triangles %.2f M (all LOD0: %.1f M)", stats.triangles() / 1e6,
              stats.forest.lod0Triangles / 1e6);
  ImGui::Text("frame %.1f ms, prepare %.1f ms", stats.frameMs, stats.prepareMs);
  if (budget) {
    ImGui::Text("target %.0f fps: LOD sizes x%.2f", 1000.0 / budget->target_ms(), budget->scale());
    if (budget->resolution() < 1.0)
      ImGui::Text("resolution %.0f %% of the window", 100.0 * budget->resolution());
    if (budget->cannotReach())
      ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.2f, 1.0f),
                         "not reachable: coarsest levels, lowest resolution");
  }
  changed.screenshot = ImGui::Button("screenshot (P)");
  ImGui::End();
  return changed;
}

}  // namespace eco
