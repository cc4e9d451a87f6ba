// `cordgrasp export`: every format is written for a plan of every shipped hand; MuJoCo loads
// each MJCF scene and its keyframes reproduce the plan's joint values and GCP position.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cordgrasp/core/mesh_io.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

constexpr double kGcpTol_m = 1e-3;     // the keyframe's GCP against the plan's
constexpr double kJointTol = 1e-6;     // keyframe joint values against the plan's [rad or m]

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() /
             ("cordgrasp_export_" + name + "_" + std::to_string(::getpid()))) {
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// Loads `xml` with MuJoCo and checks every keyframe against the plan's grasps.
void expect_mjcf_reproduces_plan(const fs::path& xml, const nlohmann::json& plan) {
  char error[1000] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> m(
      mj_loadXML(xml.c_str(), nullptr, error, sizeof(error)), mj_deleteModel);
  ASSERT_TRUE(m) << xml << ": " << error;
  std::unique_ptr<mjData, void (*)(mjData*)> d(mj_makeData(m.get()), mj_deleteData);
  const auto& grasps = plan["grasps"];
  ASSERT_EQ(m->nkey, static_cast<int>(grasps.size()));
  const int site = mj_name2id(m.get(), mjOBJ_SITE, "gcp");
  ASSERT_GE(site, 0);
  for (int k = 0; k < m->nkey; ++k) {
    const std::string key = "grasp_" + std::to_string(k);
    ASSERT_EQ(mj_name2id(m.get(), mjOBJ_KEY, key.c_str()), k);
    mj_resetDataKeyframe(m.get(), d.get(), k);
    mj_forward(m.get(), d.get());
    const auto& g = grasps[k];
    for (const auto& [name, value] : g["joints"].items()) {
      const int j = mj_name2id(m.get(), mjOBJ_JOINT, name.c_str());
      if (j < 0) continue;  // fixed joints are not MuJoCo joints
      EXPECT_NEAR(d->qpos[m->jnt_qposadr[j]], value.get<double>(), kJointTol)
          << key << " joint " << name;
    }
    const auto& p = g["gcp_pose"]["position_m"];
    const Eigen::Vector3d p_plan(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    const Eigen::Vector3d p_mj(d->site_xpos[3 * site], d->site_xpos[3 * site + 1],
                               d->site_xpos[3 * site + 2]);
    EXPECT_LT((p_mj - p_plan).norm(), kGcpTol_m) << key << ": MuJoCo " << p_mj.transpose()
                                                 << ", plan " << p_plan.transpose();
  }
}

/// Plans `hand` on the shipped box, exports all formats and checks each file.
void export_all_formats(const std::string& hand) {
  const TempDir dir(hand);
  const fs::path plan = dir.path / "plan.json";
  const test::CommandResult planned = test::run_cordgrasp(
      "plan --hand " + hand + " --object box -n 2 --out " + plan.string());
  ASSERT_EQ(planned.exit_code, 0) << planned.output;
  const nlohmann::json plan_json = nlohmann::json::parse(read_text(plan));
  const size_t n = plan_json["grasps"].size();
  ASSERT_GE(n, 1u) << planned.output;

  const fs::path xml = dir.path / "scene.xml";
  const fs::path yaml = dir.path / "grasps.yaml";
  for (const auto& [format, out] :
       std::vector<std::pair<std::string, fs::path>>{{"mjcf", xml},
                                                     {"moveit", yaml},
                                                     {"glb", dir.path / "glb"},
                                                     {"obj", dir.path / "obj"}}) {
    const test::CommandResult r = test::run_cordgrasp("export --plan " + plan.string() +
                                                      " --format " + format + " --out " +
                                                      out.string());
    ASSERT_EQ(r.exit_code, 0) << format << ": " << r.output;
  }
  expect_mjcf_reproduces_plan(xml, plan_json);

  const std::string y = read_text(yaml);
  EXPECT_EQ(count_of(y, "\n- id: "), n);
  EXPECT_EQ(count_of(y, "pre_grasp_posture:"), n);
  EXPECT_EQ(count_of(y, "grasp_posture:"), 2 * n);  // pre_grasp_posture contains it too

  const int object_triangles = plan_json["inputs"]["object"]["triangles"].get<int>();
  for (const std::string ext : {"glb", "obj"})
    for (size_t k = 0; k < n; ++k) {
      const fs::path file = dir.path / ext / ("grasp_" + std::to_string(k) + "." + ext);
      ASSERT_TRUE(fs::is_regular_file(file)) << file;
      const Mesh mesh = load_mesh(file.string());  // object + hand, read back through assimp
      EXPECT_GT(static_cast<int>(mesh.triangles.size()), object_triangles) << file;
    }
}

class ExportShippedHand : public ::testing::TestWithParam<std::string> {};
class ExportShippedHandDataset : public ::testing::TestWithParam<std::string> {};

TEST_P(ExportShippedHand, WritesEveryFormatAndMujocoReproducesThePlan) {
  export_all_formats(GetParam());
}

TEST_P(ExportShippedHandDataset, WritesEveryFormatAndMujocoReproducesThePlan) {
  if (test::shared_data_dir().empty()) GTEST_SKIP() << "needs ../shared/data (its URDFs)";
  export_all_formats(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Hands, ExportShippedHand,
                         ::testing::Values("cordgrasp_sah", "parallel_gripper"));
INSTANTIATE_TEST_SUITE_P(Hands, ExportShippedHandDataset,
                         ::testing::Values("allegro_right", "armar3_right_hand", "barrett_bh282",
                                           "icub_right_hand", "panda_hand", "schunk_sah"));

TEST(ExportCli, RefusesAnUnknownFormat) {
  const test::CommandResult r =
      test::run_cordgrasp("export --plan x.json --format stl --out /tmp/x.stl");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--format"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace cordgrasp
