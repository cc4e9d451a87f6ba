// Numeric options are checked when parsed: NaN, infinities, out-of-range values and malformed
// seeds are refused with "--name: <value> is not <rule>", a non-zero exit (not a signal) and
// no output file.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "test_files.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

struct BadOption {
  std::string command;   ///< subcommand and options, before --out
  std::string message;   ///< expected in the output
};

constexpr int kFirstSignalExitCode = 128;  ///< the shell reports a signal as 128 + signal

TEST(CliOptionChecks, BadNumbersAndSeedsAreRefusedByNameWithoutOutput) {
  const test::TempDir dir;
  const std::string out = dir.file("out.json");
  const std::string plan = dir.file("missing_plan.json");  // the options fail before it is read
  const std::vector<BadOption> cases = {
      {"plan --mu nan", "--mu: nan is not a finite number in [0, 10]"},
      {"plan --grasps 0", "--grasps: 0 is not a whole number"},
      {"plan --seed -1", "--seed: -1 is not a whole number in [0, 18446744073709551615]"},
      {"plan --seed 18446744073709551616", "--seed: 18446744073709551616 is not"},
      {"plan --seed 1e23", "--seed: 1e23 is not a whole number"},
      {"run --mu inf --out-dir " + dir.file("run"), "--mu: inf is not a finite number"},
      {"validate --plan " + plan + " --mu -1", "--mu: -1 is not a finite number"},
      {"validate --plan " + plan + " --mu nan", "--mu: nan is not a finite number"},
      {"validate --plan " + plan + " --trials 0", "--trials: 0 is not a whole number in [1, 1000]"},
      {"validate --plan " + plan + " --mass 0", "--mass: 0 is not a finite number in [1e-06, 10000]"},
      {"plan --validate fast", "--validate: fast is not one of"},
      {"validate --plan " + plan + " --seed 2.5", "--seed: 2.5 is not a whole number"},
      {"explore --object box.obj --seed -3 --json", "--seed: -3 is not"},
  };
  for (const BadOption& c : cases) {
    // plan and validate write --out, explore --json OUT, run its --out-dir.
    const bool starts_run = c.command.rfind("run", 0) == 0;
    const bool ends_json =
        c.command.size() >= 6 && c.command.compare(c.command.size() - 6, 6, "--json") == 0;
    const auto r = test::run_cordgrasp(c.command + (starts_run ? "" : ends_json ? " " + out
                                                                                : " --out " + out));
    EXPECT_NE(r.exit_code, 0) << c.command << "\n" << r.output;
    EXPECT_LT(r.exit_code, kFirstSignalExitCode) << c.command << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.command << "\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.command;
    EXPECT_FALSE(std::filesystem::exists(dir.file("run"))) << c.command;
  }
}

}  // namespace
}  // namespace cordgrasp
