// Force-closure test and ε (docs/finger-stage-and-quality.md, "Stability"): the wrench sets most
// finger-stage attempts give (not force closure: the linear program's screen answers) and one
// that passes to the hull. Contacts on a 10 cm box, soft fingers, μ 0.5, 8 edges.
#include <benchmark/benchmark.h>

#include <vector>

#include "cordgrasp/core/grasp_quality.h"
#include "cordgrasp/core/shapes.h"

namespace {

using namespace cordgrasp;

Contact contact_at(const Eigen::Vector3d& p_O, const Eigen::Vector3d& n_O) {
  Contact c;
  c.link = 0;
  c.p_O = p_O;
  c.n_O = n_O.normalized();
  return c;
}

QualityParams soft_fingers() {
  QualityParams p;
  p.contact.soft_finger_radius_m = 0.005;
  return p;
}

void run(benchmark::State& state, const std::vector<Contact>& contacts, bool expect_fc) {
  const QualityParams params = soft_fingers();
  const WrenchSpaceObject box = prepare_wrench_space(make_box_mesh({0.1, 0.1, 0.1}), params);
  for (auto _ : state) {
    const GraspQuality q = evaluate_grasp_quality(contacts, box, params);
    if (q.force_closure != expect_fc) state.SkipWithError("unexpected verdict");
    benchmark::DoNotOptimize(q.epsilon);
  }
}

// Three fingertips on the top face and one on a side: all push down or sideways, nothing up.
void BM_QualityNotForceClosure(benchmark::State& state) {
  run(state,
      {contact_at({0.02, 0.0, 0.05}, Eigen::Vector3d::UnitZ()),
       contact_at({-0.02, 0.01, 0.05}, Eigen::Vector3d::UnitZ()),
       contact_at({0.0, -0.02, 0.05}, Eigen::Vector3d::UnitZ()),
       contact_at({0.05, 0.0, 0.0}, Eigen::Vector3d::UnitX())},
      false);
}
BENCHMARK(BM_QualityNotForceClosure)->Unit(benchmark::kMicrosecond);

// Two pads on opposite faces, two points each: force closure, the hull gives ε.
void BM_QualityForceClosure(benchmark::State& state) {
  run(state,
      {contact_at({0.05, 0.0, 0.01}, Eigen::Vector3d::UnitX()),
       contact_at({0.05, 0.0, -0.01}, Eigen::Vector3d::UnitX()),
       contact_at({-0.05, 0.0, 0.01}, -Eigen::Vector3d::UnitX()),
       contact_at({-0.05, 0.0, -0.01}, -Eigen::Vector3d::UnitX())},
      true);
}
BENCHMARK(BM_QualityForceClosure)->Unit(benchmark::kMicrosecond);

}  // namespace
