#include "cordgrasp/jobs/uncertainty_settings.h"

#include <stdexcept>

#include "cordgrasp/core/error.h"
#include "params_json.h"
#include "settings_document.h"

namespace cordgrasp {

UncertaintyParams uncertainty_settings(const std::string& choice) {
  if (choice == "none") return uncertainty_none();
  if (choice == "realistic") return UncertaintyParams{};
  const std::string what = "uncertainty settings '" + choice + "'";
  const nlohmann::json file = read_settings_document(choice, what);
  if (!file.is_object())
    throw InputError(what +
                     ": expected a mapping of uncertainty fields (or 'none', "
                     "'realistic')");
  nlohmann::json patch = file;
  std::string path;
  if (file.contains("format") && file.contains("parameters")) {  // a sim.json: repeat its run
    const nlohmann::json& params = file.at("parameters");
    if (!params.is_object() || !params.contains("uncertainty") ||
        params.at("uncertainty").is_null())
      throw InputError(what + ": parameters.uncertainty: missing (a run without --uncertainty)");
    patch = params.at("uncertainty");
    path = "parameters.uncertainty";
  }
  nlohmann::json merged = params_to_json(UncertaintyParams{});
  // Unknown keys stay in `merged`: the strict read below names them.
  overlay_json(patch, &merged);
  UncertaintyParams out;
  params_from_json(merged, what, path, &out);
  try {
    check_uncertainty_params(out);
  } catch (const std::invalid_argument& e) {
    throw InputError(what + ": " + e.what());
  }
  return out;
}

std::string uncertainty_settings_yaml(const UncertaintyParams& params) {
  return settings_yaml(params_to_json(params));
}

}  // namespace cordgrasp
