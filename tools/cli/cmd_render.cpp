// `cordgrasp render`: offscreen pictures (OSMesa) of objects, hands and plans, as PNG.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "cordgrasp/core/error.h"
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

void run_render(const RenderCommandOptions& opt) {
  if (opt.objects.empty()) throw InputError("render: give --object");
  check_output_file(opt.out);
  run_render_objects(opt);
}

}  // namespace

void add_render_command(CLI::App& app);
CORDGRASP_REGISTER_COMMAND(60, add_render_command);

void add_render_command(CLI::App& app) {
  auto opt = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd =
      app.add_subcommand("render", "Render an object (later: a hand or a plan) to PNG offscreen");
  cmd->add_option("--object,-o", opt->objects,
                  "Object mesh file to show; several: a contact sheet, --size per tile");
  cmd->add_option("--units", opt->units, "Units of the object file: m, mm or auto")
      ->check(CLI::IsMember({"m", "mm", "auto"}))
      ->capture_default_str();
  add_picture_options(*cmd, opt->picture);
  cmd->add_option("--out", opt->out, "Output PNG file")->required();
  cmd->callback([opt]() { run_render(*opt); });
}

}  // namespace cordgrasp::cli
