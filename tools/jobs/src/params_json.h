#pragma once
// JSON archive of the parameter structs (their Serialize visitors, core/serialize.h): every
// field under its own name, nested structs as objects, enums as their to_string names,
// std::optional as null when unset. Reading is strict: a missing key, an unknown key, a wrong
// type or an unknown enum name throws InputError "<context>: <json path>: <problem>".
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/serialize.h"
#include "cordgrasp/jobs/parse_name.h"

namespace cordgrasp {

namespace params_json_detail {

struct NullArchive {
  template <typename T>
  void Visit(const NameValuePair<T>&) {}
};

template <typename T, typename = void>
struct IsSerializable : std::false_type {};
template <typename T>
struct IsSerializable<T, std::void_t<decltype(std::declval<T&>().Serialize(
                             static_cast<NullArchive*>(nullptr)))>> : std::true_type {};

template <typename T>
struct IsOptional : std::false_type {};
template <typename T>
struct IsOptional<std::optional<T>> : std::true_type {};

}  // namespace params_json_detail

/// Writes visited fields into a JSON object.
class JsonWriteArchive {
 public:
  template <typename T>
  void Visit(const NameValuePair<T>& nvp) {
    json_[nvp.name] = value_json(*nvp.value);
  }

  /// The object written so far.
  const nlohmann::json& json() const { return json_; }

  /// JSON of one field value (a struct with Serialize as an object).
  template <typename T>
  static nlohmann::json value_json(const T& value) {
    using params_json_detail::IsOptional;
    using params_json_detail::IsSerializable;
    if constexpr (std::is_enum_v<T>) {
      return to_string(value);
    } else if constexpr (IsOptional<T>::value) {
      return value ? value_json(*value) : nlohmann::json(nullptr);
    } else if constexpr (IsSerializable<T>::value) {
      T copy = value;  // Serialize takes field addresses
      JsonWriteArchive nested;
      copy.Serialize(&nested);
      return nested.json_;
    } else {
      return value;
    }
  }

 private:
  nlohmann::json json_ = nlohmann::json::object();
};

/// What a JsonReadArchive does with a field whose key is absent.
enum class MissingKey {
  kFail,         ///< throw InputError (settings, parameters: a misspelt key must not pass)
  kKeepDefault,  ///< leave the field as it is (records that gained fields over time)
};

/// Reads visited fields from a JSON object; `context` (a file name) and `path` (the object's
/// JSON path, e.g. "parameters.cord") prefix every error.
class JsonReadArchive {
 public:
  JsonReadArchive(const nlohmann::json& json, std::string context, std::string path,
                  MissingKey missing = MissingKey::kFail)
      : json_(json), context_(std::move(context)), path_(std::move(path)), missing_(missing) {
    if (!json_.is_object()) fail(path_, "expected an object, got " + type_of(json_));
  }

  template <typename T>
  void Visit(const NameValuePair<T>& nvp) {
    const std::string key = path_.empty() ? std::string(nvp.name) : path_ + "." + nvp.name;
    const auto it = json_.find(nvp.name);
    if (it == json_.end() && missing_ == MissingKey::kKeepDefault) return;
    if (it == json_.end()) fail(key, "missing");
    read_value(*it, key, nvp.value);
    known_.insert(nvp.name);
  }

  /// Throws for keys of the object that no Visit asked for (misspelt or from another layout).
  void reject_unknown_keys() const {
    std::string unknown;
    for (const auto& item : json_.items())
      if (known_.count(item.key()) == 0)
        unknown += (unknown.empty() ? "'" : ", '") + item.key() + "'";
    if (!unknown.empty()) fail(path_, "unknown key(s) " + unknown);
  }

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(context_ + ": " + (key.empty() ? std::string("(top level)") : key) + ": " +
                     problem);
  }

  static std::string type_of(const nlohmann::json& j) { return j.type_name(); }

  template <typename T>
  void read_value(const nlohmann::json& j, const std::string& key, T* out) {
    using params_json_detail::IsOptional;
    using params_json_detail::IsSerializable;
    if constexpr (std::is_enum_v<T>) {
      if (!j.is_string()) fail(key, "expected a name, got " + type_of(j));
      try {
        parse_name(j.get<std::string>(), out);
      } catch (const std::invalid_argument& e) {
        fail(key, e.what());
      }
    } else if constexpr (IsOptional<T>::value) {
      if (j.is_null()) {
        out->reset();
      } else {
        typename T::value_type value{};
        read_value(j, key, &value);
        *out = value;
      }
    } else if constexpr (IsSerializable<T>::value) {
      JsonReadArchive nested(j, context_, key, missing_);
      out->Serialize(&nested);
      nested.reject_unknown_keys();
    } else if constexpr (std::is_same_v<T, bool>) {
      if (!j.is_boolean()) fail(key, "expected true or false, got " + type_of(j));
      *out = j.get<bool>();
    } else if constexpr (std::is_integral_v<T> && std::is_unsigned_v<T>) {
      if (!j.is_number_unsigned()) fail(key, "expected a non-negative integer, got " + j.dump());
      *out = j.get<T>();
    } else if constexpr (std::is_integral_v<T>) {
      if (!j.is_number_integer()) fail(key, "expected an integer, got " + j.dump());
      *out = j.get<T>();
    } else if constexpr (std::is_floating_point_v<T>) {
      if (!j.is_number()) fail(key, "expected a number, got " + type_of(j));
      *out = j.get<T>();
    } else if constexpr (std::is_same_v<T, std::string>) {
      if (!j.is_string()) fail(key, "expected a string, got " + type_of(j));
      *out = j.get<std::string>();
    } else {
      static_assert(sizeof(T) == 0, "JsonReadArchive: unsupported field type");
    }
  }

  const nlohmann::json& json_;
  std::string context_;
  std::string path_;
  MissingKey missing_;
  std::set<std::string> known_;
};

/// `params` as a JSON object, one key per visited field.
template <typename T>
nlohmann::json params_to_json(const T& params) {
  return JsonWriteArchive::value_json(params);
}

/// Reads every field of `*params` from `json` (the object at JSON path `path` of the file
/// `context`). @throws InputError for a missing or unknown key, a wrong type or an unknown
/// enum name, naming context and the key's path.
template <typename T>
void params_from_json(const nlohmann::json& json, const std::string& context,
                      const std::string& path, T* params) {
  JsonReadArchive archive(json, context, path);
  params->Serialize(&archive);
  archive.reject_unknown_keys();
}

}  // namespace cordgrasp
