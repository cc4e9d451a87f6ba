// SIGINT stops `validate`, `bench`, `run` and `plan` cleanly: exit 130 (not killed by the
// signal), the finished part written with "complete": false and "interrupted": "SIGINT", no
// temporary file left; a run to its end writes "complete": true; a second SIGINT kills at once.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "cordgrasp/jobs/bench_job.h"
#include "test_files.h"
#include "test_paths.h"

extern char** environ;

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::read_json;
using test::read_text;
using test::run_cordgrasp;
using test::source_dir;
using test::TempDir;

constexpr double kWaitForProgress_s = 15.0;  ///< longest wait for the progress line

/// A cordgrasp process started with its stderr on a pipe and its stdout in a file.
class Child {
 public:
  Child(const std::vector<std::string>& args, const std::string& stdout_path) {
    int fds[2];
    if (pipe(fds) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, stdout_path.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<std::string> argv_text = {CORDGRASP_EXE};
    argv_text.insert(argv_text.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : argv_text) argv.push_back(a.data());
    argv.push_back(nullptr);
    // The child starts with the default SIGINT action whatever this process does with it.
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    sigaddset(&defaults, SIGTERM);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
    if (posix_spawn(&pid_, CORDGRASP_EXE, &actions, &attr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    close(fds[1]);
    err_ = fds[0];
  }
  ~Child() {
    if (pid_ > 0 && !reaped_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (err_ >= 0) close(err_);
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  bool started() const { return pid_ > 0; }

  /// Reads stderr until a line holding `needle` has arrived (true) or the process closed it or
  /// kWaitForProgress_s passed (false).
  bool wait_for(const std::string& needle) {
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration<double>(kWaitForProgress_s);
    while (stderr_.find(needle) == std::string::npos) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return false;
      pollfd p{err_, POLLIN, 0};
      if (poll(&p, 1, static_cast<int>(left.count())) <= 0) return false;
      char buf[4096];
      const ssize_t n = read(err_, buf, sizeof buf);
      if (n <= 0) return false;
      stderr_.append(buf, static_cast<size_t>(n));
    }
    // The whole line: the progress callback has returned once its newline is out.
    const size_t at = stderr_.find(needle);
    while (stderr_.find('\n', at) == std::string::npos) {
      char buf[256];
      const ssize_t n = read(err_, buf, sizeof buf);
      if (n <= 0) break;
      stderr_.append(buf, static_cast<size_t>(n));
    }
    return true;
  }

  void signal(int signal_number) const { kill(pid_, signal_number); }

  /// Reads stderr to its end and waits for the process; returns its wait status.
  int wait() {
    char buf[4096];
    for (ssize_t n; (n = read(err_, buf, sizeof buf)) > 0;)
      stderr_.append(buf, static_cast<size_t>(n));
    int status = 0;
    waitpid(pid_, &status, 0);
    reaped_ = true;
    return status;
  }

  const std::string& stderr_text() const { return stderr_; }

 private:
  pid_t pid_ = -1;
  int err_ = -1;
  bool reaped_ = false;
  std::string stderr_;
};


/// Files in `dir` (recursively) that look temporary: "*.tmp" anywhere in the name.
std::vector<std::string> temp_files(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(".tmp") != std::string::npos)
      out.push_back(e.path().string());
  return out;
}

/// Exit status 130 from exit(), not death by a signal.
void expect_interrupted_exit(int status, const Child& child) {
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status) << "\n"
                                 << child.stderr_text();
  EXPECT_EQ(WEXITSTATUS(status), 130) << child.stderr_text();
  EXPECT_NE(child.stderr_text().find("cordgrasp: interrupted by SIGINT"), std::string::npos)
      << child.stderr_text();
}

std::string object(const std::string& name) {
  return source_dir() + "/assets/objects/" + name + ".obj";
}

/// Three force-closure grasps of the shipped box with the parallel gripper (generic planner).
void write_box_plan(const std::string& path) {
  const auto r = run_cordgrasp("plan --hand parallel_gripper --object box --planner generic "
                               "--grasps 3 -q --out " + quoted(path));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json plan = read_json(path);
  ASSERT_EQ(plan.at("grasps").size(), 3u);
  EXPECT_EQ(plan.at("complete"), true);  // ran to its end
  EXPECT_FALSE(plan.contains("interrupted"));
}

TEST(CliInterrupt, ValidateStopsBetweenTrialsAndKeepsTheGraspsWithEveryTrial) {
  TempDir dir;
  write_box_plan(dir.file("plan.json"));
  Child child({"validate", "--plan", dir.file("plan.json"), "--tests", "lift", "--trials", "20",
               "--out", dir.file("sim.json")},
              dir.file("stdout.txt"));
  ASSERT_TRUE(child.started());
  ASSERT_TRUE(child.wait_for("validate: trials of 1/3 grasps")) << child.stderr_text();
  child.signal(SIGINT);
  expect_interrupted_exit(child.wait(), child);
  const nlohmann::json sim = read_json(dir.file("sim.json"));
  EXPECT_EQ(sim.at("complete"), false);
  EXPECT_EQ(sim.at("interrupted"), "SIGINT");
  // Grasp 0 had all its trials; the one in flight lost its remaining trials and is left out.
  ASSERT_GE(sim.at("grasps").size(), 1u);
  EXPECT_LT(sim.at("grasps").size(), 3u);
  EXPECT_EQ(sim.at("summary").at("grasps"), sim.at("grasps").size());
  EXPECT_EQ(sim.at("parameters").at("trials"), 20);
  for (const auto& g : sim.at("grasps")) EXPECT_EQ(g.at("trials").at("count"), 20);
  EXPECT_EQ(sim.at("grasps").at(0).at("index"), 0);
  const std::string out = read_text(dir.file("stdout.txt"));
  EXPECT_NE(out.find("interrupted by SIGINT after " + std::to_string(sim.at("grasps").size()) +
                     " of 3 grasps"),
            std::string::npos)
      << out;
  EXPECT_EQ(temp_files(dir.path), std::vector<std::string>{});

  // A validation that runs to its end says so.
  const auto r = run_cordgrasp("validate --plan " + quoted(dir.file("plan.json")) +
                               " --tests lift -q --out " + quoted(dir.file("all.json")));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json all = read_json(dir.file("all.json"));
  EXPECT_EQ(all.at("complete"), true);
  EXPECT_FALSE(all.contains("interrupted"));
}

TEST(CliInterrupt, SecondSigintEndsTheProcessAtOnce) {
  TempDir dir;
  write_box_plan(dir.file("plan.json"));
  // The thorough protocol simulates each grasp for about 0.5 s (idle machine): both signals
  // come within 0.15 s of the grasp's start, while it still runs; the second kills the process
  // before it writes anything.
  Child child({"validate", "--plan", dir.file("plan.json"), "--protocol", "thorough", "--out",
               dir.file("sim.json")},
              dir.file("stdout.txt"));
  ASSERT_TRUE(child.started());
  ASSERT_TRUE(child.wait_for("validate: 1/3 grasps")) << child.stderr_text();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // grasp 1 has started
  child.signal(SIGINT);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  child.signal(SIGINT);
  const int status = child.wait();
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << WEXITSTATUS(status) << "\n"
                                   << child.stderr_text();
  EXPECT_EQ(WTERMSIG(status), SIGINT);
  EXPECT_FALSE(fs::exists(dir.file("sim.json")));
  EXPECT_EQ(temp_files(dir.path), std::vector<std::string>{});
}

TEST(CliInterrupt, BenchKeepsTheFinishedRowsAndMarksBenchJsonIncomplete) {
  TempDir dir;
  const fs::path out = dir.path / "bench";
  // The bottle takes seconds (planning and physics): it is in flight when the signal comes.
  Child child({"bench", "--hands", "parallel_gripper", "--objects", object("box"),
               object("sphere"), object("bottle"), object("mug"), object("long_cylinder"),
               "--planners", "generic", "--tests", "lift", "--out-dir", out.string()},
              dir.file("stdout.txt"));
  ASSERT_TRUE(child.started());
  ASSERT_TRUE(child.wait_for("bench: 2/5")) << child.stderr_text();
  child.signal(SIGINT);
  expect_interrupted_exit(child.wait(), child);
  const nlohmann::json meta = read_json((out / "bench.json").string());
  EXPECT_EQ(meta.at("complete"), false);
  EXPECT_EQ(meta.at("interrupted"), "SIGINT");
  const std::vector<BenchRow> rows =
      parse_bench_csv(read_text((out / "results.csv").string()), "results.csv");
  ASSERT_GE(rows.size(), 2u);
  EXPECT_LT(rows.size(), 5u);
  EXPECT_EQ(meta.at("attempts"), rows.size());
  EXPECT_EQ(meta.at("attempts_total"), 5);
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].attempt, static_cast<int>(i));  // one thread: a prefix, in order
    EXPECT_EQ(rows[i].status, "ok") << rows[i].error;
  }
  const std::string k = std::to_string(rows.size());
  const std::string summary = read_text((out / "summary.md").string());
  EXPECT_NE(summary.find("interrupted by SIGINT after " + k + " of 5 attempts"),
            std::string::npos)
      << summary;
  const std::string stdout_text = read_text(dir.file("stdout.txt"));
  EXPECT_NE(stdout_text.find("interrupted by SIGINT after " + k + " of 5 attempts"),
            std::string::npos)
      << stdout_text;
  EXPECT_FALSE(fs::exists(out / "sheets"));  // no contact sheets of a partial bench
  EXPECT_EQ(temp_files(dir.path), std::vector<std::string>{});
}

TEST(CliInterrupt, BenchRunToItsEndIsComplete) {
  TempDir dir;
  const auto r = run_cordgrasp("bench --hands parallel_gripper --objects " +
                               quoted(object("box")) +
                               " --planners generic --tests none --no-sheets -q --out-dir " +
                               quoted(dir.file("bench")));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json meta = read_json(dir.file("bench/bench.json"));
  EXPECT_EQ(meta.at("complete"), true);
  EXPECT_FALSE(meta.contains("interrupted"));
  EXPECT_EQ(read_text(dir.file("bench/summary.md")).find("interrupted"), std::string::npos);
}

TEST(CliInterrupt, RunStopsAfterTheGraspInFlightAndSaysSoInTheReport) {
  TempDir dir;
  const fs::path out = dir.path / "run";
  Child child({"run", "--hand", "parallel_gripper", "--object", "box", "--grasps", "3",
               "--no-validate", "--tests", "lift", "--out-dir",
               out.string()},
              dir.file("stdout.txt"));
  ASSERT_TRUE(child.started());
  ASSERT_TRUE(child.wait_for("physics: grasp 1/")) << child.stderr_text();
  child.signal(SIGINT);
  expect_interrupted_exit(child.wait(), child);
  // Planning had finished: plan.json is complete; physics or rendering was cut short.
  const nlohmann::json plan = read_json((out / "plan.json").string());
  EXPECT_EQ(plan.at("complete"), true);
  const nlohmann::json sim = read_json((out / "sim.json").string());
  const std::string report = read_text((out / "report.md").string());
  EXPECT_NE(report.find("**Incomplete: interrupted by SIGINT during "), std::string::npos)
      << report;
  const std::string html = read_text((out / "report.html").string());
  EXPECT_NE(html.find("<strong>Incomplete: interrupted by SIGINT during "), std::string::npos)
      << html;
  if (sim.at("complete") == false) {
    EXPECT_EQ(sim.at("interrupted"), "SIGINT");
    EXPECT_LT(sim.at("grasps").size(), plan.at("grasps").size());
    EXPECT_NE(report.find("during physics, after " + std::to_string(sim.at("grasps").size()) +
                          " of " + std::to_string(plan.at("grasps").size()) + " grasps"),
              std::string::npos)
        << report;
  } else {
    EXPECT_NE(report.find("during rendering"), std::string::npos) << report;
  }
  const std::string stdout_text = read_text(dir.file("stdout.txt"));
  EXPECT_NE(stdout_text.find("run: interrupted by SIGINT during "), std::string::npos)
      << stdout_text;
  EXPECT_FALSE(fs::exists(out / "grasps.png"));  // no contact sheet of a partial run
  EXPECT_EQ(temp_files(dir.path), std::vector<std::string>{});
}

TEST(CliInterrupt, PlanStopsBeforeTheNextAttemptAndWritesTheGraspsFound) {
  TempDir dir;
  // 200 grasps of the mug take several seconds; the signal comes after one.
  const std::string settings = dir.file("many_attempts.yaml");
  std::ofstream(settings) << "max_attempts: 100000\n";
  Child child({"plan", "--object", "mug", "--planner", "generic", "--grasps", "200",
               "--settings", settings, "--out", dir.file("plan.json")},
              dir.file("stdout.txt"));
  ASSERT_TRUE(child.started());
  std::this_thread::sleep_for(std::chrono::seconds(1));
  child.signal(SIGINT);
  expect_interrupted_exit(child.wait(), child);
  const nlohmann::json plan = read_json(dir.file("plan.json"));
  EXPECT_EQ(plan.at("complete"), false);
  EXPECT_EQ(plan.at("interrupted"), "SIGINT");
  EXPECT_LT(plan.at("grasps").size(), 200u);
  const std::string stdout_text = read_text(dir.file("stdout.txt"));
  EXPECT_NE(stdout_text.find("plan: interrupted by SIGINT after " +
                             std::to_string(plan.at("grasps").size()) + " of 200 grasps"),
            std::string::npos)
      << stdout_text;
  EXPECT_EQ(temp_files(dir.path), std::vector<std::string>{});
  // validate reads an incomplete plan (its grasps are whole).
  if (!plan.at("grasps").empty()) {
    const auto r = run_cordgrasp("validate --plan " + quoted(dir.file("plan.json")) +
                                 " --tests lift -q --out " + quoted(dir.file("sim.json")));
    EXPECT_EQ(r.exit_code, 0) << r.output;
  }
}

}  // namespace
}  // namespace cordgrasp
