#pragma once
// Planner parameters as Python keyword arguments, from the structs' Serialize visitors
// (core/serialize.h), so each field is listed once. Nested structs are flattened to their
// leaves' own names; when two leaves share a name the shallowest wins, ties the first visited
// (PlanJobParams: soft_finger_radius_m over quality.contact's, plan.seed and
// plan.time_limit_s over cord's and quality.seed, which plan_job overwrites from them anyway).
#include <pybind11/pybind11.h>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "cordgrasp/core/serialize.h"
#include "cordgrasp/jobs/parse_name.h"

namespace cordgrasp::python {

namespace py = pybind11;

/// One settable leaf field of a parameter struct instance.
struct FlatField {
  std::string path;  ///< e.g. "plan.finger.close_step"
  int depth = 0;
  std::function<py::object()> get;
  std::function<void(py::handle)> set;
};

template <typename T>
struct IsOptional : std::false_type {};
template <typename T>
struct IsOptional<std::optional<T>> : std::true_type {};

/// Collects the leaves of one struct instance by flat name.
class FlatFieldsArchive {
 public:
  template <typename T>
  void Visit(const NameValuePair<T>& nvp) {
    const std::string path = prefix_.empty() ? nvp.name : prefix_ + "." + nvp.name;
    if constexpr (is_struct<T>()) {
      FlatFieldsArchive nested(fields_, path, depth_ + 1);
      nvp.value->Serialize(&nested);
    } else {
      add(nvp.name, path, nvp.value);
    }
  }

  explicit FlatFieldsArchive(std::map<std::string, FlatField>* fields,
                             std::string prefix = "", int depth = 0)
      : fields_(fields), prefix_(std::move(prefix)), depth_(depth) {}

 private:
  template <typename T>
  static constexpr bool is_struct() {
    return std::is_class_v<T> && !std::is_same_v<T, std::string> && !IsOptional<T>::value;
  }
  template <typename T>
  static py::object to_py(const T& v) {
    if constexpr (std::is_enum_v<T>) {
      return py::str(to_string(v));
    } else {
      return py::cast(v);
    }
  }
  template <typename T>
  static void from_py(py::handle h, const std::string& name, T* out) {
    if constexpr (std::is_enum_v<T>) {
      parse_name(py::cast<std::string>(h), out);
    } else if constexpr (std::is_same_v<T, bool>) {
      if (!py::isinstance<py::bool_>(h)) throw py::type_error(name + ": expected True or False");
      *out = h.cast<bool>();
    } else if constexpr (std::is_integral_v<T>) {
      if (py::isinstance<py::bool_>(h) || !py::isinstance<py::int_>(h))
        throw py::type_error(name + ": expected an integer");
      *out = h.cast<T>();
    } else {
      *out = h.cast<T>();
    }
  }
  template <typename T>
  void add(const std::string& name, const std::string& path, T* value) {
    const auto it = fields_->find(name);
    if (it != fields_->end() && it->second.depth <= depth_) return;
    FlatField f;
    f.path = path;
    f.depth = depth_;
    if constexpr (IsOptional<T>::value) {
      using V = typename T::value_type;
      f.get = [value]() { return *value ? to_py(**value) : py::none(); };
      f.set = [value, name](py::handle h) {
        if (h.is_none()) return value->reset();
        V v{};
        from_py(h, name, &v);
        *value = v;
      };
    } else {
      f.get = [value]() { return to_py(*value); };
      f.set = [value, name](py::handle h) { from_py(h, name, value); };
    }
    (*fields_)[name] = std::move(f);
  }

  std::map<std::string, FlatField>* fields_;
  std::string prefix_;
  int depth_;
};

/// The flat fields of `*params` (pointers into it).
template <typename T>
std::map<std::string, FlatField> flat_fields(T* params) {
  std::map<std::string, FlatField> fields;
  FlatFieldsArchive archive(&fields);
  params->Serialize(&archive);
  return fields;
}

/// Sets the fields of `*params` named by `kwargs`. @throws py::type_error for unknown names.
template <typename T>
void set_from_kwargs(T* params, const py::dict& kwargs) {
  auto fields = flat_fields(params);
  for (const auto& item : kwargs) {
    const std::string name = py::cast<std::string>(item.first);
    const auto it = fields.find(name);
    if (it == fields.end()) throw py::type_error("unexpected keyword argument '" + name + "'");
    it->second.set(item.second);
  }
}

/// {name: default} of every flat field of a default-constructed T.
template <typename T>
py::dict defaults_dict() {
  T params;
  py::dict d;
  for (auto& [name, f] : flat_fields(&params)) d[py::str(name)] = f.get();
  return d;
}

}  // namespace cordgrasp::python
