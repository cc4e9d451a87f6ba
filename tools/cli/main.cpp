// cordgrasp: cord-driven grasp planning, physics validation and rendering.
#include <signal.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <atomic>
#include <exception>
#include <iostream>
#include <string>

#include "commands.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/version.h"
#include "cordgrasp/render/backend_info.h"
#include "cordgrasp/sim/backend_info.h"

namespace cordgrasp::cli {
namespace {

std::atomic<int> g_interrupt_signal{0};  ///< the first SIGINT / SIGTERM received, or 0
static_assert(std::atomic<int>::is_always_lock_free, "set from a signal handler");

extern "C" void on_interrupt(int signal_number) {
  if (g_interrupt_signal.load(std::memory_order_relaxed) == 0)
    g_interrupt_signal.store(signal_number, std::memory_order_relaxed);
  struct sigaction fallback {};  // a second signal: the default action (ends the process)
  fallback.sa_handler = SIG_DFL;
  sigemptyset(&fallback.sa_mask);
  sigaction(SIGINT, &fallback, nullptr);
  sigaction(SIGTERM, &fallback, nullptr);
}

/// A scan of millions of triangles is planned in phases (load, BVH, the object's constants) that
/// each allocate and free arrays of a few to tens of MB. glibc maps such arrays afresh and unmaps
/// them on free until its mmap threshold has risen (to 32 MiB at most), so each phase pays the
/// kernel's zeroing of its pages again. The threshold starts at that ceiling here, and up to
/// 256 MiB of freed heap stays for reuse; larger arrays are still mapped and returned.
void reuse_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
}

}  // namespace

void install_interrupt_handlers() {
  for (const int signal_number : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    sigaction(signal_number, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // e.g. a background job of a script
    struct sigaction on {};
    on.sa_handler = on_interrupt;
    sigemptyset(&on.sa_mask);
    on.sa_flags = SA_RESTART;
    sigaction(signal_number, &on, nullptr);
  }
}

CancelToken interrupt_token() { return CancelToken(&g_interrupt_signal); }

}  // namespace cordgrasp::cli

int main(int argc, char** argv) {
  using namespace cordgrasp;
  cli::reuse_freed_memory();
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
  } catch (const Interrupted& e) {
    std::cerr << "cordgrasp: " << e.what() << '\n';
    return kExitInterrupted;
  } catch (const NoGraspFound& e) {
    std::cerr << "cordgrasp: " << e.what() << '\n';
    return kExitNoGrasp;
  } catch (const std::exception& e) {
    std::cerr << "cordgrasp: error: " << e.what() << '\n';
    return kExitError;
  }
  return 0;
}
