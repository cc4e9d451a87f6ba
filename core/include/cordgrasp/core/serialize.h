#pragma once
// The field list of a parameter struct, written once: each struct has
//   template <typename Archive> void Serialize(Archive* a) {
//     visit_fields(a, CORDGRASP_NVP(x), CORDGRASP_NVP(y), ...);
//   }
// visiting every field in declaration order (nested structs as one field each). Readers,
// writers, CLI help and replays walk that list, so they cannot drift apart (the convention of
// Drake's multibody_plant_config.h and drake/common/name_value.h).
namespace cordgrasp {

/// A field's name and its address, as handed to an archive's Visit.
template <typename T>
struct NameValuePair {
  const char* name;
  T* value;
};

/// NameValuePair of `value` called `name`.
template <typename T>
NameValuePair<T> make_nvp(const char* name, T* value) {
  return {name, value};
}

/// Hands each field to a->Visit, in the order given.
template <typename Archive, typename... T>
void visit_fields(Archive* a, NameValuePair<T>... fields) {
  (a->Visit(fields), ...);
}

}  // namespace cordgrasp

/// The field `x` of the struct being serialized, named as written.
#define CORDGRASP_NVP(x) ::cordgrasp::make_nvp(#x, &x)
