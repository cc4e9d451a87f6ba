// The Python module cordgrasp._cordgrasp: meshes, hands, planning, physics validation, pictures
// and plan.json, over the jobs library. Each section below binds one job; a new job is one
// more bind_<job>() function called from PYBIND11_MODULE. Every long C++ call runs with the
// GIL released; C++ exceptions become Python ones with the same message (InputError →
// cordgrasp.InputError, std::invalid_argument → ValueError, others → RuntimeError).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/version.h"
#include "cordgrasp/jobs/hand_scene.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/jobs/physics_settings.h"
#include "cordgrasp/jobs/render_options.h"
#include "cordgrasp/jobs/sim_json.h"
#include "cordgrasp/jobs/validate_plan.h"
#include "cordgrasp/jobs/validated_plan_job.h"
#include "cordgrasp/render/png_io.h"
#include "cordgrasp/render/renderer.h"
#include "kwargs_params.h"

namespace py = pybind11;

namespace cordgrasp::python {
namespace {

// ---- value types held by the Python objects ---------------------------------------------

struct PyMesh {
  std::shared_ptr<const Mesh> mesh;
  std::string path;  ///< file it came from; empty for arrays
};

struct PyHand {
  std::shared_ptr<const HandModel> hand;
};

struct PyPlan {
  PlanDocument doc;
  std::shared_ptr<const HandModel> hand;
  std::shared_ptr<const Mesh> mesh;  ///< may be null for a plan read from a file
  double job_wall_s = 0.0;           ///< wall-clock time of plan_job [s]
};

struct PyContact {
  std::string link;
  Eigen::Vector3d point_m;  ///< object frame [m]
  Eigen::Vector3d normal;   ///< unit, out of the object
};

struct PyGrasp {
  Eigen::Matrix4d hand_pose;  ///< X_OB: hand root link in the object frame
  Eigen::Matrix4d gcp_pose;   ///< X_OG: GCP in the object frame
  Eigen::VectorXd q;
  std::map<std::string, double> joints;
  std::map<std::string, double> preshape_joints;
  std::vector<PyContact> contacts;
  bool force_closure = false;
  double epsilon = 0.0;
  double alpha_rad = 0.0;
  std::optional<int> region_rank;
  std::optional<double> chi_m2;
};

py::object json_to_py(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

std::map<std::string, double> joints_by_name(const HandModel& hand, const Eigen::VectorXd& q) {
  std::map<std::string, double> out;
  for (size_t j = 0; j < hand.joints.size() && j < static_cast<size_t>(q.size()); ++j)
    if (hand.joints[j].is_moving()) out[hand.joints[j].name] = q[j];
  return out;
}

PyGrasp to_py_grasp(const Grasp& g, const HandModel& hand) {
  PyGrasp p;
  p.hand_pose = g.X_OB.matrix();
  p.gcp_pose = g.X_OG.matrix();
  p.q = g.q;
  p.joints = joints_by_name(hand, g.q);
  p.preshape_joints = joints_by_name(hand, g.q_preshape);
  for (const Contact& c : g.contacts) {
    const std::string link =
        c.link >= 0 && c.link < static_cast<int>(hand.links.size()) ? hand.links[c.link].name : "";
    p.contacts.push_back({link, c.p_O, c.n_O});
  }
  p.force_closure = g.force_closure;
  p.epsilon = g.epsilon;
  p.alpha_rad = g.alpha_rad;
  p.region_rank = g.region_rank;
  p.chi_m2 = g.chi_m2;
  return p;
}

const Mesh& plan_mesh(PyPlan& plan) {
  if (!plan.mesh) plan.mesh = std::make_shared<const Mesh>(load_mesh(plan.doc.object_path));
  return *plan.mesh;
}

// ---- meshes, hands, plan.json ------------------------------------------------------------

void bind_io(py::module_& m) {
  py::class_<PyMesh>(m, "Mesh", "Triangle soup in meters (object frame).")
      .def(py::init([](const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& v,
                       const Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>& f,
                       const std::string& name) {
             Mesh mesh;
             mesh.name = name;
             for (Eigen::Index i = 0; i < v.rows(); ++i) mesh.vertices.push_back(v.row(i));
             for (Eigen::Index i = 0; i < f.rows(); ++i) {
               for (int k = 0; k < 3; ++k)
                 if (f(i, k) < 0 || f(i, k) >= v.rows())
                   throw std::invalid_argument("Mesh: face " + std::to_string(i) +
                                               " has a vertex index out of range");
               mesh.triangles.push_back(f.row(i));
             }
             if (mesh.triangles.empty()) throw std::invalid_argument("Mesh: no faces");
             return PyMesh{std::make_shared<const Mesh>(std::move(mesh)), ""};
           }),
           py::arg("vertices"), py::arg("faces"), py::arg("name") = "mesh",
           "From an (N, 3) float array of vertices [m] and an (M, 3) int array of faces.")
      .def_property_readonly("vertices", [](const PyMesh& p) {
        Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> v(p.mesh->vertices.size(), 3);
        for (size_t i = 0; i < p.mesh->vertices.size(); ++i) v.row(i) = p.mesh->vertices[i];
        return v;
      })
      .def_property_readonly("faces", [](const PyMesh& p) {
        Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> f(p.mesh->triangles.size(), 3);
        for (size_t i = 0; i < p.mesh->triangles.size(); ++i) f.row(i) = p.mesh->triangles[i];
        return f;
      })
      .def_property_readonly("name", [](const PyMesh& p) { return p.mesh->name; })
      .def_property_readonly("path", [](const PyMesh& p) { return p.path; })
      .def("__repr__", [](const PyMesh& p) {
        return "<cordgrasp.Mesh '" + p.mesh->name + "': " +
               std::to_string(p.mesh->triangles.size()) + " triangles>";
      });

  m.def(
      "load_mesh",
      [](const std::string& name_or_path, const std::string& units, double scale) {
        const std::string path = resolve_object_path(name_or_path);
        MeshLoadOptions options;
        options.units = parse_length_units(units);
        options.scale = scale;
        py::gil_scoped_release release;
        return PyMesh{std::make_shared<const Mesh>(load_mesh(path, options)), path};
      },
      py::arg("name_or_path"), py::arg("units") = "m", py::arg("scale") = 1.0,
      "Loads a mesh file (OBJ, STL, PLY, ...) or a shipped object by name ('mug').");

  py::class_<PyHand>(m, "Hand", "A hand: URDF kinematics and its grasping description.")
      .def_property_readonly("name", [](const PyHand& h) { return h.hand->name; })
      .def_property_readonly("path", [](const PyHand& h) { return h.hand->description_path; })
      .def_property_readonly("joint_names",
                             [](const PyHand& h) {
                               std::vector<std::string> names;
                               for (const Joint& j : h.hand->joints)
                                 if (j.is_moving()) names.push_back(j.name);
                               return names;
                             })
      .def_property_readonly("link_names",
                             [](const PyHand& h) {
                               std::vector<std::string> names;
                               for (const Link& l : h.hand->links) names.push_back(l.name);
                               return names;
                             })
      .def("__repr__", [](const PyHand& h) { return "<cordgrasp.Hand '" + h.hand->name + "'>"; });

  m.def(
      "load_hand",
      [](const std::string& name_or_path) {
        py::gil_scoped_release release;
        return PyHand{std::make_shared<const HandModel>(load_hand(name_or_path))};
      },
      py::arg("name_or_path") = std::string(default_hand_name()),
      "Loads a hand description (YAML path, hand folder, or shipped hand name).");

  m.def(
      "read_plan",
      [](const std::string& path, std::optional<PyHand> hand) {
        const nlohmann::json j = read_plan_json(path);
        PyPlan plan;
        plan.hand = hand ? hand->hand
                         : std::make_shared<const HandModel>(load_hand(plan_hand_path(j)));
        plan.doc = plan_from_json(j, *plan.hand, path);
        return plan;
      },
      py::arg("path"), py::arg("hand") = py::none(),
      "Reads plan.json (the hand it names is loaded unless given).");
}

// ---- planning ----------------------------------------------------------------------------

/// Runs one planning job with the GIL released and times it (PyPlan::job_wall_s).
template <typename Job>
PyPlan run_plan(const PyMesh& mesh, const PyHand& hand, const Job& job) {
  PyPlan plan;
  plan.hand = hand.hand;
  plan.mesh = mesh.mesh;
  const std::string path = mesh.path.empty() ? mesh.mesh->name : mesh.path;
  py::gil_scoped_release release;
  const auto start = std::chrono::steady_clock::now();
  plan.doc = job(path);
  plan.job_wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return plan;
}

void bind_plan(py::module_& m) {
  py::class_<PyContact>(m, "Contact", "A finger-object contact in the object frame.")
      .def_readonly("link", &PyContact::link)
      .def_readonly("point_m", &PyContact::point_m)
      .def_readonly("normal", &PyContact::normal)
      .def("__repr__", [](const PyContact& c) { return "<cordgrasp.Contact " + c.link + ">"; });

  py::class_<PyGrasp>(m, "Grasp", "A planned grasp; poses are 4x4 in the object frame.")
      .def_readonly("hand_pose", &PyGrasp::hand_pose)
      .def_readonly("gcp_pose", &PyGrasp::gcp_pose)
      .def_readonly("q", &PyGrasp::q)
      .def_readonly("joints", &PyGrasp::joints)
      .def_readonly("preshape_joints", &PyGrasp::preshape_joints)
      .def_readonly("contacts", &PyGrasp::contacts)
      .def_readonly("force_closure", &PyGrasp::force_closure)
      .def_readonly("epsilon", &PyGrasp::epsilon)
      .def_readonly("alpha_rad", &PyGrasp::alpha_rad)
      .def_readonly("region_rank", &PyGrasp::region_rank)
      .def_readonly("chi_m2", &PyGrasp::chi_m2)
      .def("__repr__", [](const PyGrasp& g) {
        return "<cordgrasp.Grasp epsilon " + std::to_string(g.epsilon) + ", " +
               std::to_string(g.contacts.size()) + " contacts>";
      });

  py::class_<PyPlan>(m, "Plan", "Planned grasps with their parameters and statistics.")
      .def_property_readonly("grasps",
                             [](const PyPlan& p) {
                               std::vector<PyGrasp> out;
                               for (const Grasp& g : p.doc.grasps)
                                 out.push_back(to_py_grasp(g, *p.hand));
                               return out;
                             })
      .def_readonly("job_wall_s", &PyPlan::job_wall_s,
                    "Wall-clock time of the C++ plan job (0 for a plan read from a file) [s]")
      .def_property_readonly("planner", [](const PyPlan& p) { return std::string(to_string(p.doc.planner)); })
      .def_property_readonly(
          "interrupted",
          [](const PyPlan& p) -> py::object {
            if (p.doc.interrupted.empty()) return py::none();
            return py::str(p.doc.interrupted);
          },
          "The signal that stopped the planning early ('SIGINT'; plan.json \"complete\": "
          "false), None for a complete plan (also one from before the key existed).")
      .def_property_readonly("hand", [](const PyPlan& p) { return PyHand{p.hand}; })
      .def_property_readonly("stats", [](const PyPlan& p) {
        return json_to_py(plan_to_json(p.doc, *p.hand)["stats"]);
      })
      .def_property_readonly("parameters", [](const PyPlan& p) {
        return json_to_py(plan_to_json(p.doc, *p.hand)["parameters"]);
      })
      .def_property_readonly("validation", [](const PyPlan& p) -> py::object {
        const nlohmann::json j = plan_to_json(p.doc, *p.hand);
        if (!j.contains("validation")) return py::none();
        return json_to_py(j["validation"]);
      }, "Validated planning: its parameters and stats (None for a plain plan).")
      .def("to_json", [](const PyPlan& p) { return plan_to_json(p.doc, *p.hand).dump(2); },
           "plan.json text.")
      .def("to_dict", [](const PyPlan& p) { return json_to_py(plan_to_json(p.doc, *p.hand)); })
      .def(
          "write", [](const PyPlan& p, const std::string& path) {
            write_plan_file(path, p.doc, *p.hand);
          },
          py::arg("path"), "Writes plan.json (atomically).")
      .def("__len__", [](const PyPlan& p) { return p.doc.grasps.size(); })
      .def("__repr__", [](const PyPlan& p) {
        return "<cordgrasp.Plan " + std::string(to_string(p.doc.planner)) + ", " + std::to_string(p.doc.grasps.size()) +
               " grasps>";
      });

  m.def("plan_parameters", &defaults_dict<PlanJobParams>,
        "Every planner keyword argument of plan() with its C++ default.");

  m.def(
      "plan",
      [](const PyMesh& mesh, const PyHand& hand, int jobs, const py::kwargs& kwargs) {
        PlanJobParams params;
        set_from_kwargs(&params, kwargs);
        return run_plan(mesh, hand, [&](const std::string& path) {
          return plan_job(params, *mesh.mesh, path, *hand.hand, {}, jobs);
        });
      },
      py::arg("mesh"), py::arg("hand"), py::arg("jobs") = 1,
      "Plans force-closure grasps. `jobs`: threads of the cord exploration (same result). "
      "Keyword arguments: planner ('cord' or 'generic') and every field of plan_parameters() "
      "(flat names, C++ defaults).");

  m.def("validation_parameters", &defaults_dict<ValidationParams>,
        "Every key of plan_validated()'s `validation` dict with its C++ default.");

  m.def(
      "plan_validated",
      [](const PyMesh& mesh, const PyHand& hand, const py::dict& validation, int jobs,
         const py::kwargs& kwargs) {
        PlanJobParams params;
        set_from_kwargs(&params, kwargs);
        ValidationParams v;
        set_from_kwargs(&v, validation);
        return run_plan(mesh, hand, [&](const std::string& path) {
          return validated_plan_job(params, v, *mesh.mesh, path, *hand.hand, jobs);
        });
      },
      py::arg("mesh"), py::arg("hand"), py::arg("validation") = py::dict(), py::arg("jobs") = 1,
      "Validated planning (as `cordgrasp plan --validate`): only grasps that hold in physics in "
      "at least min_held of trials, pairwise different. `validation`: keys of "
      "validation_parameters(); other keyword arguments as plan().");
}

// ---- physics -----------------------------------------------------------------------------

void bind_validate(py::module_& m) {
  m.def(
      "validate",
      [](PyPlan& plan, const std::string& protocol, const std::string& tests, int trials,
         int max_grasps, int jobs, std::uint64_t seed, std::optional<double> mass_kg,
         std::optional<double> density_kgm3, std::optional<double> squeeze_weight_factor,
         const std::string& physics) {
        PhysicsChoice choice;
        choice.protocol = parse_protocol(protocol);
        choice.overrides = SimOverrides{mass_kg, density_kgm3, squeeze_weight_factor};
        if (plan.doc.validation) choice.recorded = plan.doc.validation->params.physics;
        choice.file = !physics.empty() || !plan.doc.validation
                          ? physics
                          : plan.doc.validation->params.physics_file;
        const SimParams params = physics_settings(plan_contact_model(plan.doc), choice);
        const SimTests sim_tests = sim_tests_from_string(tests);
        const Mesh& mesh = plan_mesh(plan);
        SimDocument doc;
        {
          py::gil_scoped_release release;
          doc = validate_plan(plan.doc, *plan.hand, mesh, params, sim_tests, max_grasps, {}, {},
                              jobs);
          if (trials > 1)
            add_perturbed_trials(doc, plan.doc, *plan.hand, mesh, trials, PerturbationParams{},
                                 seed, {}, jobs);
        }
        return json_to_py(sim_to_json(doc, *plan.hand));
      },
      py::arg("plan"), py::arg("protocol") = std::string(to_string(SimParams{}.protocol)), py::arg("tests") = "lift,shake,gravity6",
      py::arg("trials") = 1, py::arg("max_grasps") = -1, py::arg("jobs") = 1,
      py::arg("seed") = 1, py::arg("mass_kg") = py::none(), py::arg("density_kgm3") = py::none(),
      py::arg("squeeze_weight_factor") = py::none(), py::arg("physics") = std::string(),
      "Checks the plan's grasps in Bullet; returns the sim.json content as a dict. mass_kg, "
      "density_kgm3, squeeze_weight_factor: as `validate --mass/--density/--squeeze-weight`; "
      "None: those a validated plan was accepted with, else the defaults. physics: a settings "
      "file (YAML or JSON) over the protocol, as `validate --physics`.");
}

// ---- pictures ----------------------------------------------------------------------------

void bind_render(py::module_& m) {
  m.def(
      "render",
      [](PyPlan& plan, int grasp, int width_px, int height_px, const std::string& view,
         bool png) -> py::object {
        if (grasp < 0 || grasp >= static_cast<int>(plan.doc.grasps.size()))
          throw py::index_error("render: no grasp " + std::to_string(grasp));
        const Mesh& mesh = plan_mesh(plan);
        Image image;
        std::string bytes;
        {
          py::gil_scoped_release release;
          const Grasp& g = plan.doc.grasps[grasp];
          Scene scene = grasp_scene(*plan.hand, make_hand_meshes(*plan.hand),
                                    std::shared_ptr<const Mesh>(plan.mesh, &mesh), g,
                                    g.region ? &*g.region : nullptr);
          PictureOptions options;
          options.view = view;
          options.size = std::to_string(width_px) + "x" + std::to_string(height_px);
          const Eigen::Vector3d approach = g.X_OG.linear().col(2);
          image = render_scene(scene, render_params(options, scene, approach));
          if (png) bytes = encode_png(image);
        }
        if (png) return py::bytes(bytes);
        py::array_t<std::uint8_t> a({image.height, image.width, 4});
        std::copy(image.rgba.begin(), image.rgba.end(), a.mutable_data());
        return std::move(a);
      },
      py::arg("plan"), py::arg("grasp") = 0, py::arg("width") = 1024, py::arg("height") = 768,
      py::arg("view") = "iso", py::arg("png") = false,
      "Draws grasp `grasp` of the plan: an (height, width, 4) uint8 RGBA array, or PNG bytes.");
}

}  // namespace
}  // namespace cordgrasp::python

PYBIND11_MODULE(_cordgrasp, m) {
  using namespace cordgrasp;
  m.doc() = "cordgrasp: cord-driven grasp planning, Bullet validation, OSMesa pictures";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  m.def("version", [] { return std::string(version()); });
  m.def("assets_dir", &assets_dir, "Folder of the shipped hands and objects.");
  m.def("default_hand_name", [] { return std::string(default_hand_name()); });
  python::bind_io(m);
  python::bind_plan(m);
  python::bind_validate(m);
  python::bind_render(m);
}
