#include "validation_options.h"

#include "options.h"
#include "cordgrasp/jobs/text_format.h"
#include "cordgrasp/jobs/uncertainty_settings.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp::cli {

const char* const kPhysicsHelp =
    "Physics settings (JSON, or YAML named *.yaml) merged over the protocol: any SimParams "
    "fields, or a sim.json whose parameters to repeat (docs/physics.md §5a)";

void add_uncertainty_options(CLI::App* cmd, ValidationParams& v, const char* use) {
  const std::string model =
      "P(held) under uncertain hand pose, friction, mass, centre of mass and grip force (none, "
      "realistic, or a JSON/YAML file of their spreads; docs/physics.md §3b)";
  const std::string accept =
      "Validated planning: accept a candidate held as planned when its " + model +
      " is decided above --min-hold-probability within the settings' validation.max_draws "
      "draws, then again on draws of its own; rank the accepted grasps by the second "
      "(default: none, the nudged trials)";
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
