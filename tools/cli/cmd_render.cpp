// `cordgrasp render`: offscreen pictures (OSMesa) of objects, hands and plans, as PNG.
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/render/contact_sheet.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/render/renderer.h"
#include "hand_scene.h"
#include "region_json.h"
#include "render_options.h"

namespace cordgrasp::cli {
namespace {

struct RenderCommandOptions {
  PictureOptions picture;
  std::vector<std::string> objects;
  std::string hand;
  double close = 0.0;
  std::vector<std::string> joints;  // NAME=VALUE
  bool collision = false;
  bool no_visual = false;
  std::string regions;  // explore --json file
  int region = 1;       // 1-based rank
  int sheet = 0;        // > 0: the first N as a contact sheet
  std::string units = "m";
  std::string out;
};

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

// Regions of `cordgrasp explore --json`: the object with one region's front cords and P1, P_l,
// P_r, or with --sheet N the N best regions as a contact sheet.
void run_render_regions(const RenderCommandOptions& opt) {
  std::ifstream in(opt.regions);
  if (!in) throw InputError("render: '" + opt.regions + "': cannot open");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw InputError("render: '" + opt.regions + "': not JSON: " + e.what());
  }
  if (!j.is_object() || !j.contains("regions") || !j["regions"].is_array())
    throw InputError("render: '" + opt.regions +
                     "': no \"regions\" list (write it with "
                     "cordgrasp explore --json)");
  std::vector<GraspRegion> regions;
  for (const auto& r : j["regions"]) {
    try {
      regions.push_back(region_from_json(r));
    } catch (const InputError& e) {
      throw InputError("render: '" + opt.regions + "': " + e.what());
    }
  }
  if (regions.empty()) throw InputError("render: '" + opt.regions + "': no regions to show");
  const std::string object_path =
      !opt.objects.empty() ? opt.objects[0] : j.value("object", std::string());
  if (object_path.empty())
    throw InputError("render: '" + opt.regions + "': no object; give --object");
  MeshLoadOptions load;
  load.units = parse_length_units(opt.units);
  const auto object = std::make_shared<const Mesh>(load_mesh(object_path, load));
  const double radius = bounding_radius(*object, vertex_mean(*object));

  const int count = static_cast<int>(regions.size());
  const int first = opt.sheet > 0 ? 1 : opt.region;
  const int last = opt.sheet > 0 ? std::min(count, opt.sheet) : opt.region;
  if (first < 1 || first > count)
    throw InputError("render: --region " + std::to_string(opt.region) + ": '" + opt.regions +
                     "' has regions 1.." + std::to_string(count));
  PictureOptions picture = opt.picture;
  if (!picture.view_given()) picture.view = "approach";  // shows the cords best
  OverlayStyle style;
  style.p1 = picture.view != "approach";  // P1 would sit in front of the camera
  Renderer renderer;
  std::vector<Image> tiles;
  std::vector<std::string> captions;
  RenderParams params;
  for (int k = first; k <= last; ++k) {
    const GraspRegion& r = regions[k - 1];
    Scene scene;
    add_object(scene, object);
    add_region_overlay(scene, r, Eigen::Isometry3d::Identity(), radius, style);
    const std::string chi = "χ = " + fixed(r.chi_m2 * 1e6, 1) + " mm²";
    const std::string kind = std::string("case ") + (r.cord_case == CordCase::kI ? "I" : "II") +
                             " · n = " + std::to_string(r.n);
    const std::string what = "region " + std::to_string(k) + "/" + std::to_string(count) + " · " +
                             chi + " · " + kind + " · ξ = " + fixed(r.xi_m * 1e3, 1) + " mm";
    const std::string tile = "#" + std::to_string(k) + " · " + chi + " · " + kind;
    scene.caption = opt.sheet > 0 ? "" : object->name + " · " + what;
    params = render_params(picture, scene, r.p_m - r.p1);  // approach: P1 → P_m (§7.2)
    if (opt.sheet > 0) {
      captions.push_back(opt.picture.no_caption ? "" : tile);
      scene.caption.clear();
    }
    tiles.push_back(renderer.render(scene, params));
  }
  ContactSheetParams sheet;
  if (!opt.picture.no_caption)
    sheet.title = object->name + " · cord exploration · " + std::to_string(count) +
                  " regions, best " + std::to_string(tiles.size()) + " by χ";
  const Image image = opt.sheet > 0 ? compose_contact_sheet(tiles, captions, sheet) : tiles[0];
  write_png(opt.out, image);
  std::cout << "render: wrote " << opt.out << " (" << image.width << "x" << image.height
            << ", view " << view_name(params.view.view) << ")\n";
}

// Objects: one picture, or with several --object a contact sheet of one tile (--size) each.
void run_render_objects(const RenderCommandOptions& opt) {
  MeshLoadOptions load;
  load.units = parse_length_units(opt.units);
  Renderer renderer;
  std::vector<Image> tiles;
  std::vector<std::string> captions;
  RenderParams params;
  for (const std::string& path : opt.objects) {
    auto object = std::make_shared<const Mesh>(load_mesh(path, load));
    Scene scene;
    add_object(scene, object);
    const std::string caption =
        object->name + " · " + std::to_string(object->triangles.size()) + " triangles";
    scene.caption = opt.objects.size() == 1 ? caption : "";
    params = render_params(opt.picture, scene);
    if (opt.objects.size() > 1) {
      captions.push_back(scene.caption.empty() && !opt.picture.no_caption ? caption : "");
      scene.caption.clear();
    }
    tiles.push_back(renderer.render(scene, params));
  }
  const Image image = tiles.size() == 1 ? tiles[0] : compose_contact_sheet(tiles, captions);
  write_png(opt.out, image);
  std::cout << "render: wrote " << opt.out << " (" << image.width << "x" << image.height
            << ", view " << view_name(params.view.view) << ")\n";
}

// A hand alone at a configuration: preshape, partly closed (--close) and/or --joint values.
void run_render_hand(const RenderCommandOptions& opt) {
  const HandModel hand = load_hand(opt.hand);
  Eigen::VectorXd q = closing_configuration(hand, opt.close);
  for (const std::string& text : opt.joints) {
    const size_t eq = text.find('=');
    const std::string name = text.substr(0, eq);
    const int j = find_joint(hand, name);
    double value = 0.0;
    try {
      if (eq == std::string::npos) throw std::invalid_argument("no '='");
      size_t used = 0;
      value = std::stod(text.substr(eq + 1), &used);
      if (used != text.size() - eq - 1) throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
      throw InputError("--joint '" + text + "': expected NAME=VALUE (rad or m)");
    }
    if (j < 0)
      throw InputError("--joint '" + text + "': hand '" + hand.name + "' has no joint '" + name +
                       "'");
    q[j] = value;
  }
  q = clamp_to_limits(hand, apply_couplings(hand, q));
  HandStyle style;
  style.collision = opt.collision;
  style.visual = !opt.no_visual;
  if (!style.visual && !style.collision)
    throw InputError("render: --no-visual needs --collision (nothing would be drawn)");
  const auto X_WL = link_poses(hand, q);
  Scene scene;
  add_hand(scene, make_hand_meshes(hand, style), X_WL);
  std::ostringstream caption;
  caption << hand.name << " · " << degrees_of_freedom(hand) << " DOF · "
          << (opt.close > 0.0 ? "closed " + std::to_string(int(std::lround(100 * opt.close))) + " %"
                              : std::string("preshape"))
          << (opt.joints.empty() ? "" : " + --joint") << (style.collision ? " · collision" : "");
  scene.caption = caption.str();
  const Eigen::Vector3d approach_W = gcp_pose(hand, X_WL).linear().col(2);
  const RenderParams params = render_params(opt.picture, scene, approach_W);
  Renderer renderer;
  write_png(opt.out, renderer.render(scene, params));
  std::cout << "render: wrote " << opt.out << " (" << params.width_px << "x" << params.height_px
            << ", view " << view_name(params.view.view) << ")\n";
}

void run_render(const RenderCommandOptions& opt) {
  const int modes =
      !opt.regions.empty() + !opt.hand.empty() + (opt.regions.empty() && !opt.objects.empty());
  if (modes != 1)
    throw InputError("render: give one of --object FILE..., --hand HAND or --regions FILE");
  if (opt.regions.empty() && opt.sheet > 0)
    throw InputError("render: --sheet needs --regions (or, later, --plan)");
  if (opt.regions.empty() && opt.region != 1) throw InputError("render: --region needs --regions");
  if (!opt.regions.empty() && opt.objects.size() > 1)
    throw InputError("render: --regions takes at most one --object");
  check_output_file(opt.out);
  if (!opt.regions.empty())
    run_render_regions(opt);
  else if (!opt.hand.empty())
    run_render_hand(opt);
  else
    run_render_objects(opt);
}

}  // namespace

void add_render_command(CLI::App& app);
CORDGRASP_REGISTER_COMMAND(60, add_render_command);

void add_render_command(CLI::App& app) {
  auto opt = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd =
      app.add_subcommand("render", "Render objects, hands or grasp regions to PNG offscreen");
  cmd->add_option("--object,-o", opt->objects,
                  "Object mesh file to show; several: a contact sheet, --size per tile");
  cmd->add_option(
      "--hand", opt->hand,
      "Hand description (YAML) or shipped hand name: the hand alone, root at the origin");
  cmd->add_option("--close", opt->close,
                  "With --hand: close every actor joint this fraction of the way to its limit")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--joint", opt->joints, "With --hand: set a joint, NAME=VALUE (rad or m)");
  cmd->add_flag("--collision", opt->collision, "Also show collision shapes (translucent)");
  cmd->add_flag("--no-visual", opt->no_visual, "With --collision: collision shapes only");
  cmd->add_option("--regions", opt->regions,
                  "Grasp regions from `cordgrasp explore --json`: the object with a region's "
                  "front cords and P1 (dark), P_l (magenta), P_r (teal)");
  cmd->add_option("--region", opt->region, "With --regions: which region, by rank (1 = best)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--sheet", opt->sheet,
                  "With --regions: the N best as a contact sheet, --size per tile")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--units", opt->units, "Units of the object file: m, mm or auto")
      ->check(CLI::IsMember({"m", "mm", "auto"}))
      ->capture_default_str();
  add_picture_options(*cmd, opt->picture);
  cmd->add_option("--out", opt->out, "Output PNG file")->required();
  cmd->callback([opt]() { run_render(*opt); });
}

}  // namespace cordgrasp::cli
