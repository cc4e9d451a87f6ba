#pragma once
// Command-line options shared by several subcommands, bound to the jobs' parameter structs.
#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>

#include "cordgrasp/jobs/parse_name.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/jobs/render_options.h"

namespace cordgrasp::cli {

/// An option naming an enumerator of `*field` (its to_string names; parse_name rejects others),
/// with the field's current value as the default shown by --help.
template <typename E>
CLI::Option* add_enum_option(CLI::App* cmd, const std::string& name, E* field,
                             const std::string& help) {
  return cmd
      ->add_option_function<std::string>(
          name, [field](const std::string& text) { parse_name(text, field); }, help)
      ->check([](const std::string& text) {
        E value{};
        try {
          parse_name(text, &value);
        } catch (const std::invalid_argument& e) {
          return std::string(e.what());
        }
        return std::string();
      })
      ->default_str(to_string(*field));
}

/// Adds the planner options (--planner, --grasps, --time-limit, --seed, --mu,
/// --soft-finger-radius, --side-cords, --quality, --units, --sets, --no-local-improvement) to
/// `cmd`, bound to `p`.
void add_plan_job_options(CLI::App* cmd, PlanJobParams& p);

/// Adds --view, --approach, --size, --supersample, --ground, --caption, --no-caption, --ortho.
void add_picture_options(CLI::App& cmd, PictureOptions& o);

}  // namespace cordgrasp::cli
