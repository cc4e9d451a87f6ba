// The parameter structs' Serialize visitors (core/serialize.h), the enums' to_string/parse
// pairs and the JSON archive (tools/jobs/src/params_json.h).
#include "params_json.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <utility>

#include "cordgrasp/core/contact_model.h"
#include "cordgrasp/core/cord_params.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/finger_stage.h"
#include "cordgrasp/core/grasp_perturbation.h"
#include "cordgrasp/core/grasp_plan.h"
#include "cordgrasp/core/grasp_quality.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/jobs/plan_job.h"
#include "cordgrasp/sim/convex_decomposition.h"
#include "cordgrasp/sim/sim_params.h"

namespace cordgrasp {
namespace {

// ---- Number of members of an aggregate, without a hand-kept list ------------------------
// T{a1, ..., aN} is well-formed for N up to the member count (each AnyField converts to the
// member's type), so the largest such N is the count: a field added to a struct but not to
// its Serialize makes the visit count differ.
struct AnyField {
  template <typename T>
  operator T() const;  // unevaluated only
};

template <typename T, typename Seq, typename = void>
struct BraceConstructible : std::false_type {};
template <typename T, std::size_t... I>
struct BraceConstructible<T, std::index_sequence<I...>,
                          std::void_t<decltype(T{(static_cast<void>(I), AnyField{})...})>>
    : std::true_type {};

template <typename T, std::size_t N = 0>
constexpr std::size_t member_count() {
  if constexpr (BraceConstructible<T, std::make_index_sequence<N + 1>>::value)
    return member_count<T, N + 1>();
  else
    return N;
}

// ---- Archives used by the tests ---------------------------------------------------------
struct NameCollector {
  std::vector<std::string> names;
  template <typename T>
  void Visit(const NameValuePair<T>& nvp) {
    names.push_back(nvp.name);
  }
};

template <typename T>
std::vector<std::string> field_names() {
  T params;
  NameCollector collector;
  params.Serialize(&collector);
  return collector.names;
}

// Another enumerator than `e` (the next one, wrapping around).
template <typename E>
E other_enumerator(E e) {
  const E next = static_cast<E>(static_cast<int>(e) + 1);
  return std::string(to_string(next)) != "?" ? next : static_cast<E>(0);
}

// Sets every visited field (recursively) to a value other than the one it holds.
struct Perturber {
  int step = 1;  // makes values differ between fields too
  template <typename T>
  void Visit(const NameValuePair<T>& nvp) {
    change(nvp.value);
  }
  template <typename T>
  void change(T* v) {
    ++step;
    if constexpr (std::is_enum_v<T>) {
      *v = other_enumerator(*v);
    } else if constexpr (std::is_same_v<T, bool>) {
      *v = !*v;
    } else if constexpr (std::is_integral_v<T>) {
      *v = static_cast<T>(*v + step);
    } else if constexpr (std::is_floating_point_v<T>) {
      *v = *v * 1.5 + 0.001 * step;  // exactly representable? no matter: JSON round-trips
    } else if constexpr (std::is_same_v<T, std::string>) {
      *v += "_changed";
    } else if constexpr (params_json_detail::IsOptional<T>::value) {
      if (*v) {
        v->reset();
      } else {
        typename T::value_type x{};
        change(&x);
        *v = x;
      }
    } else {
      v->Serialize(this);
    }
  }
};

// Leaf paths of a JSON object ("a.b.c") with their values.
void leaves(const nlohmann::json& j, const std::string& prefix,
            std::map<std::string, nlohmann::json>* out) {
  for (const auto& [key, value] : j.items()) {
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    if (value.is_object())
      leaves(value, path, out);
    else
      (*out)[path] = value;
  }
}

template <typename T>
void expect_every_field_round_trips(const char* what) {
  SCOPED_TRACE(what);
  // The visitor visits every member once.
  const std::vector<std::string> names = field_names<T>();
  EXPECT_EQ(names.size(), member_count<T>()) << "Serialize misses or repeats a field";
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());

  T changed;
  Perturber perturber;
  changed.Serialize(&perturber);
  const nlohmann::json written = params_to_json(changed);
  EXPECT_EQ(written.size(), names.size());

  // Every leaf differs from the default, so the comparison below sees every field.
  std::map<std::string, nlohmann::json> defaults, values;
  leaves(params_to_json(T{}), "", &defaults);
  leaves(written, "", &values);
  EXPECT_EQ(defaults.size(), values.size());
  for (const auto& [path, value] : values) EXPECT_NE(value, defaults[path]) << path;

  T back;
  params_from_json(written, "test.json", "", &back);
  std::map<std::string, nlohmann::json> reread;
  leaves(params_to_json(back), "", &reread);
  EXPECT_EQ(reread, values);
  // Through text too (doubles keep every bit).
  T from_text;
  params_from_json(nlohmann::json::parse(written.dump()), "test.json", "", &from_text);
  EXPECT_EQ(params_to_json(from_text), written);
}

TEST(ParamsJson, EveryFieldOfEveryStructRoundTrips) {
  expect_every_field_round_trips<ContactModel>("ContactModel");
  expect_every_field_round_trips<CordParams>("CordParams");
  expect_every_field_round_trips<FingerParams>("FingerParams");
  expect_every_field_round_trips<QualityParams>("QualityParams");
  expect_every_field_round_trips<PlanParams>("PlanParams");
  expect_every_field_round_trips<PerturbationParams>("PerturbationParams");
  expect_every_field_round_trips<DecompositionParams>("DecompositionParams");
  expect_every_field_round_trips<SimParams>("SimParams");
  expect_every_field_round_trips<PlanJobParams>("PlanJobParams");
}

TEST(ParamsJson, MemberCountSeesEveryAggregateMember) {
  struct Three {
    int a = 0;
    std::optional<double> b;
    ContactModel c;
  };
  EXPECT_EQ(member_count<Three>(), 3u);
  EXPECT_EQ(member_count<ContactModel>(), 3u);
}

TEST(ParamsJson, NestedStructsAreObjectsAndEnumsTheirNames) {
  SimParams p;
  p.mass_kg = 0.25;
  const nlohmann::json j = params_to_json(p);
  EXPECT_EQ(j.at("contact").at("mu"), kDefaultFrictionCoefficient);
  EXPECT_EQ(j.at("decomposition").at("max_input_triangles"), p.decomposition.max_input_triangles);
  EXPECT_EQ(j.at("object_shape"), "auto");
  EXPECT_EQ(j.at("world_frame"), "approach_down");
  EXPECT_EQ(j.at("mass_kg"), 0.25);
  EXPECT_TRUE(params_to_json(SimParams{}).at("mass_kg").is_null());
}

std::string read_error(const nlohmann::json& j) {
  try {
    CordParams p;
    params_from_json(j, "plan.json", "parameters.cord", &p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ParamsJson, MissingKeyNamesFileAndPath) {
  nlohmann::json j = params_to_json(CordParams{});
  j.erase("xi_min_m");
  EXPECT_EQ(read_error(j), "plan.json: parameters.cord.xi_min_m: missing");
}

TEST(ParamsJson, WrongTypeUnknownKeyAndUnknownEnumNameAreErrors) {
  nlohmann::json j = params_to_json(CordParams{});
  j["sets"] = "20";
  EXPECT_NE(read_error(j).find("plan.json: parameters.cord.sets: expected an integer"),
            std::string::npos)
      << read_error(j);
  j = params_to_json(CordParams{});
  j["sets"] = 2.5;
  EXPECT_NE(read_error(j).find("parameters.cord.sets"), std::string::npos);
  j = params_to_json(CordParams{});
  j["seed"] = -1;
  EXPECT_NE(read_error(j).find("parameters.cord.seed: expected a non-negative integer"),
            std::string::npos);
  j = params_to_json(CordParams{});
  j["xi_min"] = 0.01;
  EXPECT_EQ(read_error(j), "plan.json: parameters.cord: unknown key(s) 'xi_min'");
  j = params_to_json(CordParams{});
  j["side_cord_policy"] = "sometimes";
  EXPECT_EQ(read_error(j),
            "plan.json: parameters.cord.side_cord_policy: side-cord policy: unknown name "
            "'sometimes' (allowed: discard, shrink, empty, fallback)");
  j = params_to_json(CordParams{});
  j["local_improvement"] = 1;
  EXPECT_NE(read_error(j).find("local_improvement: expected true or false"), std::string::npos);
}

TEST(ParamsJson, MissingNestedKeyNamesTheFullPath) {
  nlohmann::json j = params_to_json(SimParams{});
  j["decomposition"].erase("max_input_triangles");
  try {
    SimParams p;
    params_from_json(j, "sim.json", "parameters", &p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "sim.json: parameters.decomposition.max_input_triangles: missing");
  }
}

template <typename E>
void expect_names_round_trip(E (*parse)(const std::string&), std::initializer_list<E> all) {
  std::set<std::string> names;
  for (E e : all) {
    EXPECT_EQ(parse(to_string(e)), e) << to_string(e);
    names.insert(to_string(e));
  }
  EXPECT_EQ(names.size(), all.size()) << "two enumerators share a name";
  try {
    parse("no-such-name");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'no-such-name'"), std::string::npos) << message;
    for (const std::string& name : names)
      EXPECT_NE(message.find(name), std::string::npos) << message << " lacks " << name;
  }
}

TEST(EnumNames, EveryEnumParsesItsNamesAndListsThemWhenItCannot) {
  expect_names_round_trip(parse_side_cord_policy,
                          {SideCordPolicy::kDiscardSet, SideCordPolicy::kShrink,
                           SideCordPolicy::kEmptyWhenMissed, SideCordPolicy::kFallback});
  expect_names_round_trip(parse_sphere_sequence,
                          {SphereSequence::kYershovaLaValle, SphereSequence::kFibonacci});
  expect_names_round_trip(parse_cord_construction,
                          {CordConstruction::kHullChain, CordConstruction::kTighten});
  expect_names_round_trip(parse_xor_backend, {XorBackend::kClipper, XorBackend::kConvex});
  expect_names_round_trip(parse_quality_mode, {QualityMode::kTextbook, QualityMode::kSimox});
  expect_names_round_trip(parse_length_units,
                          {LengthUnits::kMeters, LengthUnits::kMillimeters, LengthUnits::kAuto});
  expect_names_round_trip(parse_object_shape,
                          {ObjectShape::kAuto, ObjectShape::kConvexHull,
                           ObjectShape::kDecomposition, ObjectShape::kGImpact});
  expect_names_round_trip(parse_world_frame, {WorldFrame::kApproachDown, WorldFrame::kObject});
}

TEST(EnumNames, TheCliNamesOfSideCordsAndQualityStay) {
  // plan.json files and scripts use these names.
  EXPECT_STREQ(to_string(SideCordPolicy::kEmptyWhenMissed), "empty");
  EXPECT_STREQ(to_string(SideCordPolicy::kDiscardSet), "discard");
  EXPECT_STREQ(to_string(SideCordPolicy::kShrink), "shrink");
  EXPECT_STREQ(to_string(SideCordPolicy::kFallback), "fallback");
  EXPECT_STREQ(to_string(QualityMode::kSimox), "simox");
  EXPECT_STREQ(to_string(LengthUnits::kMillimeters), "mm");
}

}  // namespace
}  // namespace cordgrasp
