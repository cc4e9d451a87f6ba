#pragma once
// One planning job (object + hand + planner parameters -> PlanDocument), shared by
// `cordgrasp plan`, `run` and `bench` so the three agree on every option and default.
#include <cstdint>
#include <optional>
#include <string>

#include "cordgrasp/core/contact_model.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/jobs/plan_json.h"

namespace cordgrasp {

/// Planner options as the CLI takes them (units in names; defaults are the CLI's).
struct PlanJobParams {
  std::string planner = "cord";  ///< cord (Li et al. 2015) or generic (Simox-style baseline)
  int grasps = 1;                ///< stop after this many force-closure grasps
  double time_limit_s = 10.0;    ///< wall-clock limit of the plan [s]
  std::uint64_t seed = 1;        ///< seed of every random choice
  double mu = kDefaultFrictionCoefficient;  ///< friction coefficient (planner and physics)
  /// Contact patch radius [m]; 0 = point contacts; unset: the hand's soft_finger_radius_m.
  std::optional<double> soft_finger_radius_m;
  std::string side_cords = "empty";         ///< empty, discard or shrink (SideCordPolicy)
  std::string quality = "textbook";         ///< textbook or simox (spec §8)
  std::string units = "m";                  ///< object file units: m, mm or auto
  int cord_sets = 20;                       ///< cord: valid sets sampled (K, spec §4)
  bool cord_local_improvement = true;       ///< cord: local improvement of the sets (§5)
};

/// Loads the object mesh in p.units. Says on stderr when --units auto read it as millimetres,
/// and warns when a file read as meters is over 5 m across (a millimetre file given as m).
/// @throws InputError as load_mesh.
Mesh load_job_mesh(const PlanJobParams& p, const std::string& object_path);

/// The friction model a plan was made with (μ, soft-finger radius from its parameters): the
/// physics of validate, run and bench uses it too (one source of truth).
ContactModel plan_contact_model(const PlanDocument& plan);

/// Plans grasps on `mesh` (loaded from `object_path`) with `hand`: the document plan.json
/// holds. Deterministic for a given seed (timings aside).
PlanDocument plan_job(const PlanJobParams& p, const Mesh& mesh, const std::string& object_path,
                      const HandModel& hand);

/// Absolute, normalized path.
std::string absolute_path(const std::string& path);

}  // namespace cordgrasp
