#include "app/design_command.hpp"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/data_paths.hpp"
#include "app/design_panel.hpp"
#include "app/view_options.hpp"
#include "core/atomic_file.hpp"
#include "model/design/edit_script.hpp"
#include "model/export/tree_export.hpp"
#include "model/mesh/lod.hpp"
#include "model/species_writer.hpp"
#include "model/tree_generator.hpp"
#include "render/gl/background_preview.hpp"
#include "render/gl/design_view.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/offscreen_ui.hpp"
#include "render/gl/window.hpp"
#include "sim/image_io.hpp"

namespace eco {
namespace {

struct DesignArgs {
  std::string species;
  std::vector<std::string> compare;
  std::string apply;
  std::string name;  // the saved species' new name
  std::string save, exportFile, screenshot;
  FrameSize size{1600, 900};
  std::uint64_t seed = 1;
  double age = 1.0;
  int level = 0;
  bool noRow = false;
  bool noPanels = false;       // a screenshot of the preview alone
  std::string frame = "tree";  // what the camera frames first: the edited tree or the row
  int frames = 0;              // > 0: the window closes after this many frames (automation, tests)
};

std::vector<Species> loadCompared(const std::vector<std::string>& names) {
  std::vector<Species> compared;
  for (const std::string& name : names) compared.push_back(loadSpecies(resolveSpecies(name)));
  return compared;
}

std::vector<std::string> namesOf(const std::vector<Species>& species) {
  std::vector<std::string> names;
  for (const Species& s : species) names.push_back(s.name);
  return names;
}

std::string orDefault(const std::string& path, const Species& species, const char* suffix) {
  return path.empty() ? species.name + "-design" + suffix : path;
}

// The edited tree as `ecoforest tree` exports it: the preview's seed, age and mesh level.
void exportDesigned(const Species& species, const PreviewSettings& preview,
                    const std::filesystem::path& file) {
  TreeBuildOptions options;
  options.seed = preview.seed;
  options.age = preview.age;
  const int lod = preview.level < kLodCount ? preview.level : 0;
  exportTree(buildLod(buildTree(species, options), species, lod), species, file);
}

// The whole preview of the session's species as it stands.
PreviewScene firstScene(const DesignSession& session, const std::vector<Species>& compared,
                        const PreviewSettings& settings) {
  PreviewScene scene = buildCompletePreview(session.species(), compared, settings);
  scene.version = session.version();
  return scene;
}

// Where the window test finds the control points: ECOFOREST_DESIGN_LAYOUT names a JSON file
// that receives each graph's points in window pixels.
void reportLayout(const DesignPanelState& state, FrameSize size) {
  const char* file = std::getenv("ECOFOREST_DESIGN_LAYOUT");
  if (!file || !*file) return;
  nlohmann::ordered_json graphs;
  for (const LocalGraphInfo& info : localGraphs()) {
    nlohmann::json points = nlohmann::json::array();
    for (glm::vec2 p : state.pointPixels[static_cast<int>(info.graph)])
      points.push_back({p.x, p.y});
    graphs[std::string(info.key)] = points;
  }
  AtomicFile out(file);
  out.write(
      nlohmann::ordered_json{{"window", {size.width, size.height}}, {"graphs", graphs}}.dump(1));
  out.commit();
}

// --name: the designed species' new name.
void rename(const DesignArgs& args, DesignSession& session) {
  if (args.name.empty()) return;
  try {
    session.apply(SetName{args.name});
  } catch (const EditRefused& refused) {
    throw InputError(SourceLocation("--name"), refused.what());
  }
}

void runHeadless(const DesignArgs& args, DesignSession& session, DesignPanelState& state,
                 const std::vector<Species>& compared) {
  const EditScript script = loadEditScript(args.apply);
  applyEditScript(script, session);
  if (script.hint) {
    const HintRequest& h = script.hint.value();
    const int points =
        static_cast<int>(graphOf(session.species().strand.graphs, h.graph).points().size());
    if (h.point && *h.point >= points)
      throw InputError(h.where, "the graph has no point " + std::to_string(*h.point));
    if (h.segment && *h.segment + 1 >= points)
      throw InputError(h.where, "the graph has no segment " + std::to_string(*h.segment));
    state.pinned = GraphFocus{h.graph, h.point.value_or(-1), h.segment.value_or(-1)};
    state.preview.hint = hintOf(*state.pinned, session.species());
  }
  rename(args, session);
  std::cout << session.species().name << ": " << script.edits.size() << " edits applied\n";
  if (!args.save.empty()) {
    saveSpecies(session.species(), args.save);
    std::cout << "saved " << args.save << "\n";
  }
  if (!args.exportFile.empty()) {
    exportDesigned(session.species(), state.preview, args.exportFile);
    std::cout << "exported " << args.exportFile << "\n";
  }
  if (args.screenshot.empty()) return;

  HeadlessGl gl;
  DesignView view(session.species(), compared, firstScene(session, compared, state.preview));
  OffscreenUi ui;
  const RenderTarget target = RenderTarget::create(args.size.width, args.size.height);
  const RenderOptions options = previewRenderOptions(state.preview, 0.0, 0.0);
  // ImGui sizes auto-resizing panels over its first frames: draw a few, keep the last.
  for (int frame = 0; frame < 3; ++frame) {
    ui.beginFrame(args.size);
    if (!args.noPanels)
      drawDesignPanels(session, state, view.shown().stats, namesOf(compared),
                       {static_cast<float>(args.size.width), static_cast<float>(args.size.height)});
    view.render(args.frame == "row" ? view.rowCamera() : view.framingCamera(), options, state.row,
                target);
    ui.drawOnto(target);
  }
  writeRgb8Image(args.screenshot, readPixels(target));
  std::cout << "screenshot " << args.screenshot << "\n";
}

void runWindow(const DesignArgs& args, DesignSession& session, DesignPanelState& state,
               const std::vector<Species>& compared) {
  rename(args, session);
  Window window("ecoforest design — " + session.species().name, args.size, "`design`",
                "`ecoforest design --apply EDITS.toml` edits, saves and screenshots without one");
  // The trees are built on one thread and drawn on another (background_preview.hpp): this
  // one only draws the panels and shows the newest picture.
  BackgroundPreview preview(session.species(), compared,
                            firstScene(session, compared, state.preview));
  OrbitCamera camera = args.frame == "row" ? preview.rowCamera() : preview.framingCamera();
  PreviewBuilder builder(compared);
  std::uint64_t requestedVersion = session.version();
  PreviewSettings requested = state.preview;
  const std::vector<std::string> comparedNames = namesOf(compared);
  RenderTarget shown;  // the newest picture, in this context
  PreviewStats stats;
  std::optional<PreviewFrame> lastAsked;
  double windTime = 0.0, lastTime = window.seconds();
  for (int frame = 1; !window.shouldClose(); ++frame) {
    const ViewInput& input = window.beginFrame();
    const double now = window.seconds();
    const double dt = std::min(now - lastTime, 0.1);
    if (now > lastTime) state.windowFps = 0.9 * state.windowFps + 0.1 / (now - lastTime);
    lastTime = now;
    const FrameSize size = window.framebufferSize();
    DesignPanelRequests asked =
        drawDesignPanels(session, state, stats, comparedNames,
                         {static_cast<float>(size.width), static_cast<float>(size.height)});
    if (!input.keyboardTaken) applyShortcuts(input.shortcuts, session, asked);
    state.preview.hint = asked.hint;

    if (asked.frameTree) camera = preview.framingCamera();
    if (asked.frameRow) camera = preview.rowCamera();
    // The orbit camera: drag anywhere off the panels, wheel to zoom.
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureMouse) {
      if (ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right))
        camera.orbit(io.MouseDelta.x, io.MouseDelta.y);
      camera.zoom(io.MouseWheel);
    }

    // A change asks the builder for a new tree; the frame that asked waits for it up to
    // 12 ms when the tree builds that fast (the beech), so it goes to the preview at once.
    std::chrono::milliseconds wait{0};
    if (session.version() != requestedVersion || !(state.preview == requested)) {
      requestedVersion = session.version();
      requested = state.preview;
      builder.request(session.species(), requestedVersion, requested);
      wait = builder.worthWaiting();
    }
    std::optional<PreviewScene> scene = builder.take(wait);
    if (state.windPlaying) windTime += 2.0 * dt;
    PreviewFrame next{camera, state.row,
                      state.windPlaying ? session.species().wind.undirected_ws : 0.0, windTime,
                      size};
    const bool moved = !lastAsked || lastAsked->camera.yaw_deg != next.camera.yaw_deg ||
                       lastAsked->camera.pitch_deg != next.camera.pitch_deg ||
                       lastAsked->camera.distance_m != next.camera.distance_m ||
                       lastAsked->row != next.row || !(lastAsked->size == next.size) ||
                       (next.sway_ws > 0.0 && lastAsked->windTime != next.windTime);
    if ((scene || moved) && size.width > 0 && size.height > 0) {
      preview.request(next, std::move(scene));
      lastAsked = next;
    }
    preview.rethrowFailure();
    if (std::optional<RenderedPreview> picture = preview.take()) {
      if (shown.width != picture->image.width || shown.height != picture->image.height)
        shown = RenderTarget::create(picture->image.width, picture->image.height);
      writePixels(shown, picture->image);
      stats = picture->stats;
      state.previewMs = picture->frameMs;
    }

    try {
      if (asked.save) {
        const std::string file = orDefault(args.save, session.species(), ".toml");
        saveSpecies(session.species(), file);
        state.status = "saved " + file;
      }
      if (asked.exportTree) {
        const std::string file = orDefault(args.exportFile, session.species(), ".glb");
        exportDesigned(session.species(), state.preview, file);
        state.status = "exported " + file;
      }
      if (asked.screenshot && shown.width > 0) {
        const std::string file = orDefault(args.screenshot, session.species(), ".png");
        writeRgb8Image(file, readPixels(shown));
        state.status = "screenshot " + file;
      }
    } catch (const std::exception& error) {
      state.status = error.what();  // the window stays: the user can choose another file
    }
    if (asked.save || asked.exportTree || asked.screenshot)
      std::cerr << "ecoforest design: " << state.status << "\n";
    if (frame == 3) reportLayout(state, size);
    window.present(shown);
    if (args.frames > 0 && frame >= args.frames) break;
  }
}

void runDesign(const DesignArgs& args) {
  DesignSession session(loadSpecies(resolveSpecies(args.species)));
  const std::vector<Species> compared = loadCompared(args.compare);
  DesignPanelState state;
  state.preview.seed = args.seed;
  state.preview.age = args.age;
  state.preview.level = args.level;
  state.row = !args.noRow;
  if (!args.apply.empty())
    runHeadless(args, session, state, compared);
  else
    runWindow(args, session, state, compared);
}

}  // namespace

void addDesignCommand(CLI::App& app) {
  auto args = std::make_shared<DesignArgs>();
  CLI::App* command = app.add_subcommand(
      "design", "Design a species' tree: the EcoMod dialogs with an immediate 3D preview");
  command
      ->add_option("species", args->species, "Species name (beech, pine, ...) or a species .toml")
      ->required();
  command->add_option("--compare", args->compare,
                      "Other species to shape it against, side by side");
  command->add_option("--apply", args->apply,
                      "Apply a file of edits without a window (docs/designer.md), then save, "
                      "export and screenshot as asked");
  command->add_option("--name", args->name,
                      "A new name for the designed species (a variety beside the original)");
  command->add_option("--save", args->save, "Species .toml the edited species is saved to");
  command->add_option("--export", args->exportFile,
                      "Write the edited tree: .obj, .gltf, .glb, .pov or .wrl");
  command->add_option("--screenshot", args->screenshot,
                      "PNG of the designer (with --apply: made headless)");
  addSizeOption(*command, args->size);
  command->add_option("--seed", args->seed, "The individual shown")->capture_default_str();
  command->add_option("--age", args->age, "Age shown, 0 seedling .. 1 mature")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command->add_option("--level", args->level, "Level shown: 0-2 the LODs, 3 the impostor")
      ->check(CLI::Range(0, kLevelCount - 1))
      ->capture_default_str();
  command->add_flag("--no-row", args->noRow, "Show the edited tree alone");
  command->add_flag("--no-panels", args->noPanels,
                    "With --apply: a screenshot of the preview alone");
  command->add_option("--frame", args->frame, "What the camera frames first: tree or row")
      ->check(CLI::IsMember({"tree", "row"}))
      ->capture_default_str();
  command->add_option("--frames", args->frames,
                      "Close the window after this many frames (automation)");
  command->callback([args] { runDesign(*args); });
}

}  // namespace eco
