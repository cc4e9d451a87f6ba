// Object part of `cordgrasp info`.
#include <iomanip>
#include <iostream>

#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "info.h"
#include "json_util.h"

namespace cordgrasp::cli {

nlohmann::json object_info_json(const std::string& path, const std::string& units) {
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

void print_object_info(const nlohmann::json& j) {
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

}  // namespace cordgrasp::cli
