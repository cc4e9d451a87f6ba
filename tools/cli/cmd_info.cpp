// `cordgrasp info`: human or JSON summary of an object mesh.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "json_util.h"

namespace cordgrasp::cli {
namespace {

struct InfoOptions {
  std::string object;
  std::string units = "m";
  bool json = false;
};

nlohmann::json object_info(const std::string& path, const std::string& units) {
  MeshLoadOptions opt;
  opt.units = parse_length_units(units);
  MeshLoadReport report;
  const Mesh mesh = load_mesh(path, opt, &report);
  const Aabb box = mesh_bounds(mesh);
  const Eigen::Vector3d c = vertex_mean(mesh);
  const PrincipalAxes pa = principal_axes(mesh);
  nlohmann::json j;
  j["path"] = path;
  j["name"] = mesh.name;
  j["triangles"] = mesh.triangles.size();
  j["vertices"] = mesh.vertices.size();
  j["degenerate_dropped"] = report.degenerate_dropped;
  j["scale_to_m"] = report.scale_to_m;
  j["units_auto_chose_mm"] = report.auto_chose_mm;
  j["bounds_min_m"] = to_json(box.min);
  j["bounds_max_m"] = to_json(box.max);
  j["size_m"] = to_json(box.size());
  j["barycenter_m"] = to_json(c);
  j["bounding_radius_m"] = bounding_radius(mesh, c);
  j["surface_area_m2"] = pa.area_m2;
  j["principal_axes"] = {to_json(pa.axes.col(0)), to_json(pa.axes.col(1)),
                         to_json(pa.axes.col(2))};
  j["principal_variances_m2"] = to_json(pa.variances);
  return j;
}

void print_object(const nlohmann::json& j) {
  std::cout << std::setprecision(4);
  std::cout << "object     " << j["name"].get<std::string>() << "  (" << j["path"].get<std::string>()
            << ")\n"
            << "triangles  " << j["triangles"] << "  vertices " << j["vertices"]
            << "  degenerate dropped " << j["degenerate_dropped"] << '\n';
  if (j["units_auto_chose_mm"].get<bool>())
    std::cout << "units      auto: bounding-box diagonal > 5, read as millimeters\n";
  std::cout << "size [m]   " << vec_text(j["size_m"]) << '\n'
            << "bounds [m] " << vec_text(j["bounds_min_m"]) << " .. " << vec_text(j["bounds_max_m"])
            << '\n'
            << "C [m]      " << vec_text(j["barycenter_m"]) << "   r " << j["bounding_radius_m"].get<double>()
            << " m\n"
            << "area       " << j["surface_area_m2"].get<double>() << " m^2\n"
            << "axis 1     " << vec_text(j["principal_axes"][0]) << "  (largest)\n";
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto opt = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand("info", "Summarize an object mesh or a hand model");
  cmd->add_option("--object,-o", opt->object, "Object mesh file (OBJ, STL, PLY, OFF, DAE, glTF)");
  cmd->add_option("--units", opt->units, "Units of the object file: m, mm or auto")
      ->check(CLI::IsMember({"m", "mm", "auto"}))
      ->capture_default_str();
  cmd->add_flag("--json", opt->json, "Print machine-readable JSON instead of text");
  cmd->callback([opt]() {
    if (opt->object.empty()) throw CLI::RequiredError("--object or --hand");
    const nlohmann::json j = object_info(opt->object, opt->units);
    if (opt->json)
      std::cout << j.dump(2) << '\n';
    else
      print_object(j);
  });
}

}  // namespace cordgrasp::cli
