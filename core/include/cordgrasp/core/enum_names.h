#pragma once
// Name tables behind each enum's to_string / parse_<enum> pair (one table per enum, in the
// library that owns the enum).
#include <cstddef>
#include <stdexcept>
#include <string>

namespace cordgrasp {

/// One enumerator and its name.
template <typename E>
struct EnumName {
  E value;
  const char* name;
};

/// The name of `value` in `table` ("?" when it is missing, which is a bug).
template <typename E, std::size_t N>
const char* enum_to_string(E value, const EnumName<E> (&table)[N]) {
  for (const EnumName<E>& entry : table)
    if (entry.value == value) return entry.name;
  return "?";
}

/// The enumerator called `text` in `table`.
/// @throws std::invalid_argument "<what>: unknown name 'x' (allowed: a, b, c)".
template <typename E, std::size_t N>
E parse_enum(const std::string& text, const EnumName<E> (&table)[N], const char* what) {
  std::string allowed;
  for (const EnumName<E>& entry : table) {
    if (text == entry.name) return entry.value;
    allowed += (allowed.empty() ? "" : ", ") + std::string(entry.name);
  }
  throw std::invalid_argument(std::string(what) + ": unknown name '" + text + "' (allowed: " +
                              allowed + ")");
}

}  // namespace cordgrasp
