// Object part of `cordgrasp info`.
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cordgrasp/core/convex_hull_volume.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/core/mesh_topology.h"
#include "cordgrasp/core/mesh_volume.h"
#include "cordgrasp/jobs/info.h"
#include "cordgrasp/jobs/plan_job.h"
#include "json_util.h"

namespace cordgrasp {

nlohmann::json object_info_json(const std::string& path, const std::string& units,
                                double scale) {
  const MeshLoadOptions opt = job_mesh_load_options(parse_length_units(units), scale);
  MeshLoadReport report;
  const Mesh mesh = load_mesh(path, opt, &report);
  const Aabb box = mesh_bounds(mesh);
  const Eigen::Vector3d c = vertex_mean(mesh);
  const PrincipalAxes pa = principal_axes(mesh);
  const MeshTopology topo = mesh_topology(mesh);
  const std::optional<SolidVolume> solid = closed_mesh_volume(mesh);
  const SolidVolume hull = convex_hull_volume(mesh);
  nlohmann::json j;
  j["path"] = path;
  j["name"] = mesh.name;
  j["triangles"] = mesh.triangles.size();
  j["vertices"] = mesh.vertices.size();
  j["degenerate_dropped"] = report.degenerate_dropped;
  j["units"] = units;
  j["scale"] = scale;
  j["scale_to_m"] = report.scale_to_m;
  j["units_auto_chose_mm"] = report.auto_chose_mm;
  j["bounds_min_m"] = to_json(box.min);
  j["bounds_max_m"] = to_json(box.max);
  j["size_m"] = to_json(box.size());
  j["barycenter_m"] = to_json(c);
  j["bounding_radius_m"] = bounding_radius(mesh, c);
  j["surface_area_m2"] = pa.area_m2;
  j["principal_axes"] = nlohmann::json::array();
  for (int k = 0; k < 3; ++k) j["principal_axes"].push_back(to_json(pa.axes.col(k)));
  j["principal_variances_m2"] = to_json(pa.variances);
  j["topology"] = {{"vertices", topo.vertices},
                   {"edges", topo.edges},
                   {"boundary_edges", topo.boundary_edges},
                   {"non_manifold_edges", topo.non_manifold_edges},
                   {"misoriented_edges", topo.misoriented_edges},
                   {"components", topo.components},
                   {"euler_characteristic", topo.euler_characteristic},
                   {"closed", topo.closed}};
  j["volume_m3"] = solid ? nlohmann::json(solid->volume_m3) : nlohmann::json(nullptr);
  j["center_of_mass_m"] = solid ? to_json(solid->center_of_mass_m) : nlohmann::json(nullptr);
  j["convex_hull_volume_m3"] = hull.volume_m3;
  j["convex_hull_centroid_m"] = to_json(hull.center_of_mass_m);
  return j;
}

namespace {

std::string plural(int n, const std::string& word) {
  return std::to_string(n) + ' ' + word + (n == 1 ? "" : "s");
}

std::string topology_text(const nlohmann::json& t) {
  std::ostringstream out;
  if (t["closed"].get<bool>()) {
    out << "closed (watertight)";
  } else {
    out << "open: " << plural(t["boundary_edges"].get<int>(), "boundary edge") << ", "
        << plural(t["non_manifold_edges"].get<int>(), "non-manifold edge");
  }
  out << ", " << plural(t["components"].get<int>(), "component") << ", Euler characteristic "
      << t["euler_characteristic"].get<int>();
  if (t["misoriented_edges"].get<int>() > 0)
    out << ", " << plural(t["misoriented_edges"].get<int>(), "edge")
        << " between oppositely wound faces";
  return out.str();
}

}  // namespace

void print_object_info(const nlohmann::json& j) {
  std::cout << std::setprecision(4);
  std::cout << "object     " << j["name"].get<std::string>() << "  ("
            << j["path"].get<std::string>() << ")\n"
            << "triangles  " << j["triangles"] << "  vertices " << j["vertices"]
            << "  degenerate dropped " << j["degenerate_dropped"] << '\n';
  if (j["units_auto_chose_mm"].get<bool>())
    std::cout << "units      auto: bounding-box diagonal > 5, read as millimeters (x 0.001)\n";
  else if (j["scale_to_m"].get<double>() != 1.0)
    std::cout << "units      " << j["units"].get<std::string>() << ", scale "
              << j["scale"].get<double>() << " (x " << j["scale_to_m"].get<double>() << ")\n";
  const std::string bounds = vec_text(j["bounds_min_m"]) + " .. " + vec_text(j["bounds_max_m"]);
  std::cout << "size [m]   " << vec_text(j["size_m"]) << '\n'
            << "bounds [m] " << bounds << '\n'
            << "C [m]      " << vec_text(j["barycenter_m"]) << "   r "
            << j["bounding_radius_m"].get<double>() << " m\n"
            << "area       " << j["surface_area_m2"].get<double>() << " m^2\n"
            << "axis 1     " << vec_text(j["principal_axes"][0]) << "  (largest)\n"
            << "topology   " << topology_text(j["topology"]) << '\n';
  if (j["volume_m3"].is_null())
    std::cout << "volume     open (no enclosed volume)\n";
  else
    std::cout << "volume     " << j["volume_m3"].get<double>() << " m^3   centre of mass "
              << vec_text(j["center_of_mass_m"]) << " m\n";
  std::cout << "hull       convex-hull volume " << j["convex_hull_volume_m3"].get<double>()
            << " m^3   centroid " << vec_text(j["convex_hull_centroid_m"]) << " m\n";
}

}  // namespace cordgrasp
