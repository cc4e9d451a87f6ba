#include "options.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "cordgrasp/jobs/plan_settings.h"
#include "cordgrasp/sim/validate_grasp.h"

namespace cordgrasp::cli {
namespace {

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

bool all_digits(const std::string& text, bool allow_minus) {
  size_t i = allow_minus && !text.empty() && text[0] == '-' ? 1 : 0;
  if (i == text.size()) return false;
  for (; i < text.size(); ++i)
    if (text[i] < '0' || text[i] > '9') return false;
  return true;
}

}  // namespace

CLI::Validator number_in(double lo, double hi) {
  const std::string rule = "a finite number in [" + number_text(lo) + ", " + number_text(hi) + "]";
  return CLI::Validator(
      [lo, hi, rule](std::string& text) {
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(text.c_str(), &end);
        const bool parsed = end != text.c_str() && *end == '\0' && errno != ERANGE;
        if (!parsed || !std::isfinite(v) || v < lo || v > hi) return text + " is not " + rule;
        return std::string();
      },
      rule);
}

CLI::Validator whole_number_in(long long lo, long long hi) {
  const std::string rule =
      "a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, rule](std::string& text) {
        if (!all_digits(text, true) || text.size() > 18) return text + " is not " + rule;
        const long long v = std::stoll(text);
        if (v < lo || v > hi) return text + " is not " + rule;
        return std::string();
      },
      rule);
}

CLI::Validator whole_number_at_least(long long lo) {
  const std::string rule = "a whole number \u2265 " + std::to_string(lo);
  return CLI::Validator(
      [lo, rule](std::string& text) {
        if (!all_digits(text, true) || text.size() > 18) return text + " is not " + rule;
        if (std::stoll(text) < lo) return text + " is not " + rule;
        return std::string();
      },
      rule);
}

CLI::Validator seed_value() {
  const std::string rule = "a whole number in [0, 18446744073709551615]";
  return CLI::Validator(
      [rule](std::string& text) {
        if (!all_digits(text, false)) return text + " is not " + rule;
        errno = 0;
        char* end = nullptr;
        (void)std::strtoull(text.c_str(), &end, 10);
        if (errno == ERANGE || *end != '\0') return text + " is not " + rule;
        return std::string();
      },
      rule);
}

CLI::Validator one_of(const std::vector<std::string>& names) {
  std::string rule = "one of ", braces = "{";
  for (size_t i = 0; i < names.size(); ++i) {
    rule += (i ? ", " : "") + names[i];
    braces += (i ? "," : "") + names[i];
  }
  return CLI::Validator(
      [names, rule](std::string& text) {
        if (std::find(names.begin(), names.end(), text) != names.end()) return std::string();
        return text + " is not " + rule;
      },
      braces + "}");
}

std::string enum_refusal(const std::string& text, const std::string& parse_error) {
  // parse_error reads "units: unknown name 'cm' (allowed: m, mm, auto)".
  const std::string key = "(allowed: ";
  const size_t at = parse_error.find(key), end = parse_error.rfind(')');
  if (at == std::string::npos || end == std::string::npos || end < at + key.size())
    return text + " is not a known name (" + parse_error + ")";
  return text + " is not one of " + parse_error.substr(at + key.size(), end - at - key.size());
}

CLI::Validator physics_tests(bool allow_none) {
  const std::string rule = std::string("a comma list of lift, shake, gravity6") +
                           (allow_none ? ", or none" : " (at least one)");
  return CLI::Validator(
      [allow_none, rule](std::string& text) {
        if (allow_none && text == "none") return std::string();
        try {
          (void)sim_tests_from_string(text);
        } catch (const std::invalid_argument&) {
          return text + " is not " + rule;
        }
        return std::string();
      },
      rule);
}

CLI::Option* add_scale_option(CLI::App* cmd, double* scale, const std::string& extra_help) {
  return cmd
      ->add_option("--scale", *scale,
                   "Uniform object scale after --units, e.g. 2 for a mesh at half its real "
                   "size" + extra_help)
      ->check(settings_number("scale"))
      ->capture_default_str();
}

CLI::Validator settings_number(const std::string& key) {
  const auto [lo, hi] = plan_settings_range(key);
  return number_in(lo, hi);
}

CLI::Validator settings_whole_number(const std::string& key) {
  const auto [lo, hi] = plan_settings_range(key);
  return whole_number_in(static_cast<long long>(lo), static_cast<long long>(hi));
}

void add_planner_option(CLI::App* cmd, PlanJobParams& p) {
  add_enum_option(cmd, "--planner", &p.planner,
                  "cord (Li et al. 2015) or generic (Simox baseline)");
}

void add_plan_job_options(CLI::App* cmd, PlanJobParams& p) {
  cmd->add_option("--grasps,-n", p.plan.grasps,
                  "Grasps wanted, pairwise distinct (the diversity rule, docs/algorithm.md §10b)")
      ->check(settings_whole_number("grasps"))
      ->capture_default_str();
  cmd->add_option("--seed", p.plan.seed, "Seed of every random choice")
      ->check(seed_value())
      ->capture_default_str();
  cmd->add_option("--mu", p.plan.quality.contact.mu,
                  "Friction coefficient of the wrench space and the physics")
      ->check(settings_number("quality.contact.mu"))
      ->capture_default_str();
}

void add_units_option(CLI::App* cmd, PlanJobParams& p) {
  add_enum_option(cmd, "--units", &p.units, "Units of the object file: m, mm or auto");
}

void add_time_limit_option(CLI::App* cmd, PlanJobParams& p) {
  cmd->add_option("--time-limit", p.plan.time_limit_s,
                  "Safety net: wall-clock limit of the plan [s]; when it fires, the result "
                  "depends on the machine's speed (timed_out in plan.json and results.csv)")
      ->check(settings_number("time_limit_s"))
      ->capture_default_str();
}

void add_plan_settings_option(CLI::App* cmd, PlanJobParams& p, ValidationParams& v) {
  cmd->add_option_function<std::string>(
         "--settings",
         [&p, &v](const std::string& path) { merge_plan_settings_file(path, &p, &v); },
         "Planner settings (JSON, or YAML named *.yaml): any fields of plan.json's parameters "
         "and validation blocks, or a plan.json whose settings to repeat; the options given "
         "here win (docs/algorithm.md §10c)")
      ->trigger_on_parse();  // before the other options' values are stored: those win
}

void add_package_path_option(CLI::App* cmd, HandLoadOptions& o) {
  cmd->add_option_function<std::vector<std::string>>(
         "--package-path",
         [&o](const std::vector<std::string>& items) {
           for (const std::string& item : items) {
             const size_t eq = item.find('=');
             // Relative to the working directory, not to the URDF.
             o.package_paths[item.substr(0, eq)] =
                 std::filesystem::absolute(item.substr(eq + 1)).lexically_normal().string();
           }
         },
         "ROS package directory for package://NAME/... meshes, NAME=DIR (repeatable; "
         "before ROS_PACKAGE_PATH and AMENT_PREFIX_PATH)")
      ->type_name("NAME=DIR")
      ->check(CLI::Validator(
          [](std::string& text) {
            const size_t eq = text.find('=');
            if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
              return text + " is not NAME=DIR";
            std::error_code ec;
            if (!std::filesystem::is_directory(text.substr(eq + 1), ec))
              return text + ": '" + text.substr(eq + 1) + "' is not a directory";
            return std::string();
          },
          "NAME=DIR"));
}

void add_picture_options(CLI::App& cmd, PictureOptions& o) {
  cmd.add_option("--view", o.view,
                     "Viewpoint: iso, front, side, top or approach (default: iso; approach for "
                     "--regions)")
      ->check(one_of({"iso", "front", "side", "top", "approach"}));
  cmd.add_option("--approach", o.approach,
                 "Viewing direction x,y,z for --view approach (default: the grasp's approach)");
  cmd.add_option("--size", o.size, "Image size WxH in pixels")->capture_default_str();
  cmd.add_option("--supersample", o.supersample, "Anti-aliasing: supersampling factor 1..4")
      ->check(whole_number_in(1, 4))
      ->capture_default_str();
  cmd.add_option("--ground", o.ground, "Under the scene: shadow, grid or none")
      ->check(one_of({"shadow", "grid", "none"}))
      ->capture_default_str();
  cmd.add_option("--caption", o.caption, "Caption text instead of the default one");
  cmd.add_flag("--no-caption", o.no_caption, "No caption line");
  cmd.add_flag("--ortho", o.orthographic, "Orthographic instead of perspective projection");
}

}  // namespace cordgrasp::cli
