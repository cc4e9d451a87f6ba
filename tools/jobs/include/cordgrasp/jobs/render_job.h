#pragma once
// `cordgrasp render` as a job: a PNG of a plan's grasp, grasp regions, a hand or objects.
#include <functional>
#include <string>
#include <vector>

#include "cordgrasp/core/hand_description.h"
#include "cordgrasp/jobs/render_options.h"

namespace cordgrasp {

/// What to draw and how; exactly one of plan, regions, hand or objects.
struct RenderJobParams {
  PictureOptions picture;
  std::vector<std::string> objects;
  std::string hand;
  HandLoadOptions hand_load;  ///< package:// directories of the hand's URDF
  double close = 0.0;
  std::vector<std::string> joints;  // NAME=VALUE
  bool collision = false;
  bool no_visual = false;
  std::string plan;    // plan.json
  int grasp = 0;       // 0-based, as `cordgrasp plan` prints them
  bool cones = false;  // friction cones instead of normal arrows
  bool no_cords = false;
  std::string regions;  // explore --json file
  int region = 1;       // 1-based rank
  int sheet = 0;        // > 0: the first N as a contact sheet
  std::string units = "m";
  double scale = 1.0;  ///< object scale after the units (a plan's pictures use the plan's)
  std::string out;
};

/// Receives warnings (e.g. cords that could not be replayed).
using Warn = std::function<void(const std::string&)>;

/// Draws what `p` asks for into p.out (PNG) and returns a one-line summary
/// ("render: wrote out.png (1024x768, view iso)"). @throws InputError for bad options or files.
std::string render_job(const RenderJobParams& p, const Warn& warn);

}  // namespace cordgrasp
