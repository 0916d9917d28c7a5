// The ecoforest command line. Errors are caught here, in one place (README, "Exit codes"):
// bad input exits with 2 and "ecoforest: error: FILE:LINE: message", a machine that lacks
// what the work needs with 3 and "ecoforest: cannot run here: ...", a bug with 1.
#include <csignal>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/compare_command.hpp"
#include "app/conditions_command.hpp"
#include "app/design_command.hpp"
#include "app/export_command.hpp"
#include "app/lsystem_command.hpp"
#include "app/render_command.hpp"
#include "app/run_command.hpp"
#include "app/stand_command.hpp"
#include "app/timelapse_command.hpp"
#include "app/tree_command.hpp"
#include "app/validate_command.hpp"
#include "app/view_command.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"

int main(int argc, char** argv) {
  // Ctrl-C removes the temporaries of whatever is being written (core/interrupt.hpp).
  eco::installInterruptCleanup();
  // A file-size limit (ulimit -f) then fails a write with EFBIG, reported like a full disk,
  // instead of killing the process with the temporary left behind.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"ecoforest grows forests: procedural EcoMod trees, ecosystems, renders and exports"};
  app.set_version_flag("--version", std::string("ecoforest ") + ECOFOREST_VERSION);
  app.require_subcommand(1);
  eco::addTreeCommand(app);
  eco::addLSystemCommand(app);
  eco::addDesignCommand(app);
  eco::addConditionsCommand(app);
  eco::addTerrainCommand(app);
  eco::addRunCommand(app);
  eco::addValidateCommand(app);
  eco::addCompareCommand(app);
  eco::addStandCommand(app);
  eco::addRenderCommand(app);
  eco::addViewCommand(app);
  eco::addExportCommand(app);
  eco::addTimelapseCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForVersion& version) {
    return app.exit(version);
  } catch (const CLI::RuntimeError& done) {
    return done.get_exit_code();  // a command that reported its own outcome (an interrupted run)
  } catch (const CLI::ParseError& error) {
    std::cerr << "ecoforest: error: " << error.what() << "\n";
    if (error.get_exit_code() != 0) std::cerr << "Run with --help for usage.\n";
    return eco::kExitBadInput;
  } catch (const eco::InputError& error) {
    std::cerr << "ecoforest: error: " << error.what() << "\n";
    return eco::kExitBadInput;
  } catch (const eco::EnvironmentError& error) {
    std::cerr << "ecoforest: cannot run here: " << error.what() << "\n";
    return eco::kExitEnvironment;
  } catch (const std::exception& error) {
    std::cerr << "ecoforest: internal error (a bug; please report it): " << error.what() << "\n";
    return eco::kExitBug;
  }
  return 0;
}
