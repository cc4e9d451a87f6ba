#include "cordgrasp/jobs/bench_job.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <functional>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/parallel_for.h"
#include "cordgrasp/jobs/bench_report_html.h"
#include "cordgrasp/jobs/physics_settings.h"
#include "cordgrasp/jobs/sim_json.h"
#include "cordgrasp/jobs/text_format.h"
#include "cordgrasp/jobs/validated_plan_job.h"
#include "params_json.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

// Quantities: 9 significant digits (exact enough to compare runs); times: microseconds.
std::string number(double v) { return format_number(v, "%.9g"); }
std::string seconds(double v) { return format_number(v, "%.6f"); }
std::string optional_number(const std::optional<double>& v) { return v ? number(*v) : ""; }
std::string optional_seconds(const std::optional<double>& v) { return v ? seconds(*v) : ""; }
std::string optional_count(const std::optional<int>& v) { return v ? std::to_string(*v) : ""; }

std::string csv_quote(const std::string& cell) {
  if (cell.find_first_of(",\"\n\r") == std::string::npos) return cell;
  std::string out = "\"";
  for (char c : cell) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

// RFC 4180 records (quoted cells may hold commas, quotes and newlines).
std::vector<std::vector<std::string>> parse_csv_records(const std::string& text,
                                                        const std::string& what) {
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> record;
  std::string cell;
  bool quoted = false, any = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cell += c;
      }
      continue;
    }
    if (c == '"') {
      quoted = true;
      any = true;
    } else if (c == ',') {
      record.push_back(cell);
      cell.clear();
      any = true;
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      if (any || !cell.empty()) {
        record.push_back(cell);
        records.push_back(record);
      }
      record.clear();
      cell.clear();
      any = false;
    } else {
      cell += c;
      any = true;
    }
  }
  if (quoted) throw InputError(what + ": unterminated quoted cell");
  if (any || !cell.empty()) {
    record.push_back(cell);
    records.push_back(record);
  }
  return records;
}

double parse_double(const std::string& s, const std::string& what) {
  try {
    size_t used = 0;
    const double v = std::stod(s, &used);
    if (used != s.size()) throw std::invalid_argument("trailing text");
    return v;
  } catch (const std::exception&) {
    throw InputError(what + ": '" + s + "' is not a number");
  }
}

long long parse_integer(const std::string& s, const std::string& what) {
  try {
    size_t used = 0;
    const long long v = std::stoll(s, &used);
    if (used != s.size()) throw std::invalid_argument("trailing text");
    return v;
  } catch (const std::exception&) {
    throw InputError(what + ": '" + s + "' is not an integer");
  }
}

std::optional<double> parse_optional_double(const std::string& s, const std::string& what) {
  if (s.empty()) return std::nullopt;
  return parse_double(s, what);
}

bool is_mesh_file(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) {
    return static_cast<char>(std::tolower(c));
  });
  return ext == ".obj" || ext == ".stl" || ext == ".ply" || ext == ".off";
}

// Mean, sample SD (0 for one value), median.
struct Stats {
  int n = 0;
  double mean = 0.0, sd = 0.0, median = 0.0;
};

Stats stats_of(std::vector<double> v) {
  Stats s;
  s.n = static_cast<int>(v.size());
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  double sum = 0.0;
  for (double x : v) sum += x;
  s.mean = sum / s.n;
  double ss = 0.0;
  for (double x : v) ss += (x - s.mean) * (x - s.mean);
  s.sd = s.n > 1 ? std::sqrt(ss / (s.n - 1)) : 0.0;
  s.median = s.n % 2 ? v[s.n / 2] : 0.5 * (v[s.n / 2 - 1] + v[s.n / 2]);
  return s;
}


// The summary cells of one group of rows (summary_columns()).
std::vector<std::string> summary_cells(const std::vector<const BenchRow*>& rows) {
  int ok = 0, no_grasp = 0, error = 0, simulated = 0, held = 0;
  std::vector<double> first_fc, total, alpha, alpha_approach, epsilon, processed, hold_p;
  for (const BenchRow* r : rows) {
    ok += r->status == "ok";
    no_grasp += r->status == "no_grasp";
    error += r->status == "error";
    if (r->status == "ok") {
      if (r->first_fc_s) first_fc.push_back(*r->first_fc_s);
      if (r->alpha_rad) alpha.push_back(*r->alpha_rad);
      if (r->alpha_approach_rad) alpha_approach.push_back(*r->alpha_approach_rad);
      if (r->epsilon) epsilon.push_back(*r->epsilon);
      if (r->region_rank) processed.push_back(r->regions_processed);
    }
    if (r->status != "error") total.push_back(r->total_s);
    if (r->hold_p) hold_p.push_back(*r->hold_p);
    if (!r->sim_outcome.empty()) {
      ++simulated;
      held += r->sim_outcome == "held";
    }
  }
  const int n = static_cast<int>(rows.size());
  const Stats t = stats_of(first_fc), a = stats_of(alpha), e = stats_of(epsilon),
              tt = stats_of(total), aa = stats_of(alpha_approach), h = stats_of(hold_p);
  auto or_dash = [](bool have, const std::string& s) { return have ? s : std::string("–"); };
  return {std::to_string(n),
          std::to_string(ok) + " (" + fixed(n ? 100.0 * ok / n : 0.0, 0) + " %)",
          std::to_string(no_grasp),
          std::to_string(error),
          or_dash(t.n > 0, fixed(t.median, 3)),
          or_dash(t.n > 0, fixed(t.mean, 3)),
          or_dash(t.n > 0, fixed(t.sd, 3)),
          or_dash(tt.n > 0, fixed(tt.mean, 3)),
          or_dash(a.n > 0, fixed(a.mean, 3)),
          or_dash(a.n > 0, fixed(a.sd, 3)),
          or_dash(aa.n > 0, fixed(aa.mean, 3)),
          or_dash(aa.n > 0, fixed(aa.sd, 3)),
          or_dash(e.n > 0, format_number(e.mean, "%.3g")),
          or_dash(simulated > 0, std::to_string(held) + "/" + std::to_string(simulated) + " (" +
                                     fixed(simulated ? 100.0 * held / simulated : 0.0, 0) +
                                     " %)"),
          or_dash(h.n > 0, fixed(h.median, 2))};
}

// Column names of summary_cells(), in order.
const std::vector<std::string>& summary_columns() {
  static const std::vector<std::string> kColumns = {
      "attempts", "FC grasp found", "no grasp", "error", "first FC median [s]",
      "first FC mean [s]", "first FC sd [s]", "total mean [s]", "α mean [rad]", "α sd [rad]",
      "α approach mean [rad]", "α approach sd [rad]", "ε mean", "sim held", "P(held) median"};
  return kColumns;
}

// One Markdown table: header, rule, rows.
void markdown_table(const BenchSummaryTable& table, std::ostream& out) {
  auto line = [&out](const std::vector<std::string>& cells) {
    out << "|";
    for (const std::string& c : cells) out << " " << c << " |";
    out << "\n";
  };
  line(table.columns);
  out << "|";
  for (size_t i = 0; i < table.columns.size(); ++i) out << "---|";
  out << "\n";
  for (const auto& row : table.rows) line(row);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::uint64_t repeat_seed(std::uint64_t base_seed, int repeat) {
  return base_seed + static_cast<std::uint64_t>(repeat);
}

std::vector<std::string> expand_object_args(const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (const std::string& a : args) {
    std::error_code ec;
    if (fs::is_directory(a, ec)) {
      std::vector<std::string> files;
      for (const auto& e : fs::directory_iterator(a))
        if (e.is_regular_file() && is_mesh_file(e.path())) files.push_back(e.path().string());
      if (files.empty())
        throw InputError("bench: '" + a + "': no mesh files (.obj, .stl, .ply, .off)");
      std::sort(files.begin(), files.end());
      out.insert(out.end(), files.begin(), files.end());
    } else if (fs::exists(a, ec)) {
      out.push_back(a);
    } else {
      throw InputError("bench: '" + a + "': no such file or directory");
    }
  }
  return out;
}

std::vector<BenchAttempt> bench_attempts(const BenchParams& params) {
  std::vector<BenchAttempt> out;
  for (const std::string& object : params.objects)
    for (const std::string& hand : params.hands)
      for (const PlannerKind planner : params.planners)
        for (int r = 0; r < params.repeats; ++r) {
          BenchAttempt a;
          a.index = static_cast<int>(out.size());
          a.object_path = object;
          a.hand = hand;
          a.planner = planner;
          a.repeat = r;
          a.seed = repeat_seed(params.seed, r);
          out.push_back(a);
        }
  return out;
}

std::pair<int, int> parse_shard(const std::string& text) {
  const size_t slash = text.find('/');
  try {
    if (slash == std::string::npos) throw std::invalid_argument("no '/'");
    size_t used_k = 0, used_n = 0;
    const int k = std::stoi(text.substr(0, slash), &used_k);
    const int n = std::stoi(text.substr(slash + 1), &used_n);
    if (used_k != slash || used_n != text.size() - slash - 1 || n < 1 || k < 1 || k > n)
      throw std::invalid_argument("range");
    return {k, n};
  } catch (const std::exception&) {
    throw InputError("--shard '" + text + "': expected k/N with 1 <= k <= N");
  }
}

std::vector<BenchAttempt> shard_attempts(const std::vector<BenchAttempt>& attempts, int k,
                                         int n) {
  std::vector<BenchAttempt> out;
  for (const BenchAttempt& a : attempts)
    if (a.index % n == k - 1) out.push_back(a);
  return out;
}

namespace {

/// One results.csv column: its name, how a row's field becomes a cell and back, and whether
/// files written before the column existed may lack it (the field then keeps its default).
struct BenchColumn {
  const char* name;
  std::function<std::string(const BenchRow&)> write;
  std::function<void(const std::string& cell, const std::string& where, BenchRow*)> read;
  bool may_be_absent = false;
};

template <typename T>
BenchColumn text_column(const char* name, T BenchRow::*field) {
  return {name, [field](const BenchRow& r) { return r.*field; },
          [field](const std::string& cell, const std::string&, BenchRow* r) { r->*field = cell; }};
}

template <typename T>
BenchColumn whole_column(const char* name, T BenchRow::*field) {
  return {name, [field](const BenchRow& r) { return std::to_string(r.*field); },
          [field](const std::string& cell, const std::string& where, BenchRow* r) {
            r->*field = static_cast<T>(parse_integer(cell, where));
          }};
}

BenchColumn optional_whole_column(const char* name, std::optional<int> BenchRow::*field,
                                  bool may_be_absent = false) {
  return {name, [field](const BenchRow& r) { return optional_count(r.*field); },
          [field](const std::string& cell, const std::string& where, BenchRow* r) {
            if (!cell.empty()) r->*field = static_cast<int>(parse_integer(cell, where));
          },
          may_be_absent};
}

BenchColumn seconds_column(const char* name, double BenchRow::*field) {
  return {name, [field](const BenchRow& r) { return seconds(r.*field); },
          [field](const std::string& cell, const std::string& where, BenchRow* r) {
            r->*field = parse_double(cell, where);
          }};
}

BenchColumn optional_column(const char* name, std::optional<double> BenchRow::*field,
                            bool is_seconds, bool may_be_absent = false) {
  return {name,
          [field, is_seconds](const BenchRow& r) {
            return is_seconds ? optional_seconds(r.*field) : optional_number(r.*field);
          },
          [field](const std::string& cell, const std::string& where, BenchRow* r) {
            r->*field = parse_optional_double(cell, where);
          },
          may_be_absent};
}

/// Every column, in file order, listed once for writing and reading.
const std::vector<BenchColumn>& bench_columns() {
  static const std::vector<BenchColumn> kColumns = [] {
    using R = BenchRow;
    std::vector<BenchColumn> c = {
        whole_column("attempt", &R::attempt),
        text_column("object", &R::object),
        text_column("object_path", &R::object_path),
        text_column("hand", &R::hand),
        text_column("planner", &R::planner),
        whole_column("repeat", &R::repeat),
        whole_column("seed", &R::seed),
        {"status", [](const R& r) { return r.status; },
         [](const std::string& cell, const std::string& where, R* r) {
           if (cell != "ok" && cell != "no_grasp" && cell != "error")
             throw InputError(where + ": unknown status '" + cell + "'");
           r->status = cell;
         }},
        text_column("error", &R::error),
        optional_column("first_fc_s", &R::first_fc_s, true),
        seconds_column("exploration_s", &R::exploration_s),
        seconds_column("finger_s", &R::finger_s),
        seconds_column("quality_s", &R::quality_s),
        seconds_column("total_s", &R::total_s),
        whole_column("regions", &R::regions),
        whole_column("regions_processed", &R::regions_processed),
        whole_column("finger_attempts", &R::finger_attempts),
        whole_column("grasps", &R::grasps),
        {"timed_out", [](const R& r) { return std::string(r.timed_out ? "1" : "0"); },
         [](const std::string& cell, const std::string&, R* r) { r->timed_out = cell == "1"; }},
        optional_column("epsilon", &R::epsilon, false),
        optional_column("alpha_rad", &R::alpha_rad, false),
        optional_column("alpha_approach_rad", &R::alpha_approach_rad, false, true),
        optional_column("chi_m2", &R::chi_m2, false),
        optional_whole_column("region_rank", &R::region_rank),
        text_column("sim_lift", &R::sim_lift),
        text_column("sim_shake", &R::sim_shake),
        text_column("sim_gravity6", &R::sim_gravity6),
        text_column("sim_outcome", &R::sim_outcome),
        optional_column("sim_wall_s", &R::sim_wall_s, true),
        {"object_scale", [](const R& r) { return format_number(r.object_scale, "%.17g"); },
         [](const std::string& cell, const std::string& where, R* r) {
           r->object_scale = parse_double(cell, where);
         },
         true},
        optional_whole_column("validated_accepted", &R::validated_accepted, true),
        optional_whole_column("validated_candidates", &R::validated_candidates, true),
        optional_whole_column("validated_simulated", &R::validated_simulated, true),
        optional_whole_column("validated_rejected_early", &R::validated_rejected_early, true),
        optional_whole_column("validated_held_as_planned", &R::validated_held_as_planned, true),
        optional_column("validated_first_accepted_cpu_s", &R::validated_first_accepted_cpu_s,
                        true, true),
        optional_column("validated_cpu_s", &R::validated_cpu_s, true, true),
        optional_column("hold_p", &R::hold_p, false, true),
        optional_column("hold_low", &R::hold_low, false, true),
        optional_column("hold_high", &R::hold_high, false, true),
        optional_whole_column("hold_draws", &R::hold_draws, true),
        optional_column("hold_cpu_s", &R::hold_cpu_s, true, true)};
    return c;
  }();
  return kColumns;
}

}  // namespace

const std::vector<std::string>& bench_csv_columns() {
  static const std::vector<std::string> kNames = [] {
    std::vector<std::string> names;
    for (const BenchColumn& c : bench_columns()) names.push_back(c.name);
    return names;
  }();
  return kNames;
}

const std::vector<std::string>& bench_timing_columns() {
  static const std::vector<std::string> kTiming = {
      "first_fc_s", "exploration_s", "finger_s", "quality_s", "total_s", "sim_wall_s",
      "validated_first_accepted_cpu_s", "validated_cpu_s", "hold_cpu_s"};
  return kTiming;
}

std::vector<std::string> bench_row_cells(const BenchRow& r) {
  std::vector<std::string> cells;
  for (const BenchColumn& c : bench_columns()) cells.push_back(c.write(r));
  return cells;
}

std::string bench_csv(const std::vector<BenchRow>& rows) {
  std::string out;
  auto line = [&](const std::vector<std::string>& cells) {
    for (size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + csv_quote(cells[i]);
    out += '\n';
  };
  line(bench_csv_columns());
  for (const BenchRow& r : rows) line(bench_row_cells(r));
  return out;
}

std::vector<BenchRow> parse_bench_csv(const std::string& text, const std::string& what) {
  const auto records = parse_csv_records(text, what);
  if (records.empty()) throw InputError(what + ": not a cordgrasp bench results.csv (empty)");
  // Columns are found by name: files from before a newer column (may_be_absent) read too.
  const std::vector<std::string>& header = records[0];
  std::vector<std::pair<const BenchColumn*, size_t>> read_at;
  for (const BenchColumn& c : bench_columns()) {
    const auto it = std::find(header.begin(), header.end(), c.name);
    if (it != header.end())
      read_at.emplace_back(&c, static_cast<size_t>(it - header.begin()));
    else if (!c.may_be_absent)
      throw InputError(what + ": not a cordgrasp bench results.csv (no column '" +
                       std::string(c.name) + "')");
  }
  if (read_at.size() != header.size())
    throw InputError(what + ": not a cordgrasp bench results.csv (unknown or repeated columns)");
  std::vector<BenchRow> rows;
  for (size_t i = 1; i < records.size(); ++i) {
    const auto& cells = records[i];
    const std::string where = what + ": row " + std::to_string(i);
    if (cells.size() != header.size())
      throw InputError(where + ": " + std::to_string(cells.size()) + " cells, expected " +
                       std::to_string(header.size()));
    BenchRow r;
    for (const auto& [column, index] : read_at) column->read(cells[index], where, &r);
    rows.push_back(std::move(r));
  }
  return rows;
}

struct BenchInputs::Loaded {
  std::map<std::string, std::shared_ptr<const Mesh>> meshes;
  std::map<std::string, std::shared_ptr<const HandModel>> hands;
  std::map<std::string, std::string> errors;  // "object:path" / "hand:name" → message
};

BenchInputs::BenchInputs(const BenchParams& params, const std::vector<BenchAttempt>& attempts) {
  auto loaded = std::make_shared<Loaded>();
  for (const BenchAttempt& a : attempts) {
    if (!loaded->meshes.count(a.object_path) && !loaded->errors.count("object:" + a.object_path)) {
      try {
        loaded->meshes[a.object_path] =
            std::make_shared<const Mesh>(load_job_mesh(params.job, a.object_path));
      } catch (const std::exception& e) {
        loaded->errors["object:" + a.object_path] = e.what();
      }
    }
    if (!loaded->hands.count(a.hand) && !loaded->errors.count("hand:" + a.hand)) {
      try {
        loaded->hands[a.hand] =
            std::make_shared<const HandModel>(load_hand(a.hand, params.hand_load));
      } catch (const std::exception& e) {
        loaded->errors["hand:" + a.hand] = e.what();
      }
    }
  }
  loaded_ = loaded;
}

std::shared_ptr<const Mesh> BenchInputs::mesh(const std::string& path,
                                              std::string* error) const {
  const auto it = loaded_->meshes.find(path);
  if (it != loaded_->meshes.end()) return it->second;
  const auto e = loaded_->errors.find("object:" + path);
  if (error) *error = e != loaded_->errors.end() ? e->second : "object '" + path + "' not loaded";
  return nullptr;
}

const HandModel* BenchInputs::hand(const std::string& name, std::string* error) const {
  const auto it = loaded_->hands.find(name);
  if (it != loaded_->hands.end()) return it->second.get();
  const auto e = loaded_->errors.find("hand:" + name);
  if (error) *error = e != loaded_->errors.end() ? e->second : "hand '" + name + "' not loaded";
  return nullptr;
}

BenchResult run_bench_attempt(const BenchAttempt& attempt, const BenchParams& params,
                              const BenchInputs& inputs, const CancelToken& cancel) {
  BenchResult result;
  BenchRow& row = result.row;
  row.attempt = attempt.index;
  row.object = fs::path(attempt.object_path).stem().string();
  row.object_path = attempt.object_path;
  row.object_scale = params.job.scale;
  row.hand = attempt.hand;
  row.planner = to_string(attempt.planner);
  row.repeat = attempt.repeat;
  row.seed = attempt.seed;
  try {
    std::string error;
    const std::shared_ptr<const Mesh> mesh = inputs.mesh(attempt.object_path, &error);
    if (!mesh) throw InputError(error);
    const HandModel* hand = inputs.hand(attempt.hand, &error);
    if (!hand) throw InputError(error);
    PlanJobParams job = params.job;
    job.planner = attempt.planner;
    job.plan.seed = attempt.seed;
    PhysicsChoice physics;
    physics.protocol = params.protocol;
    physics.cache_dir = params.sim_cache_dir;
    physics.file = params.physics_file;
    PlanDocument plan;
    if (params.validation) {
      ValidationParams v = *params.validation;
      v.tests = params.tests == "none" ? std::string("lift,shake") : params.tests;
      v.protocol = params.protocol;
      v.physics_file = params.physics_file;
      plan = validated_plan_job(job, v, *mesh, attempt.object_path, *hand, 1, {}, cancel,
                                params.sim_cache_dir);
      const ValidationStats& vs = plan.validation->stats;
      row.validated_accepted = vs.accepted;
      row.validated_candidates = vs.force_closure;
      row.validated_simulated = vs.simulated;
      row.validated_rejected_early = vs.rejected_early;
      row.validated_held_as_planned = vs.held_as_planned;
      row.validated_first_accepted_cpu_s = vs.first_accepted_cpu_s;
      row.validated_cpu_s = vs.cpu_s;
    } else {
      plan = plan_job(job, *mesh, attempt.object_path, *hand, cancel);
    }
    if (!plan.interrupted.empty()) {
      result.interrupted = true;
      return result;
    }
    const PlanStats& s = plan.stats;
    row.first_fc_s = s.first_force_closure_s;
    row.exploration_s = s.exploration_s;
    row.finger_s = s.finger_s;
    row.quality_s = s.quality_s;
    row.total_s = s.total_s;
    row.regions = s.regions;
    row.regions_processed = s.regions_processed;
    row.finger_attempts = s.attempts;
    row.grasps = static_cast<int>(plan.grasps.size());
    row.timed_out = s.timed_out;
    row.status = plan.grasps.empty() ? "no_grasp" : "ok";
    if (plan.grasps.empty()) return result;
    const Grasp& g = plan.grasps.front();
    row.epsilon = g.epsilon;
    row.alpha_rad = g.alpha_rad;
    row.alpha_approach_rad = g.alpha_approach_rad;
    row.chi_m2 = g.chi_m2;
    row.region_rank = g.region_rank;
    result.first_grasp = g;
    if (params.tests == "none") return result;
    SimParams sim = physics_settings(plan_contact_model(plan), physics);
    if (params.validation) sim.squeeze_shift_limit_m = params.validation->squeeze_shift_limit_m;
    const SimDocument doc = validate_plan(plan, *hand, *mesh, sim,
                                          sim_tests_from_string(params.tests), 1, {}, {}, 1,
                                          cancel);
    if (!doc.interrupted.empty()) {
      result.interrupted = true;
      return result;
    }
    if (!doc.results.empty() && !is_none(params.uncertainty)) {
      const HoldProbability h = estimate_hold_probability(
          *mesh, *hand, plan.grasps.front(), 0, doc.params, doc.tests, params.uncertainty,
          params.hold_test, cancel);
      if (!h.complete) {
        result.interrupted = true;
        return result;
      }
      row.hold_p = h.interval.p;
      row.hold_low = h.interval.low;
      row.hold_high = h.interval.high;
      row.hold_draws = static_cast<int>(h.draws.size());
      row.hold_cpu_s = h.cpu_s;
    }
    if (!doc.results.empty()) {
      const SimResult& r = doc.results.front();
      auto phase = [&](const char* name) {
        const PhaseResult* p = r.phase(name);
        return std::string(p ? to_string(p->outcome) : to_string(Outcome::kNotRun));
      };
      row.sim_lift = phase("lift");
      row.sim_shake = phase("shake");
      row.sim_gravity6 = phase("gravity6");
      row.sim_outcome = to_string(r.outcome);
      row.sim_wall_s = r.wall_time_s;
    }
  } catch (const std::exception& e) {
    row.status = "error";
    row.error = e.what();
    result.first_grasp.reset();
  }
  return result;
}

std::vector<BenchResult> run_bench_attempts(const std::vector<BenchAttempt>& attempts,
                                            const BenchParams& params, const BenchInputs& inputs,
                                            int jobs, const BenchProgress& progress,
                                            const CancelToken& cancel) {
  std::vector<BenchResult> results(attempts.size());
  std::mutex mutex;
  int done = 0;
  const int total = static_cast<int>(attempts.size());
  parallel_for(total, jobs, [&](int i) {
    const size_t k = static_cast<size_t>(i);
    if (cancel.cancelled()) {  // no new attempt once a stop is asked for
      results[k].interrupted = true;
      return;
    }
    results[k] = run_bench_attempt(attempts[k], params, inputs, cancel);
    if (results[k].interrupted) return;
    const std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (progress) progress(done, total, results[k].row);
  });
  return results;
}

nlohmann::json bench_params_to_json(const BenchParams& p) {
  PlanJobParams j = p.job;
  j.plan.seed = p.seed;  // per attempt: seed + repeat
  nlohmann::json job = params_to_json(j);
  job.erase("planner");  // per attempt: "planners"
  return {{"hands", p.hands},
          {"objects", p.objects},
          {"planners", [&p] {
             nlohmann::json names = nlohmann::json::array();
             for (const PlannerKind k : p.planners) names.push_back(to_string(k));
             return names;
           }()},
          {"repeats", p.repeats},
          {"seed", p.seed},
          {"job", job},
          {"tests", p.tests},
          {"protocol", to_string(p.protocol)},
          {"validation", p.validation ? params_to_json(*p.validation) : nlohmann::json(nullptr)},
          {"uncertainty", is_none(p.uncertainty) ? nlohmann::json(nullptr)
                                                 : params_to_json(p.uncertainty)},
          {"hold_test", is_none(p.uncertainty) ? nlohmann::json(nullptr)
                                               : params_to_json(p.hold_test)}};
}

std::vector<BenchRow> merge_bench_rows(const std::vector<std::vector<BenchRow>>& parts) {
  std::vector<BenchRow> rows;
  for (const auto& part : parts) rows.insert(rows.end(), part.begin(), part.end());
  std::stable_sort(rows.begin(), rows.end(),
                   [](const BenchRow& a, const BenchRow& b) { return a.attempt < b.attempt; });
  for (size_t i = 1; i < rows.size(); ++i)
    if (rows[i].attempt == rows[i - 1].attempt)
      throw InputError("merge: attempt " + std::to_string(rows[i].attempt) + " (" +
                       rows[i].object + ", " + rows[i].hand + ", " + rows[i].planner +
                       ", repeat " + std::to_string(rows[i].repeat) +
                       ") appears twice (the same shard given twice, or overlapping shards?)");
  return rows;
}

BenchSummaryTables bench_summary_tables(const std::vector<BenchRow>& rows) {
  // Groups in attempt order.
  std::vector<std::string> keys, totals_keys;
  std::map<std::string, std::vector<const BenchRow*>> groups, totals;
  std::map<std::string, std::vector<std::string>> key_cells;
  for (const BenchRow& r : rows) {
    const std::string key = r.object_path + '\n' + r.hand + '\n' + r.planner;
    if (!groups.count(key)) {
      keys.push_back(key);
      key_cells[key] = {r.object, r.hand, r.planner};
    }
    groups[key].push_back(&r);
    const std::string tkey = r.hand + '\n' + r.planner;
    if (!totals.count(tkey)) {
      totals_keys.push_back(tkey);
      key_cells[tkey] = {r.hand, r.planner};
    }
    totals[tkey].push_back(&r);
  }
  BenchSummaryTables t;
  t.per_object.columns = {"object", "hand", "planner"};
  t.totals.columns = {"hand", "planner"};
  for (BenchSummaryTable* table : {&t.per_object, &t.totals})
    table->columns.insert(table->columns.end(), summary_columns().begin(),
                          summary_columns().end());
  auto add = [&key_cells](BenchSummaryTable* table, const std::string& key,
                          const std::vector<const BenchRow*>& group) {
    std::vector<std::string> cells = key_cells[key];
    const std::vector<std::string> values = summary_cells(group);
    cells.insert(cells.end(), values.begin(), values.end());
    table->rows.push_back(std::move(cells));
  };
  for (const std::string& k : keys) add(&t.per_object, k, groups[k]);
  for (const std::string& k : totals_keys) add(&t.totals, k, totals[k]);
  return t;
}

std::string bench_summary_markdown(const std::vector<BenchRow>& rows,
                                   const BenchSummaryInfo& info) {
  std::ostringstream out;
  out << "# cordgrasp bench summary\n\n";
  out << "- command: `" << info.command << "`\n";
  for (const std::string& c : info.merged_from) out << "  - merged from: `" << c << "`\n";
  out << "- machine: " << info.machine << "\n";
  out << "- attempts: " << rows.size() << " of " << info.attempts_total;
  if (!info.shard.empty()) out << " (shard " << info.shard << ")";
  if (!info.interrupted.empty())
    out << "\n- **incomplete: interrupted by " << info.interrupted << " after " << rows.size()
        << " of " << info.attempts_asked
        << " attempts**; the attempts in flight were abandoned and the rest did not run";
  out << "\n- physics tests on each attempt's first grasp: "
      << (info.tests.empty() ? "none" : info.tests) << "\n";
  const auto timed_out = std::count_if(rows.begin(), rows.end(),
                                       [](const BenchRow& r) { return r.timed_out; });
  out << "- machine-dependent attempts (the --time-limit safety net fired before the attempt "
         "budget; timed_out = 1 in results.csv): "
      << timed_out << "\n";
  out << "- times are wall-clock seconds; α (skewness, docs/algorithm.md §9; of the palm "
         "normal, α approach of the GCP z axis) and ε of the "
         "first force-closure grasp; first FC, α and ε over the attempts that found a grasp; sim held = first "
         "grasps that held through every test / first grasps simulated.\n\n";

  const BenchSummaryTables tables = bench_summary_tables(rows);
  out << "## Per object, hand and planner\n\n";
  markdown_table(tables.per_object, out);
  out << "\n## Totals per hand and planner (all objects)\n\n";
  markdown_table(tables.totals, out);
  std::vector<const BenchRow*> errors;
  for (const BenchRow& r : rows)
    if (r.status == "error") errors.push_back(&r);
  if (!errors.empty()) {
    out << "\n## Errors\n\n";
    for (const BenchRow* r : errors)
      out << "- attempt " << r->attempt << " (" << r->object << ", " << r->hand << ", "
          << r->planner << ", repeat " << r->repeat << "): " << r->error << "\n";
  }
  if (!info.sheets.empty()) {
    out << "\n## Contact sheets (best first grasp by ε per hand and planner)\n\n";
    for (const std::string& s : info.sheets) out << "- [" << s << "](" << s << ")\n";
  }
  return out.str();
}

void write_bench_outputs(const std::string& out_dir, const std::vector<BenchRow>& rows,
                         const nlohmann::json& bench_json, const BenchSummaryInfo& info) {
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) throw InputError("bench: cannot create '" + out_dir + "': " + ec.message());
  write_file_atomically((fs::path(out_dir) / "results.csv").string(), bench_csv(rows));
  write_file_atomically((fs::path(out_dir) / "bench.json").string(), bench_json.dump(2) + "\n");
  write_file_atomically((fs::path(out_dir) / "summary.md").string(),
                        bench_summary_markdown(rows, info));
  write_file_atomically((fs::path(out_dir) / "report.html").string(),
                        bench_report_html(rows, info));
}

std::string machine_description() {
  const unsigned cores = std::thread::hardware_concurrency();
  std::string model = "unknown CPU";
  std::istringstream cpuinfo(read_text("/proc/cpuinfo"));
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) {
        model = line.substr(colon + 1);
        model.erase(0, model.find_first_not_of(" \t"));
      }
      break;
    }
  }
  return std::to_string(cores) + " cores (nproc), " + model;
}

std::string process_command_line() {
  const std::string raw = read_text("/proc/self/cmdline");
  std::string out;
  size_t start = 0;
  while (start < raw.size()) {
    size_t end = raw.find('\0', start);
    if (end == std::string::npos) end = raw.size();
    std::string arg = raw.substr(start, end - start);
    if (start == 0) arg = fs::path(arg).filename().string();  // "cordgrasp", not the build path
    const bool plain = !arg.empty() && arg.find_first_not_of(
                                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                           "0123456789-_./,=:+") == std::string::npos;
    if (!out.empty()) out += ' ';
    if (plain) {
      out += arg;
    } else {
      out += '\'';
      for (char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
      out += '\'';
    }
    start = end + 1;
  }
  return out;
}

}  // namespace cordgrasp
