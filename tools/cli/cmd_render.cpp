// `cordgrasp render`: offscreen pictures (OSMesa) of objects, hands and plans, as PNG.
#include <iostream>
#include <memory>
#include <string>

#include "commands.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/render/renderer.h"
#include "hand_scene.h"
#include "render_options.h"

namespace cordgrasp::cli {
namespace {

struct RenderCommandOptions {
  PictureOptions picture;
  std::string object;
  std::string units = "m";
  std::string out;
};

void run_render(const RenderCommandOptions& opt) {
  if (opt.object.empty()) throw InputError("render: give --object");
  check_output_file(opt.out);
  MeshLoadOptions load;
  load.units = parse_length_units(opt.units);
  auto object = std::make_shared<const Mesh>(load_mesh(opt.object, load));
  Scene scene;
  add_object(scene, object);
  scene.caption = object->name + " · " + std::to_string(object->triangles.size()) + " triangles";
  RenderParams params = render_params(opt.picture, scene);
  Renderer renderer;
  write_png(opt.out, renderer.render(scene, params));
  std::cout << "render: wrote " << opt.out << " (" << params.width_px << "x" << params.height_px
            << ", view " << view_name(params.view.view) << ")\n";
}

}  // namespace

void add_render_command(CLI::App& app);
CORDGRASP_REGISTER_COMMAND(60, add_render_command);

void add_render_command(CLI::App& app) {
  auto opt = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd =
      app.add_subcommand("render", "Render an object (later: a hand or a plan) to PNG offscreen");
  cmd->add_option("--object,-o", opt->object, "Object mesh file to show");
  cmd->add_option("--units", opt->units, "Units of the object file: m, mm or auto")
      ->check(CLI::IsMember({"m", "mm", "auto"}))
      ->capture_default_str();
  add_picture_options(*cmd, opt->picture);
  cmd->add_option("--out", opt->out, "Output PNG file")->required();
  cmd->callback([opt]() { run_render(*opt); });
}

}  // namespace cordgrasp::cli
