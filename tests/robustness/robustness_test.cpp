// Malformed inputs and option values against the cordgrasp command line, one test per case of
// tests/data/robustness/cases.yaml. Each case runs the built executable in a fresh empty folder
// and asserts how it ended (the exit code, and never a signal), what it said (stderr is exactly
// the expected number of non-empty lines, one by default, the last matching the case's regex)
// and that it wrote nothing it should not (the folder holds only what the case allows).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "test_files.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

/// One row of cases.yaml (the file's header describes the fields).
struct RobustnessCase {
  std::string id;
  std::string args;
  int exit_code = 1;
  std::string stderr_regex;
  int stderr_lines = 1;
  std::string stdout_regex;
  std::vector<std::string> setup_dirs, setup_files, setup_readonly_dirs;
  std::vector<std::string> absent, may_write;
  std::vector<std::string> finite;  ///< JSON files written with no NaN or infinity
  bool skip_as_root = false;
};

/// Keys of sim.json whose null is documented (docs/physics.md, sim_json.h): anywhere else a
/// null is a NaN or an infinity the JSON writer turned into null.
const std::set<std::string> kNullableKeys = {
    "failed_phase", "mass_kg", "held_trials", "trials", "planned_contact_offsets_m",
    "close_shift_m", "close_turn_rad", "first_force_closure_s", "uncertainty",
    "hold_probability", "most_associated"};

/// JSON paths of `j` holding a null outside kNullableKeys (an element of a nullable array too).
void undocumented_nulls(const nlohmann::json& j, const std::string& path, const std::string& key,
                        std::vector<std::string>* out) {
  if (j.is_null() && kNullableKeys.count(key) == 0) out->push_back(path);
  if (j.is_object())
    for (const auto& item : j.items())
      undocumented_nulls(item.value(), path + "." + item.key(), item.key(), out);
  if (j.is_array())
    for (size_t i = 0; i < j.size(); ++i)
      undocumented_nulls(j[i], path + "[" + std::to_string(i) + "]", key, out);
}

void PrintTo(const RobustnessCase& c, std::ostream* os) { *os << c.id << ": " << c.args; }

std::vector<std::string> strings(const YAML::Node& n) {
  std::vector<std::string> out;
  if (n) out = n.as<std::vector<std::string>>();
  return out;
}

std::string cases_file() { return test::test_data("robustness/cases.yaml"); }

/// Every case of cases.yaml; throws (failing the test discovery, naming the file) when the
/// table is malformed or repeats an id.
std::vector<RobustnessCase> load_cases() {
  std::vector<RobustnessCase> out;
  std::set<std::string> ids;
  const YAML::Node root = YAML::LoadFile(cases_file());
  for (const YAML::Node& n : root["cases"]) {
    RobustnessCase c;
    c.id = n["id"].as<std::string>();
    c.args = n["args"].as<std::string>();
    c.exit_code = n["exit"].as<int>();
    if (n["stderr"]) c.stderr_regex = n["stderr"].as<std::string>();
    c.stderr_lines = n["stderr_lines"] ? n["stderr_lines"].as<int>() : 1;
    if (n["stdout"]) c.stdout_regex = n["stdout"].as<std::string>();
    if (const YAML::Node s = n["setup"]) {
      c.setup_dirs = strings(s["dirs"]);
      c.setup_files = strings(s["files"]);
      c.setup_readonly_dirs = strings(s["readonly_dirs"]);
    }
    c.absent = strings(n["absent"]);
    c.may_write = strings(n["may_write"]);
    c.finite = strings(n["finite"]);
    c.skip_as_root = n["skip_as_root"] && n["skip_as_root"].as<bool>();
    if (!ids.insert(c.id).second)
      throw std::runtime_error(cases_file() + ": id '" + c.id + "' appears twice");
    if (c.stderr_lines > 0 && c.stderr_regex.empty())
      throw std::runtime_error(cases_file() + ": case '" + c.id + "' has no stderr regex");
    out.push_back(c);
  }
  return out;
}

/// `text` with {data}, {test_data}, {source} and {tmp} replaced.
std::string expand(std::string text, const std::string& tmp) {
  const std::pair<std::string, std::string> subs[] = {
      {"{data}", test::test_data("robustness")},
      {"{test_data}", test::test_data("")},
      {"{source}", test::source_dir()},
      {"{tmp}", tmp}};
  for (const auto& [key, value] : subs)
    for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at))
      text.replace(at, key.size(), value), at += value.size();
  return text;
}

/// Arguments: split at spaces first, then expanded (paths with spaces stay one argument).
std::vector<std::string> split_args(const std::string& args, const std::string& tmp) {
  std::vector<std::string> out;
  std::istringstream in(args);
  std::string word;
  while (in >> word) out.push_back(expand(word, tmp));
  return out;
}

/// Every path under `dir`, relative to it.
std::set<std::string> tree(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    out.insert(fs::relative(e.path(), dir).string());
  return out;
}

/// Lines of `text` without the final newline; a trailing empty piece is not a line.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

class Robustness : public ::testing::TestWithParam<RobustnessCase> {};

TEST_P(Robustness, EndsCleanlyWithOneLineAndNoOutput) {
  const RobustnessCase& c = GetParam();
  if (c.skip_as_root && ::geteuid() == 0)
    GTEST_SKIP() << "running as root: permission bits do not stop root from writing";
  const test::TempDir scratch;
  const fs::path work = scratch.path / "work", capture = scratch.path / "capture";
  fs::create_directories(work);
  fs::create_directories(capture);
  for (const std::string& d : c.setup_dirs) fs::create_directories(work / d);
  for (const std::string& f : c.setup_files) std::ofstream(work / f) << "not a mesh\n";
  for (const std::string& d : c.setup_readonly_dirs) {
    fs::create_directories(work / d);
    fs::permissions(work / d, fs::perms::owner_read | fs::perms::owner_exec);
  }
  const std::set<std::string> before = tree(work);
  const std::vector<std::string> args = split_args(c.args, work.string());
  std::string command = "cordgrasp";
  for (const std::string& a : args) command += " " + a;
  SCOPED_TRACE(command);

  const test::ProcessResult r = test::run_cordgrasp_argv(args, work.string(), capture.string());
  const std::string printed = "\nstderr:\n" + r.err + "stdout:\n" + r.out;
  EXPECT_FALSE(r.signaled) << "ended by signal " << r.signal << printed;
  ASSERT_TRUE(r.exited) << printed;
  EXPECT_EQ(r.exit_code, c.exit_code) << printed;

  const std::vector<std::string> lines = lines_of(r.err);
  EXPECT_EQ(static_cast<int>(lines.size()), c.stderr_lines) << printed;
  for (const std::string& line : lines) EXPECT_FALSE(line.empty()) << "an empty line" << printed;
  if (!c.stderr_regex.empty() && !lines.empty())
    EXPECT_TRUE(std::regex_search(lines.back(), std::regex(c.stderr_regex)))
        << "last stderr line does not match /" << c.stderr_regex << "/" << printed;
  if (!c.stdout_regex.empty())
    EXPECT_TRUE(std::regex_search(r.out, std::regex(c.stdout_regex)))
        << "stdout does not match /" << c.stdout_regex << "/" << printed;

  for (const std::string& a : c.absent) {
    const fs::path p = expand(a, work.string());
    EXPECT_FALSE(fs::exists(p.is_absolute() ? p : work / p)) << a << " was written" << printed;
  }
  for (const std::string& f : c.finite) {
    ASSERT_TRUE(fs::exists(work / f)) << f << " was not written" << printed;
    std::vector<std::string> nulls;
    undocumented_nulls(test::read_json((work / f).string()), f, "", &nulls);
    for (const std::string& at : nulls) ADD_FAILURE() << "NaN or infinity at " << at << printed;
  }
  std::set<std::string> allowed = before;
  for (const std::string& m : c.may_write) allowed.insert(m);
  for (const std::string& p : tree(work))
    EXPECT_TRUE(allowed.count(p)) << "wrote " << p << " in the scratch folder" << printed;
  for (const std::string& d : c.setup_readonly_dirs)  // so that TempDir can remove it
    fs::permissions(work / d, fs::perms::owner_all);
}

INSTANTIATE_TEST_SUITE_P(Cases, Robustness, ::testing::ValuesIn(load_cases()),
                         [](const ::testing::TestParamInfo<RobustnessCase>& info) {
                           return info.param.id;
                         });

}  // namespace
}  // namespace cordgrasp
