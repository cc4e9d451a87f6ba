// `cordgrasp render`: offscreen pictures (OSMesa) of objects, hands and plans, as PNG.
#include <cmath>
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
#include "cordgrasp/render/contact_sheet.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/render/renderer.h"
#include "hand_scene.h"
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
  std::string units = "m";
  std::string out;
};

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
  if (opt.objects.empty() == opt.hand.empty())
    throw InputError("render: give --object FILE... or --hand HAND");
  check_output_file(opt.out);
  if (!opt.hand.empty())
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
      app.add_subcommand("render", "Render objects or a hand (later: a plan) to PNG offscreen");
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
  cmd->add_option("--units", opt->units, "Units of the object file: m, mm or auto")
      ->check(CLI::IsMember({"m", "mm", "auto"}))
      ->capture_default_str();
  add_picture_options(*cmd, opt->picture);
  cmd->add_option("--out", opt->out, "Output PNG file")->required();
  cmd->callback([opt]() { run_render(*opt); });
}

}  // namespace cordgrasp::cli
