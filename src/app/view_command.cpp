#include "app/view_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/scene_source.hpp"
#include "app/view_options.hpp"
#include "core/error.hpp"
#include "sim/image_io.hpp"

namespace eco {
namespace {

struct ViewArgs {
  std::string source;
  std::optional<int> year;
  std::size_t demoTrees = 0;
  int frames = 0;  // > 0: quit after this many frames (automation, tests)
  std::string screenshot = "ecoforest_view.png";
  ViewOptions view;
};

// The trees of the shown year with the species the user switched off left out.
Forest visibleTrees(const Forest& all, const TreeLibrary& library, const std::vector<char>& shown) {
  Forest forest;
  forest.reserve(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!shown[library.types()[all.type[i]].species]) continue;
    forest.append(all, i);
  }
  return forest;
}

void saveScreenshot(const RenderTarget& target, const std::string& file) {
  if (target.width == 0) return;  // nothing drawn yet
  target.bind();
  const Image image = readPixels(target.width, target.height);
  writeRgb8Image(file, image);
  std::cerr << "ecoforest view: saved " << file << "\n";
}

class GlfwSession {
 public:
  GlfwSession() {
    if (!glfwInit())
      throw InputError({"DISPLAY", 0, ""},
                       "`view` needs a display and none could be opened; `ecoforest render` "
                       "draws stills without one");
  }
  ~GlfwSession() { glfwTerminate(); }
};

void runView(const ViewArgs& args) {
  SceneSource source = openSceneSource(args.source);
  if (args.year) source.requireSnapshot(*args.year);
  std::vector<int> years = source.run ? source.run->snapshotYears : std::vector<int>{0};
  if (years.empty()) years.push_back(0);
  int yearIndex = static_cast<int>(years.size()) - 1;
  if (args.year)
    yearIndex = static_cast<int>(std::find(years.begin(), years.end(), *args.year) - years.begin());
  std::optional<Field> overlay;
  if (!args.view.overlay.empty()) overlay = source.overlay(args.view.overlay);
  if (source.run || args.demoTrees > 0) source.buildLibrary();

  GlfwSession session;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(
      args.view.size.width, args.view.size.height, ("ecoforest — " + source.scenario.name).c_str(), nullptr, nullptr);
  if (!window) throw std::runtime_error("view: could not open an OpenGL 4.5 window");
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");

  {
    SceneRenderer renderer(source.terrain, source.scenario.climate.latitude_deg,
                           source.library.get());
    if (overlay) renderer.terrain().setOverlay(args.view.overlay, *overlay);
    Camera camera = cameraFrom(args.view, source.terrain);
    RenderOptions options = renderOptionsFrom(args.view, source.scenario);
    const std::size_t speciesCount = source.library ? source.library->species().size() : 0;
    std::vector<char> shown(speciesCount, 1);
    std::map<int, Forest> loaded;  // snapshot year -> its trees
    auto treesOf = [&](int year) -> const Forest& {
      auto it = loaded.find(year);
      if (it == loaded.end())
        it = loaded.emplace(year, source.forestOf(year, args.demoTrees)).first;
      return it->second;
    };
    Forest forest =
        source.library ? visibleTrees(treesOf(years[yearIndex]), *source.library, shown) : Forest{};
    bool walk = args.view.view == "ground", playing = false, showOverlay = overlay.has_value();
    float speed = 20.0f;
    double lastTime = glfwGetTime(), playClock = 0.0, lastX = 0.0, lastY = 0.0;
    glfwGetCursorPos(window, &lastX, &lastY);
    RenderTarget target;
    FrameStats stats;
    int frame = 0;
    std::map<int, bool> wasDown;   // key -> held in the previous frame
    auto pressed = [&](int key) {  // went down since the previous frame
      const bool down = glfwGetKey(window, key) == GLFW_PRESS;
      const bool edge = down && !wasDown[key];
      wasDown[key] = down;
      return edge;
    };

    while (!glfwWindowShouldClose(window)) {
      glfwPollEvents();
      const double now = glfwGetTime();
      const float dt = static_cast<float>(std::min(now - lastTime, 0.1));
      lastTime = now;
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      const ImGuiIO& io = ImGui::GetIO();

      // Fly: WASD (+ Q/E down/up, Shift faster), look with the right mouse button held.
      double mouseX = 0.0, mouseY = 0.0;
      glfwGetCursorPos(window, &mouseX, &mouseY);
      if (!io.WantCaptureMouse &&
          glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) {
        camera.yaw_deg += 0.15f * static_cast<float>(mouseX - lastX);
        camera.pitch_deg = std::clamp(camera.pitch_deg - 0.15f * static_cast<float>(mouseY - lastY),
                                      -89.0f, 89.0f);
      }
      lastX = mouseX, lastY = mouseY;
      if (!io.WantCaptureKeyboard) {
        const float step =
            speed * dt * (glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ? 5.0f : 1.0f);
        auto held = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f; };
        glm::vec3 forward = camera.forward();
        if (walk) forward = glm::normalize(glm::vec3(forward.x, 0.0f, forward.z));
        camera.position += step * ((held(GLFW_KEY_W) - held(GLFW_KEY_S)) * forward +
                                   (held(GLFW_KEY_D) - held(GLFW_KEY_A)) * camera.right() +
                                   (held(GLFW_KEY_E) - held(GLFW_KEY_Q)) * glm::vec3(0, 1, 0));
        if (pressed(GLFW_KEY_G)) walk = !walk;
        if (pressed(GLFW_KEY_P)) saveScreenshot(target, args.screenshot);
        if (pressed(GLFW_KEY_SPACE)) playing = !playing;
      }
      if (walk)  // eyes 1.7 m above the ground under the camera
        camera.position.y = groundBelow(source.terrain, camera.position) + 1.7f;

      // Growth: the play button steps through the snapshots, one a second.
      bool yearChanged = false;
      if (playing && (playClock += dt) > 1.0) {
        playClock = 0.0;
        yearIndex = (yearIndex + 1) % static_cast<int>(years.size());
        yearChanged = true;
      }
      options.wind.time += dt * 2.0;

      ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
      ImGui::Begin("ecoforest");
      if (source.run) {
        yearChanged |=
            ImGui::SliderInt("snapshot", &yearIndex, 0, static_cast<int>(years.size()) - 1,
                             fmt::format("year {}", years[yearIndex]).c_str());
        if (ImGui::Button(playing ? "pause" : "play")) playing = !playing;
      }
      bool speciesChanged = false;
      for (std::size_t s = 0; s < speciesCount; ++s) {
        bool on = shown[s];
        if (ImGui::Checkbox(source.library->species()[s].name.c_str(), &on))
          shown[s] = on, speciesChanged = true;
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
      ImGui::SliderFloat("speed m/s", &speed, 1.0f, 200.0f);
      ImGui::Checkbox("walk (G)", &walk);
      ImGui::Checkbox("shadows", &options.shadows);
      ImGui::Checkbox("impostors", &options.lod.impostors);
      if (overlay && ImGui::Checkbox(("overlay " + args.view.overlay).c_str(), &showOverlay)) {
        if (showOverlay)
          renderer.terrain().setOverlay(args.view.overlay, *overlay);
        else
          renderer.terrain().clearOverlay();
      }
      const auto& n = stats.forest.instances;
      ImGui::Text("LOD0 %zu  LOD1 %zu  LOD2 %zu  impostors %zu", n[0], n[1], n[2], n[3]);
      ImGui::Text("triangles %.2f M (all LOD0: %.1f M)", stats.triangles() / 1e6,
                  stats.forest.lod0Triangles / 1e6);
      ImGui::Text("frame %.1f ms, prepare %.1f ms", stats.frameMs, stats.prepareMs);
      if (ImGui::Button("screenshot (P)")) saveScreenshot(target, args.screenshot);
      ImGui::End();

      if ((yearChanged || speciesChanged) && source.library)
        forest = visibleTrees(treesOf(years[yearIndex]), *source.library, shown);

      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      if (width > 0 && height > 0) {
        if (target.width != width || target.height != height)
          target = RenderTarget::create(width, height);
        stats = renderer.render(&forest, camera, options, target);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer.id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                          GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDisable(GL_FRAMEBUFFER_SRGB);  // ImGui's colours are already sRGB
      }
      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      glfwSwapBuffers(window);
      if (args.frames > 0 && ++frame >= args.frames) {
        saveScreenshot(target, args.screenshot);
        break;
      }
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
}

}  // namespace

void addViewCommand(CLI::App& app) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* command = app.add_subcommand("view",
                                         "Fly through a run or a scenario in a window (WASD, right "
                                         "mouse to look, G walk, P screenshot)");
  command->add_option("source", args->source, "A run folder, or a scenario (name or .toml)")
      ->required();
  command->add_option("--year", args->year,
                      "Snapshot year to start with (default: the run's last)");
  command->add_option("--demo-trees", args->demoTrees,
                      "With a scenario: plant this many trees at random");
  command->add_option("--frames", args->frames,
                      "Quit after this many frames, saving a screenshot (automation)");
  command->add_option("--screenshot", args->screenshot, "PNG file the screenshot key writes");
  addFrameOptions(*command, args->view);
  addCameraOptions(*command, args->view);
  command->callback([args] { runView(*args); });
}

}  // namespace eco
