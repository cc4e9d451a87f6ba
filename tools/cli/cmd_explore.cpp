// `cordgrasp explore`: the cord exploration stage (docs/algorithm.md) on one object, for a
// hand's palm width (--hand, default the shipped default hand) or an explicit --palm-width-m.
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "options.h"
#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/jobs/explore_job.h"

namespace cordgrasp::cli {
namespace {

std::string point_text(const Eigen::Vector3d& p) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(4) << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return s.str();
}

void print_regions(const ExploreOutcome& out, const ExploreJobParams& opt) {
  std::cout << "object   " << out.object_name << "  (" << out.triangles << " triangles)  "
            << "W_palm " << out.palm_width_m << " m (" << out.palm_width_from << ")  seed "
            << opt.cord.seed << '\n'
            << "explored " << std::fixed << std::setprecision(4) << out.stats.time_s << " s  ("
            << "sampling " << out.stats.sampling_time_s << " s, local improvement "
            << out.stats.improvement_time_s << " s)"
            << (out.stats.hit_time_limit ? "  TIME LIMIT" : "")
            << '\n'
            << "sampled  " << out.stats.triangles_sampled << " triangles, " << out.stats.triangles_acute
            << " acute, " << out.stats.seed_cords << " seed cords, " << out.stats.sets_tried
            << " sets tried, " << out.stats.sets_valid << " valid; local improvement "
            << out.stats.improvement_valid << '/' << out.stats.improvement_tried << " valid\n";
  if (out.regions.empty()) {
    std::cout << "no grasp region found";
    if (out.stats.sets_tried > 0 && out.params.side_cord_policy == SideCordPolicy::kDiscardSet)
      std::cout << " (eligible seeds existed but their outer scanned cords failed: the object "
                   "may be narrower than the palm; try --side-cords empty)";
    std::cout << '\n';
  } else {
    std::cout << "rank  chi[mm^2]  case   n  xi[mm]  P1 [m]                       "
                 "P_l [m]                      P_r [m]                      LI\n";
    const size_t shown = opt.top > 0 ? std::min<size_t>(opt.top, out.regions.size()) : out.regions.size();
    for (size_t k = 0; k < shown; ++k) {
      const GraspRegion& r = out.regions[k];
      std::cout << std::setw(4) << k + 1 << "  " << std::setw(9) << std::setprecision(3)
                << r.chi_m2 * 1e6 << "  " << std::setw(4)
                << (r.cord_case == CordCase::kI ? "I" : "II") << "  " << std::setw(2) << r.n << "  "
                << std::setw(6) << std::setprecision(2) << r.xi_m * 1e3 << "  " << std::left
                << std::setw(29) << point_text(r.p1) << std::setw(29) << point_text(r.p_l)
                << std::setw(29) << point_text(r.p_r) << std::right
                << (r.from_local_improvement ? "yes" : "") << '\n';
    }
    if (shown < out.regions.size())
      std::cout << "... " << out.regions.size() - shown << " more (--top 0 prints all)\n";
  }

}

}  // namespace

void add_explore_command(CLI::App& app) {
  auto opt = std::make_shared<ExploreJobParams>();
  CLI::App* cmd = app.add_subcommand(
      "explore", "Cord exploration: ranked grasp regions (front-cord sets by ascending chi)");
  cmd->add_option("--object,-o", opt->object, "Object mesh file (OBJ, STL, PLY, OFF, DAE, glTF) or shipped object name")
      ->required();
  CLI::Option* hand =
      cmd->add_option("--hand", opt->hand,
                      std::string("Hand (shipped name or description path) whose palm width is "
                                  "used; default: ") +
                          default_hand_name());
  add_package_path_option(cmd, opt->hand_load);
  cmd->add_option("--palm-width-m", opt->palm_width_m, "Palm width W_palm instead of a hand [m]")
      ->check(number_in(1e-4, 10.0))
      ->excludes(hand);
  CordParams* cord = &opt->cord;
  cmd->add_option("--sets", cord->sets, "Valid sets to sample before local improvement (K)")
      ->check(whole_number_in(1, 100000))
      ->capture_default_str();
  cmd->add_option("--seed", cord->seed, "Seed of the random generator")
      ->check(seed_value())
      ->capture_default_str();
  cmd->add_flag_callback(
      "--no-local-improvement", [cord]() { cord->local_improvement = false; },
      "Skip the local-improvement pass");
  add_enum_option(cmd, "--side-cords", &cord->side_cord_policy,
                  "When a scanned cord fails: empty (a cord that misses the object counts as an "
                  "empty polygon in chi; other failures discard the set), discard (paper: discard "
                  "the set), shrink (shrink n to the cords that succeed; docs/algorithm.md)");
  add_enum_option(cmd, "--xor", &cord->xor_backend,
                  "chi backend: clipper (Clipper 6.4.2 integer XOR, Eq. (1)) or convex (exact "
                  "convex clipping, same value, faster)");
  cmd->add_option("--time-limit", cord->time_limit_s,
                  "Wall-clock cap [s]; 0 = none. Hitting it makes results time-dependent")
      ->check(number_in(0.0, 1e6))
      ->capture_default_str();
  add_enum_option(cmd, "--units", &opt->units, "Units of the object file: m, mm or auto");
  add_scale_option(cmd, &opt->scale);
  cmd->add_option("--top", opt->top, "Regions to print (0 = all)")
      ->check(whole_number_in(0, 1000000))
      ->capture_default_str();
  cmd->add_option("--json", opt->json_path, "Also write all regions and stats to this JSON file");
  cmd->callback([opt]() {
    opt->object = resolve_object_path(opt->object);
    const ExploreOutcome out = explore_job(*opt);
    print_regions(out, *opt);
    if (!opt->json_path.empty()) std::cout << "wrote    " << opt->json_path << '\n';
  });
}

}  // namespace cordgrasp::cli
