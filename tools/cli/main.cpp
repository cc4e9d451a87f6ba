// cordgrasp: cord-driven grasp planning, physics validation and rendering.
#include <exception>
#include <iostream>
#include <string>

#include "commands.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/version.h"
#include "cordgrasp/render/backend_info.h"
#include "cordgrasp/sim/backend_info.h"

int main(int argc, char** argv) {
  using namespace cordgrasp;
  CLI::App app{
      "cordgrasp: plan grasps for multi-fingered hands with the cord-driven planner\n"
      "(Li et al., T-RO 2015), prove them in Bullet physics, render them to PNG.",
      "cordgrasp"};
  app.set_version_flag("--version", std::string("cordgrasp ") + version() + "\n  " +
                                        sim_backend_version() + "\n  " +
                                        render_backend_version());
  app.require_subcommand(1);
  // Refusals are one line on stderr ("--mu: nan is not a finite number in [0, 10]"), without
  // CLI11's "Run with --help" footer.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string(e.what()) + '\n';
  });
  app.fallthrough();
  cli::add_run_command(app);
  cli::add_info_command(app);
  cli::add_explore_command(app);
  cli::add_plan_command(app);
  cli::add_validate_command(app);
  cli::add_render_command(app);
  cli::add_bench_command(app);
  cli::add_generate_objects_command(app);
  cli::add_merge_command(app);
  cli::add_hand_command(app);
  cli::add_export_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const NoGraspFound& e) {
    std::cerr << "cordgrasp: " << e.what() << '\n';
    return kExitNoGrasp;
  } catch (const std::exception& e) {
    std::cerr << "cordgrasp: error: " << e.what() << '\n';
    return kExitError;
  }
  return 0;
}
