#pragma once
// One planning job (object + hand + planner parameters -> PlanDocument), shared by
// `cordgrasp plan`, `run` and `bench` so the three agree on every option and default.
#include <cstdint>
#include <optional>
#include <string>

#include "cordgrasp/core/cancel_token.h"
#include "cordgrasp/core/contact_model.h"
#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/serialize.h"
#include "cordgrasp/jobs/plan_json.h"

namespace cordgrasp {

/// One planning job's parameters: the planner and its typed parameter structs (the CLI binds
/// its options to these fields, so its help shows their defaults).
struct PlanJobParams {
  PlannerKind planner = PlannerKind::kCord;
  /// Shared planner parameters; plan.seed also seeds cord.seed and plan.quality.seed, and
  /// plan.time_limit_s caps cord.time_limit_s (plan_job sets both).
  PlanParams plan;
  CordParams cord;  ///< cord planner: exploration parameters (seed, time limit from `plan`)
  /// Contact patch radius [m]; 0 = point contacts; unset: the hand's soft_finger_radius_m
  /// (overrides plan.quality.contact.soft_finger_radius_m).
  std::optional<double> soft_finger_radius_m;
  LengthUnits units = LengthUnits::kMeters;  ///< object file units
  double scale = 1.0;  ///< uniform object scale applied after the units (e.g. 2: twice the size)

  /// Visits every field in declaration order (core/serialize.h).
  template <typename Archive>
  void Serialize(Archive* a) {
    visit_fields(a, CORDGRASP_NVP(planner), CORDGRASP_NVP(plan), CORDGRASP_NVP(cord),
                 CORDGRASP_NVP(soft_finger_radius_m), CORDGRASP_NVP(units), CORDGRASP_NVP(scale));
  }
};

/// The commands' mesh cache folder (MeshLoadOptions::cache_folder): $CORDGRASP_MESH_CACHE
/// ("off": none), else $XDG_CACHE_HOME/cordgrasp/meshes, else ~/.cache/cordgrasp/meshes.
std::string mesh_cache_folder();

/// The commands' load options: `units`, `scale` and the mesh cache folder.
MeshLoadOptions job_mesh_load_options(LengthUnits units, double scale);

/// Loads the object mesh in p.units, scaled by p.scale. Says on stderr when --units auto read it
/// as millimetres, and warns when a file read as meters is over 5 m across (a millimetre file given
/// as m).
/// @throws InputError as load_mesh.
Mesh load_job_mesh(const PlanJobParams& p, const std::string& object_path);

/// The friction model a plan was made with (plan.params.quality.contact: μ, cone edges,
/// soft-finger radius): the physics of validate, run and bench uses it too.
ContactModel plan_contact_model(const PlanDocument& plan);

/// The document plan_job() fills, before any planning: the inputs and the parameters as they
/// will be planned with (seeds, time limit, soft-finger radius resolved). @throws
/// std::invalid_argument for an unknown planner.
PlanDocument plan_document_for(const PlanJobParams& p, const Mesh& mesh,
                               const std::string& object_path, const HandModel& hand);

/// Plans grasps on `mesh` (loaded from `object_path`) with `hand`: the document plan.json
/// holds. Deterministic for a given seed (timings aside). `cancel` stops the finger stage
/// before its next attempt: the document then holds the grasps found so far and
/// doc.interrupted names the signal. `threads`: the cord exploration's (plan_cord_grasps);
/// the document does not depend on it.
PlanDocument plan_job(const PlanJobParams& p, const Mesh& mesh, const std::string& object_path,
                      const HandModel& hand, const CancelToken& cancel = {}, int threads = 1);

/// One line on a plan that found no force-closure grasp: "<who>: no force-closure grasp of
/// <object> with <hand> (<planner> planner, N attempts in T s, <why it stopped>); try ...",
/// with a --units hint when the object is over 5 m across.
std::string no_grasp_message(const std::string& who, const PlanDocument& doc, const Mesh& mesh);

/// Absolute, normalized path.
std::string absolute_path(const std::string& path);

}  // namespace cordgrasp
