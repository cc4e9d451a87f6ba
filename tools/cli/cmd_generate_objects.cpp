// `cordgrasp generate-objects`: writes the shipped test objects (assets/objects) as OBJ.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "options.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/object_meshes.h"

namespace cordgrasp::cli {
namespace {

struct GenerateObjectsOptions {
  std::string out_dir;
  std::vector<std::string> only;
};

void run_generate_objects(const GenerateObjectsOptions& opt) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(opt.out_dir, ec);
  if (ec || !fs::is_directory(opt.out_dir))
    throw InputError("generate-objects: cannot create output directory '" + opt.out_dir + "'");
  const std::vector<std::string>& names = opt.only.empty() ? shipped_object_names() : opt.only;
  for (const std::string& name : names) {
    const Mesh mesh = make_object_mesh(name);
    const std::string path = (fs::path(opt.out_dir) / (name + ".obj")).string();
    save_mesh_obj(mesh, path);
    const Eigen::Vector3d size = mesh_bounds(mesh).size();
    std::cout << std::left << std::setw(14) << name << std::right << std::setw(6)
              << mesh.triangles.size() << " triangles  " << std::fixed << std::setprecision(3)
              << size.x() << " x " << size.y() << " x " << size.z() << " m  -> " << path << '\n'
              << std::defaultfloat;
  }
}

}  // namespace


void add_generate_objects_command(CLI::App& app) {
  auto opt = std::make_shared<GenerateObjectsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "generate-objects", "Write the shipped test objects (box, mug, pliers...) as OBJ in meters");
  cmd->add_option("--out-dir", opt->out_dir, "Directory to write <name>.obj into")->required();
  cmd->add_option("--only", opt->only, "Only these objects (default: all)")
      ->check(one_of(shipped_object_names()));
  cmd->callback([opt]() { run_generate_objects(*opt); });
}

}  // namespace cordgrasp::cli
