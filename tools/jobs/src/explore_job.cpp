#include "cordgrasp/jobs/explore_job.h"

#include <nlohmann/json.hpp>

#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/palm_width.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/region_json.h"
#include "cordgrasp/jobs/render_options.h"

namespace cordgrasp {

ExploreOutcome explore_job(const ExploreJobParams& opt) {
  ExploreOutcome out;
  if (!opt.json_path.empty()) check_output_file(opt.json_path);  // before exploring
  const MeshLoadOptions load = job_mesh_load_options(opt.units, opt.scale);
  const Mesh mesh = load_mesh(opt.object, load);
  out.object_name = mesh.name;
  out.triangles = static_cast<int>(mesh.triangles.size());
  std::string hand_text = "--palm-width-m";
  double palm_width_m = opt.palm_width_m;
  if (palm_width_m <= 0.0) {
    const std::string hand_name = opt.hand.empty() ? default_hand_name() : opt.hand;
    const HandModel hand = load_hand(hand_name, opt.hand_load);
    palm_width_m = palm_width(hand);
    hand_text = "hand " + hand_name;
  }
  const CordParams& params = opt.cord;
  ExplorationStats& stats = out.stats;
  out.regions = explore_cords(mesh, palm_width_m, params, &stats);
  const std::vector<GraspRegion>& regions = out.regions;
  out.palm_width_m = palm_width_m;
  out.palm_width_from = hand_text;
  out.params = params;

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
    for (size_t k = 0; k < regions.size(); ++k) {
      nlohmann::json r = region_to_json(regions[k]);
      r["rank"] = static_cast<int>(k) + 1;
      list.push_back(r);
    }
    j["regions"] = list;
    write_file_atomically(opt.json_path, j.dump(2) + "\n");
  }
  return out;
}


}  // namespace cordgrasp
