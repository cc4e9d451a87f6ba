// `cordgrasp explore`: the cord exploration stage (spec §2–§6) on one object, for a hand's
// palm width (--hand, default the shipped default hand) or an explicit --palm-width-m.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.h"
#include "options.h"
#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/explore_cords.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/palm_width.h"

namespace cordgrasp::cli {
namespace {

nlohmann::json to_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

struct ExploreOptions {
  std::string object;
  LengthUnits units = LengthUnits::kMeters;
  std::string hand;  // empty: the shipped default hand (unless --palm-width-m)
  double palm_width_m = 0.0;
  CordParams cord;  // options bind to its fields: --help shows its defaults
  int top = 20;
  std::string json_path;
};

nlohmann::json region_json(const GraspRegion& r, int rank) {
  nlohmann::json j;
  j["rank"] = rank;
  j["chi_m2"] = r.chi_m2;
  j["case"] = r.cord_case == CordCase::kI ? "I" : "II";
  j["n"] = r.n;
  j["xi_m"] = r.xi_m;
  j["from_local_improvement"] = r.from_local_improvement;
  j["p1"] = to_json(r.p1);
  j["p2"] = to_json(r.p2);
  j["p3"] = to_json(r.p3);
  j["normal"] = to_json(r.normal);
  j["p_l"] = to_json(r.p_l);
  j["p_r"] = to_json(r.p_r);
  j["p_m"] = to_json(r.p_m);
  nlohmann::json cords = nlohmann::json::array();
  for (const Polyline3& c : r.front_cords) {
    nlohmann::json poly = nlohmann::json::array();
    for (const Eigen::Vector3d& p : c) poly.push_back(to_json(p));
    cords.push_back(poly);
  }
  j["front_cords"] = cords;
  return j;
}

std::string point_text(const Eigen::Vector3d& p) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(4) << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return s.str();
}

void run_explore(const ExploreOptions& opt) {
  MeshLoadOptions load;
  load.units = opt.units;
  const Mesh mesh = load_mesh(opt.object, load);
  std::string hand_text = "--palm-width-m";
  double palm_width_m = opt.palm_width_m;
  if (palm_width_m <= 0.0) {
    const std::string hand_name = opt.hand.empty() ? default_hand_name() : opt.hand;
    const HandModel hand = load_hand(hand_name);
    palm_width_m = palm_width(hand);
    hand_text = "hand " + hand_name;
  }
  const CordParams& params = opt.cord;
  ExplorationStats stats;
  const std::vector<GraspRegion> regions = explore_cords(mesh, palm_width_m, params, &stats);

  std::cout << "object   " << mesh.name << "  (" << mesh.triangles.size() << " triangles)  "
            << "W_palm " << palm_width_m << " m (" << hand_text << ")  seed " << params.seed
            << '\n'
            << "explored " << std::fixed << std::setprecision(4) << stats.time_s << " s  ("
            << "sampling " << stats.sampling_time_s << " s, local improvement "
            << stats.improvement_time_s << " s)" << (stats.hit_time_limit ? "  TIME LIMIT" : "")
            << '\n'
            << "sampled  " << stats.triangles_sampled << " triangles, " << stats.triangles_acute
            << " acute, " << stats.seed_cords << " seed cords, " << stats.sets_tried
            << " sets tried, " << stats.sets_valid << " valid; local improvement "
            << stats.improvement_valid << '/' << stats.improvement_tried << " valid\n";
  if (regions.empty()) {
    std::cout << "no grasp region found";
    if (stats.sets_tried > 0 && params.side_cord_policy == SideCordPolicy::kDiscardSet)
      std::cout << " (eligible seeds existed but their outer scanned cords failed: the object "
                   "may be narrower than the palm; try --side-cords empty)";
    std::cout << '\n';
  } else {
    std::cout << "rank  chi[mm^2]  case   n  xi[mm]  P1 [m]                       "
                 "P_l [m]                      P_r [m]                      LI\n";
    const size_t shown = opt.top > 0 ? std::min<size_t>(opt.top, regions.size()) : regions.size();
    for (size_t k = 0; k < shown; ++k) {
      const GraspRegion& r = regions[k];
      std::cout << std::setw(4) << k + 1 << "  " << std::setw(9) << std::setprecision(3)
                << r.chi_m2 * 1e6 << "  " << std::setw(4)
                << (r.cord_case == CordCase::kI ? "I" : "II") << "  " << std::setw(2) << r.n << "  "
                << std::setw(6) << std::setprecision(2) << r.xi_m * 1e3 << "  " << std::left
                << std::setw(29) << point_text(r.p1) << std::setw(29) << point_text(r.p_l)
                << std::setw(29) << point_text(r.p_r) << std::right
                << (r.from_local_improvement ? "yes" : "") << '\n';
    }
    if (shown < regions.size())
      std::cout << "... " << regions.size() - shown << " more (--top 0 prints all)\n";
  }

  if (!opt.json_path.empty()) {
    nlohmann::json j;
    j["object"] = opt.object;
    j["name"] = mesh.name;
    j["triangles"] = mesh.triangles.size();
    j["palm_width_m"] = palm_width_m;
    j["palm_width_from"] = hand_text;
    j["seed"] = params.seed;
    j["sets"] = params.sets;
    j["local_improvement"] = params.local_improvement;
    j["time_limit_s"] = params.time_limit_s;
    j["side_cords"] = to_string(params.side_cord_policy);
    j["xor_backend"] = to_string(params.xor_backend);
    j["stats"] = {{"triangles_sampled", stats.triangles_sampled},
                  {"triangles_acute", stats.triangles_acute},
                  {"seed_cords", stats.seed_cords},
                  {"sets_tried", stats.sets_tried},
                  {"sets_valid", stats.sets_valid},
                  {"improvement_tried", stats.improvement_tried},
                  {"improvement_valid", stats.improvement_valid},
                  {"iterations", stats.iterations},
                  {"sampling_time_s", stats.sampling_time_s},
                  {"improvement_time_s", stats.improvement_time_s},
                  {"time_s", stats.time_s},
                  {"hit_time_limit", stats.hit_time_limit}};
    nlohmann::json list = nlohmann::json::array();
    for (size_t k = 0; k < regions.size(); ++k) list.push_back(region_json(regions[k], int(k) + 1));
    j["regions"] = list;
    write_file_atomically(opt.json_path, j.dump(2) + "\n");
    std::cout << "wrote    " << opt.json_path << '\n';
  }
}

}  // namespace


void add_explore_command(CLI::App& app) {
  auto opt = std::make_shared<ExploreOptions>();
  CLI::App* cmd = app.add_subcommand(
      "explore", "Cord exploration: ranked grasp regions (front-cord sets by ascending chi)");
  cmd->add_option("--object,-o", opt->object, "Object mesh file (OBJ, STL, PLY, OFF, DAE, glTF)")
      ->required();
  CLI::Option* hand =
      cmd->add_option("--hand", opt->hand,
                      std::string("Hand (shipped name or description path) whose palm width is "
                                  "used; default: ") +
                          default_hand_name());
  cmd->add_option("--palm-width-m", opt->palm_width_m, "Palm width W_palm instead of a hand [m]")
      ->check(CLI::PositiveNumber)
      ->excludes(hand);
  CordParams* cord = &opt->cord;
  cmd->add_option("--sets", cord->sets, "Valid sets to sample before local improvement (K)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--seed", cord->seed, "Seed of the random generator")->capture_default_str();
  cmd->add_flag_callback(
      "--no-local-improvement", [cord]() { cord->local_improvement = false; },
      "Skip the local-improvement pass");
  add_enum_option(cmd, "--side-cords", &cord->side_cord_policy,
                  "When a scanned cord fails: empty (a cord that misses the object counts as an "
                  "empty polygon in chi; other failures discard the set), discard (spec 4.5: "
                  "discard the set), shrink (spec 11.6: shrink n to the cords that succeed)");
  add_enum_option(cmd, "--xor", &cord->xor_backend,
                  "chi backend: clipper (Clipper 6.4.2 integer XOR, spec 6) or convex (exact "
                  "convex clipping, same value, faster)");
  cmd->add_option("--time-limit", cord->time_limit_s,
                  "Wall-clock cap [s]; 0 = none. Hitting it makes results time-dependent")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  add_enum_option(cmd, "--units", &opt->units, "Units of the object file: m, mm or auto");
  cmd->add_option("--top", opt->top, "Regions to print (0 = all)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--json", opt->json_path, "Also write all regions and stats to this JSON file");
  cmd->callback([opt]() { run_explore(*opt); });
}

}  // namespace cordgrasp::cli
