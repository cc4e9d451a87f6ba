// report.html of `cordgrasp run`: the page, the trace plot and the 3D viewer's files, from
// hand-made reports (tests/browser opens a real one in Chromium).
#include "cordgrasp/jobs/run_report_html.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/shapes.h"
#include "cordgrasp/jobs/report_viewer.h"
#include "cordgrasp/jobs/run_job.h"
#include "cordgrasp/jobs/trace_plot_svg.h"
#include "test_files.h"
#include "test_hands.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;
using test::read_text;
using test::TempDir;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

PhaseResult phase(const std::string& name, Outcome outcome, const std::string& detail = "") {
  PhaseResult p;
  p.name = name;
  p.outcome = outcome;
  p.detail = detail;
  return p;
}

TraceSample sample(const std::string& phase, double t_s, double shift_m, double turn_rad,
                   bool end = false) {
  TraceSample s;
  s.phase = phase;
  s.phase_end = end;
  s.sim_time_s = t_s;
  s.object_shift_m = shift_m;
  s.object_turn_rad = turn_rad;
  s.contacts = 2;
  return s;
}

/// settle, close, lift, shake (two segments), 0.1 s apart; the object slips in shake y.
std::vector<TraceSample> slipping_trace() {
  return {sample("settle", 0.0, 0.0, 0.0),   sample("settle", 0.1, 0.0001, 0.0, true),
          sample("close", 0.2, 0.001, 0.01), sample("close", 0.3, 0.002, 0.02, true),
          sample("lift", 0.4, 0.0005, 0.0),  sample("lift", 0.5, 0.001, 0.01, true),
          sample("shake", 0.6, 0.002, 0.02), sample("shake x", 0.7, 0.003, 0.03, true),
          sample("shake", 0.8, 0.008, 0.1),  sample("shake y", 0.9, 0.012, 0.2, true)};
}

SimResult slipped_in_shake() {
  SimResult r;
  r.outcome = Outcome::kSlipped;
  r.phases = {phase("settle", Outcome::kHeld), phase("close", Outcome::kHeld),
              phase("lift", Outcome::kHeld), phase("shake", Outcome::kSlipped, "shake y")};
  r.phases[1].translation_m = 0.0021;
  return r;
}

/// Two grasps: 0 held, 1 slipped in shake; pictures, animation and trace for grasp 1 only.
RunReport two_grasp_report() {
  RunReport rep;
  rep.plan.object_name = "mug";
  rep.plan.hand_name = "cordgrasp_sah";
  rep.plan.grasps.resize(2);
  rep.plan.grasps[0].alpha_rad = 0.123;
  rep.plan.grasps[1].epsilon = 0.0456;
  SimDocument sim;
  SimResult held;
  held.outcome = Outcome::kHeld;
  held.phases = {phase("settle", Outcome::kHeld), phase("close", Outcome::kHeld),
                 phase("lift", Outcome::kHeld), phase("shake", Outcome::kHeld)};
  sim.results = {held, slipped_in_shake()};
  sim.grasp_indices = {0, 1};
  rep.sim = sim;
  rep.pictures.resize(2);
  rep.pictures[0].planned = "grasp_0.png";
  rep.pictures[1].planned = "grasp_1.png";
  rep.pictures[1].snapshots = {"grasp_1_physics.png"};
  rep.pictures[1].animation = "grasp_1.webp";
  rep.pictures[1].trace = slipping_trace();
  rep.sheet = "grasps.png";
  return rep;
}

ReportViewer two_models() {
  ReportViewer v;
  v.scripts_dir = kViewerDir;
  v.models = {"grasp_0", "grasp_1"};
  return v;
}

TEST(RunReportHtml, RefersOnlyToFilesInItsFolder) {
  const std::string html = run_report_html(two_grasp_report(), two_models());
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  const std::regex ref(R"((src|href)="([^"]*)\")");
  int refs = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), ref); it != std::sregex_iterator();
       ++it, ++refs) {
    const std::string target = (*it)[2];
    EXPECT_FALSE(target.empty());
    EXPECT_EQ(target.find(':'), std::string::npos) << target;  // no scheme
    EXPECT_NE(target[0], '/') << target;                       // relative
    EXPECT_EQ(target.find(".."), std::string::npos) << target;
  }
  EXPECT_GT(refs, 10);
}

TEST(RunReportHtml, TableGivesEachPhaseOutcomeTheShiftWhileClosingAndHeld) {
  const std::string html = run_report_html(two_grasp_report());
  EXPECT_NE(html.find("<th>close</th><th>lift</th><th>shake</th>"), std::string::npos) << html;
  EXPECT_EQ(html.find("<th>settle</th>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"slipped\">slipped (shake y)</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">2.1</td><td class=\"dropped\">no</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td class=\"held\">yes</td>"), std::string::npos);
  EXPECT_NE(html.find("0.123"), std::string::npos);
  EXPECT_NE(html.find("0.0456"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"#grasp-1\">grasp 1</a>"), std::string::npos);
  EXPECT_NE(html.find("id=\"grasp-1\""), std::string::npos);
}

TEST(RunReportHtml, ShowsPicturesAnimationPlotAnd3DViewWhereTheyExist) {
  const std::string html = run_report_html(two_grasp_report(), two_models());
  EXPECT_NE(html.find("src=\"grasp_0.png\""), std::string::npos);
  EXPECT_NE(html.find("src=\"grasp_1_physics.png\""), std::string::npos);
  EXPECT_NE(html.find("src=\"grasps.png\""), std::string::npos);
  EXPECT_EQ(count(html, "class=\"animation\" src=\"grasp_1.webp\""), 1);
  EXPECT_EQ(count(html, "<svg class=\"trace\""), 1);  // grasp 0 has no trace
  EXPECT_EQ(count(html, "class=\"viewer\" data-model="), 2);
  EXPECT_NE(html.find("<script src=\"viewer/three.min.js\"></script>"), std::string::npos);
  EXPECT_NE(html.find("<script src=\"viewer/GLTFLoader.js\"></script>"), std::string::npos);
  EXPECT_NE(html.find("<script src=\"viewer/OrbitControls.js\"></script>"), std::string::npos);
  EXPECT_NE(html.find("<script src=\"grasp_1.glb.js\"></script>"), std::string::npos);
  EXPECT_NE(html.find("href=\"viewer/copyright\""), std::string::npos);
}

TEST(RunReportHtml, WithoutAnimationTraceOrModelsItIsStillAWholePage) {
  RunReport rep = two_grasp_report();
  rep.pictures[1].animation.clear();
  rep.pictures[1].trace.clear();
  const std::string html = run_report_html(rep);
  EXPECT_EQ(html.find("<svg"), std::string::npos);
  EXPECT_EQ(html.find("class=\"animation\""), std::string::npos);
  EXPECT_EQ(html.find("class=\"viewer\""), std::string::npos);
  EXPECT_EQ(html.find("three.min.js"), std::string::npos);
  EXPECT_EQ(html.rfind("</html>\n"), html.size() - 8);
  EXPECT_NE(html.find("id=\"selftest\""), std::string::npos);  // the self-test still runs
}

TEST(RunReportHtml, SaysWhyThe3DViewIsUnavailable) {
  ReportViewer viewer;
  viewer.unavailable = "report viewer: three.js '/nowhere/three.min.js' is missing";
  const std::string html = run_report_html(two_grasp_report(), viewer);
  EXPECT_NE(html.find("3D view unavailable: report viewer: three.js '/nowhere/three.min.js'"),
            std::string::npos);
  EXPECT_EQ(html.find("class=\"viewer\""), std::string::npos);
}

TEST(RunReportHtml, EscapesNamesAndSaysWhenInterrupted) {
  RunReport rep = two_grasp_report();
  rep.plan.object_name = "<b>cup & \"saucer\"</b>";
  rep.interrupted = "SIGINT";
  rep.interrupted_at = "rendering, after 2 of 3 grasps";
  const std::string html = run_report_html(rep);
  EXPECT_EQ(html.find("<b>cup"), std::string::npos);
  EXPECT_NE(html.find("&lt;b&gt;cup &amp; &quot;saucer&quot;&lt;/b&gt;"), std::string::npos);
  EXPECT_NE(html.find("interrupted by SIGINT during rendering, after 2 of 3 grasps"),
            std::string::npos);
}

TEST(RunReportHtml, NoGraspGivesAPageWithoutTable) {
  RunReport rep;
  rep.plan.object_name = "box";
  const std::string html = run_report_html(rep);
  EXPECT_NE(html.find("<strong>No grasp</strong>"), std::string::npos);
  EXPECT_EQ(html.find("class=\"verdicts\""), std::string::npos);
  EXPECT_EQ(html.rfind("</html>\n"), html.size() - 8);
}

TEST(TracePlotSvg, EmptyTraceGivesNoPlot) { EXPECT_EQ(trace_plot_svg({}, nullptr), ""); }

TEST(TracePlotSvg, ShadesAndNamesEachPhaseOnceWithSegmentsInTheirPhase) {
  const std::string svg = trace_plot_svg(slipping_trace(), nullptr);
  EXPECT_EQ(count(svg, "class=\"phase\""), 4);
  for (const char* name : {">settle<", ">close<", ">lift<", ">shake<"})
    EXPECT_EQ(count(svg, name), 1) << name;
  EXPECT_EQ(svg.find("shake x"), std::string::npos);
  // One curve of each quantity per phase: the reference pose changes between phases.
  EXPECT_EQ(count(svg, "class=\"shift\""), 4);
  EXPECT_EQ(count(svg, "class=\"turn\""), 4);
  EXPECT_NE(svg.find("shift [mm]"), std::string::npos);
  EXPECT_NE(svg.find("turn [°]"), std::string::npos);
  EXPECT_NE(svg.find("simulated time [s]"), std::string::npos);
}

TEST(TracePlotSvg, TimeTicksAreRoundNumbers) {
  std::vector<TraceSample> trace = slipping_trace();
  for (TraceSample& s : trace) s.sim_time_s += 0.0197917;  // the first sample after a step
  const std::string svg = trace_plot_svg(trace, nullptr);
  EXPECT_EQ(svg.find("0.0197917"), std::string::npos) << svg;
  for (const char* tick : {">0.2</text>", ">0.4</text>", ">0.6</text>", ">0.8</text>"})
    EXPECT_NE(svg.find(tick), std::string::npos) << tick;
}

TEST(TracePlotSvg, EveryPointLiesInsideThePlotArea) {
  TracePlotParams size;
  const std::string svg = trace_plot_svg(slipping_trace(), nullptr, size);
  const std::regex points("points=\"([^\"]*)\"");
  const std::regex pair(R"(([-0-9.]+),([-0-9.]+))");
  int n = 0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), points); it != std::sregex_iterator();
       ++it) {
    const std::string list = (*it)[1];
    for (auto p = std::sregex_iterator(list.begin(), list.end(), pair); p != std::sregex_iterator();
         ++p, ++n) {
      const double x = std::stod((*p)[1]), y = std::stod((*p)[2]);
      EXPECT_GE(x, 0.0);
      EXPECT_LE(x, size.width_px);
      EXPECT_GE(y, 0.0);
      EXPECT_LE(y, size.height_px);
    }
  }
  EXPECT_EQ(n, 2 * 10);
}

TEST(TracePlotSvg, MarksTheEndOfTheFailedPhaseOnlyWhenTheGraspFailed) {
  const SimResult slipped = slipped_in_shake();
  const std::string svg = trace_plot_svg(slipping_trace(), &slipped);
  EXPECT_EQ(count(svg, "class=\"failure\""), 1);
  EXPECT_NE(svg.find(">slipped in shake (shake y)</text>"), std::string::npos) << svg;
  // At the last sample's time: the right edge of the plot (the time axis ends there).
  const std::smatch m = [&] {
    std::smatch found;
    std::regex_search(svg, found, std::regex("class=\"failure\" x1=\"([0-9.]+)\""));
    return found;
  }();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(std::stod(m[1]), TracePlotParams{}.width_px - 56.0, 0.1);

  SimResult held = slipped;
  held.outcome = Outcome::kHeld;
  held.phases.back().outcome = Outcome::kHeld;
  EXPECT_EQ(trace_plot_svg(slipping_trace(), &held).find("failure"), std::string::npos);
}

TEST(ReportViewer, MissingScriptIsNamedAndNothingIsWritten) {
  const TempDir dir;
  ViewerSources sources = default_viewer_sources();
  sources.gltf_loader_js = dir.file("nowhere/GLTFLoader.js");
  try {
    write_viewer_scripts(dir.path.string(), sources);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nowhere/GLTFLoader.js' is missing"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir.path / kViewerDir));
}

TEST(ReportViewer, CopiesDebiansThreeJsAndItsLicence) {
  const ViewerSources sources = default_viewer_sources();
  if (!fs::exists(sources.three_js) || !fs::exists(sources.licence))
    GTEST_SKIP() << "libjs-three is not installed (" << sources.three_js << ")";
  const TempDir dir;
  write_viewer_scripts(dir.path.string(), sources);
  for (const char* f : {"three.min.js", "GLTFLoader.js", "OrbitControls.js", "copyright"})
    EXPECT_GT(fs::file_size(dir.path / kViewerDir / f), 1000u) << f;
  EXPECT_EQ(read_text((dir.path / kViewerDir / "copyright").string()), read_text(sources.licence));
  // The non-module builds: they define globals, which file:// pages can load.
  EXPECT_NE(read_text((dir.path / kViewerDir / "GLTFLoader.js").string()).find("global.THREE"),
            std::string::npos);
}

/// Decodes standard base64 (no line breaks).
std::string from_base64(const std::string& text) {
  const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned v = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    v = (v << 6) | static_cast<unsigned>(digits.find(c));
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((v >> bits) & 0xFFu);
    }
  }
  return out;
}

TEST(ReportViewer, ModelScriptHoldsTheGlbBytes) {
  const TempDir dir;
  const HandModel hand = test::make_parallel_gripper();
  Grasp grasp;
  grasp.q = Eigen::VectorXd::Zero(static_cast<int>(hand.joints.size()));
  grasp.X_OB.translation() = Eigen::Vector3d(0, 0, -0.1);
  write_grasp_model_script(dir.path.string(), "grasp_0", hand, grasp,
                           make_box_mesh(Eigen::Vector3d(0.05, 0.05, 0.1)));
  const std::string glb = read_text(dir.file("grasp_0.glb"));
  ASSERT_GT(glb.size(), 100u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  const std::string script = read_text(dir.file("grasp_0.glb.js"));
  const std::string key = "window.cordgraspModels[\"grasp_0\"] = \"";
  const size_t at = script.find(key);
  ASSERT_NE(at, std::string::npos) << script.substr(0, 200);
  const size_t begin = at + key.size(), end = script.find('"', begin);
  EXPECT_EQ(from_base64(script.substr(begin, end - begin)), glb);
  for (const auto& entry : fs::directory_iterator(dir.path))  // no scratch file left
    EXPECT_NE(entry.path().filename().string()[0], '.') << entry.path();
}

TEST(RunJobHtml, WithoutThreeJsTheRunSucceedsAndTheReportSaysWhichFileIsMissing) {
  const TempDir dir;
  RunParams p;
  p.hand = "parallel_gripper";
  p.object = "box";
  p.job.plan.grasps = 1;
  p.validate = false;
  p.picture.size = "160x120";
  p.out_dir = dir.path.string();
  p.viewer.three_js = dir.file("nowhere/three.min.js");
  std::vector<std::string> progress;
  const RunOutcome out = run_job(p, [&](const std::string& line) { progress.push_back(line); });
  ASSERT_EQ(out.html_path, dir.file("report.html"));
  const std::string html = read_text(out.html_path);
  EXPECT_NE(html.find("3D view unavailable: report viewer: three.js '" +
                      dir.file("nowhere/three.min.js") + "' is missing"),
            std::string::npos)
      << html;
  EXPECT_EQ(html.find("class=\"viewer\""), std::string::npos);
  EXPECT_NE(html.find("src=\"grasp_0.png\""), std::string::npos);
  EXPECT_FALSE(fs::exists(dir.path / kViewerDir));
  EXPECT_FALSE(fs::exists(dir.path / "grasp_0.glb"));
  EXPECT_TRUE(std::any_of(progress.begin(), progress.end(), [](const std::string& line) {
    return line.find("no 3D view in report.html") != std::string::npos;
  }));
}

}  // namespace
}  // namespace cordgrasp
