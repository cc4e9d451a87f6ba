#include "validation_options.h"

#include "options.h"
#include "cordgrasp/jobs/text_format.h"
#include "cordgrasp/jobs/uncertainty_settings.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp::cli {

void add_trial_nudge_options(CLI::App* cmd, PerturbationParams& p) {
  cmd->add_option("--trial-offset", p.offset_m,
                  "Hand offset of the nudged trials (all but the first) [m], random direction")
      ->check(settings_number("validation.perturbation.offset_m"))
      ->capture_default_str();
  cmd->add_option("--trial-turn", p.turn_rad,
                  "Hand turn of the nudged trials about the GCP [rad], random axis")
      ->check(settings_number("validation.perturbation.turn_rad"))
      ->capture_default_str();
}

const char* const kPhysicsHelp =
    "Physics settings (JSON, or YAML named *.yaml) merged over the protocol: any SimParams "
    "fields, or a sim.json whose parameters to repeat (docs/physics.md §5a)";

void add_validation_options(CLI::App* cmd, ValidationParams& v) {
  cmd->add_option("--physics", v.physics_file, kPhysicsHelp);
  cmd->add_option("--trials", v.trials,
                  "Physics trials per candidate: as planned, then nudged by --trial-offset and "
                  "--trial-turn")
      ->check(settings_whole_number("validation.trials"))
      ->capture_default_str();
  cmd->add_option("--min-held", v.min_held,
                  "A candidate is accepted when held in at least this many trials")
      ->check(settings_whole_number("validation.min_held"))
      ->capture_default_str();
  cmd->add_option("--require-held-as-planned", v.require_held_as_planned,
                  "A candidate must hold in its first trial, as planned (the grasp plan.json "
                  "stores), as well as in --min-held trials in all (true or false)")
      ->capture_default_str();
  cmd->add_option("--budget", v.budget_s,
                  "CPU budget of planning and physics together, all threads [s] (replaces "
                  "--time-limit)")
      ->check(settings_number("validation.budget_s"))
      ->capture_default_str();
  cmd->add_option("--squeeze-shift-limit", v.squeeze_shift_limit_m,
                  "Candidates whose object moves farther while closing are dropped before lift "
                  "[m]; 0: off")
      ->check(settings_number("validation.squeeze_shift_limit_m"))
      ->capture_default_str();
  add_trial_nudge_options(cmd, v.perturbation);
  cmd->add_option("--trial-seed", v.trial_seed, "Seed of the nudges' random directions")
      ->check(seed_value())
      ->capture_default_str();
}

void add_uncertainty_options(CLI::App* cmd, ValidationParams& v, const char* use) {
  const std::string model =
      "P(held) under uncertain hand pose, friction, mass, centre of mass and grip force (none, "
      "realistic, or a JSON/YAML file of their spreads; docs/physics.md §3b)";
  const std::string accept =
      "Validated planning: accept a candidate held as planned when its " + model +
      " is decided above --min-hold-probability within the settings' validation.max_draws "
      "draws; rank the accepted grasps by it (default: none, the nudged trials)";
  cmd->add_option_function<std::string>(
         "--uncertainty",
         [&v](const std::string& choice) { v.uncertainty = uncertainty_settings(choice); },
         use ? std::string(use) + ": " + model + ". " + accept : accept);
  cmd->add_option("--min-hold-probability", v.min_hold_probability,
                  "Acceptance threshold of P(held) with --uncertainty")
      ->check(settings_number("validation.min_hold_probability"))
      ->capture_default_str();
}

const char* const kProtocolHelp =
    "Physics protocol (docs/physics.md §3): standard (the bounded close: the fingers start a "
    "few mm short of the planned contacts, close onto them and squeeze at most a millimetre "
    "past); quick (a squeeze spring 0.5 rad past the plan); thorough (quick's close, long "
    "phases, no early exits)";

void add_validate_option(CLI::App* cmd, bool* validate, Protocol* protocol) {
  cmd->add_option_function<std::string>(
         "--validate",
         [validate, protocol](const std::string& text) {
           *validate = true;
           if (!text.empty()) parse_name(text, protocol);
         },
         std::string("[PROTOCOL] Keep only grasps that hold in physics under PROTOCOL (default ") +
             to_string(*protocol) +
             "): force-closure candidates, best first, until --grasps are accepted or the "
             "settings' validation.budget_s is spent. " + kProtocolHelp)
      ->expected(0, 1)
      ->check(enum_name_check<Protocol>);
}

void add_sim_override_options(CLI::App* cmd, SimOverrides& o, const std::string& recorded_note) {
  cmd->add_option("--mass", o.mass_kg, "Object mass [kg] (default: " + recorded_note +
                                           "from the volume, docs/physics.md §2)")
      ->check(settings_number("validation.physics.mass_kg"));
  cmd->add_option("--density", o.density_kgm3,
                  "Object density [kg/m^3] (default: " + recorded_note +
                      format_number(SimParams{}.density_kgm3) + ")")
      ->check(settings_number("validation.physics.density_kgm3"));
  cmd->add_option("--squeeze-weight", o.squeeze_weight_factor,
                  "Grasp force in proportion to the object's weight: the fingers' squeeze "
                  "efforts are scaled down together until each planned contact is pressed with "
                  "this x m*g/mu (0: the joints' effort limits; default: " + recorded_note +
                      format_number(SimParams{}.squeeze_weight_factor) + ")")
      ->check(settings_number("validation.physics.squeeze_weight_factor"));
}

}  // namespace cordgrasp::cli
