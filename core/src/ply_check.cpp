#include "ply_check.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

namespace cordgrasp::detail {
namespace {

struct PlyProperty {
  int count_bytes = 0;  // 0: a scalar; else a list whose count takes this many bytes (binary)
  bool count_signed = false;
  int value_bytes = 0;  // a scalar's or a list item's size in a binary file
};

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::vector<PlyProperty> properties;
};

// Size of a PLY scalar type in bytes (0: unknown), and whether it is signed.
int type_bytes(const std::string& type, bool* is_signed = nullptr) {
  struct Type {
    const char* name;
    int bytes;
    bool is_signed;
  };
  static const Type kTypes[] = {{"char", 1, true},     {"int8", 1, true},     {"uchar", 1, false},
                                {"uint8", 1, false},   {"short", 2, true},    {"int16", 2, true},
                                {"ushort", 2, false},  {"uint16", 2, false},  {"int", 4, true},
                                {"int32", 4, true},    {"uint", 4, false},    {"uint32", 4, false},
                                {"float", 4, true},    {"float32", 4, true},  {"double", 8, true},
                                {"float64", 8, true}};
  for (const Type& t : kTypes)
    if (type == t.name) {
      if (is_signed) *is_signed = t.is_signed;
      return t.bytes;
    }
  return 0;
}

std::string too_many(const std::string& element, unsigned long long entry, const std::string& count,
                     std::uintmax_t bytes) {
  return "PLY element '" + element + "' entry " + std::to_string(entry) + " lists " +
         count.substr(0, 24) + (count.size() > 24 ? "..." : "") + " values, more than the " +
         std::to_string(bytes) + " bytes left in the file";
}

// ASCII body: one element entry per line (blank lines skipped); a list's count is its token's
// leading digits. Stops quietly where the body no longer matches the header (assimp's to judge).
std::string check_ascii_body(std::istream& in, const std::vector<PlyElement>& elements,
                             std::uintmax_t file_bytes) {
  std::string line;
  std::uintmax_t at = in.tellg() < 0 ? file_bytes : std::uintmax_t(in.tellg());
  for (const PlyElement& element : elements) {
    bool has_list = false;
    for (const PlyProperty& p : element.properties) has_list |= p.count_bytes > 0;
    for (unsigned long long i = 0; i < element.count; ++i) {
      do {
        if (!std::getline(in, line)) return {};
        at += line.size() + 1;
      } while (line.find_first_not_of(" \t\r\v\f") == std::string::npos);
      if (!has_list) continue;
      const std::uintmax_t left = file_bytes - std::min(file_bytes, at);
      const char* c = line.c_str();
      auto next_token = [&c](const char** begin) {
        while (*c && std::strchr(" \t\r\v\f", *c)) ++c;
        *begin = c;
        while (*c && !std::strchr(" \t\r\v\f", *c)) ++c;
        return c > *begin;
      };
      for (const PlyProperty& p : element.properties) {
        const char* token = nullptr;
        if (!next_token(&token)) break;
        if (p.count_bytes == 0) continue;
        const char* digits_end = token;
        while (*digits_end >= '0' && *digits_end <= '9') ++digits_end;
        const std::string digits(token, digits_end);
        // The values of this entry lie on its line: a count past the line's bytes left and
        // the file's is what made assimp reserve gigabytes.
        if (digits.size() > 18 || (!digits.empty() && std::stoull(digits) > left + line.size()))
          return too_many(element.name, i, digits, left + line.size());
        const unsigned long long n = digits.empty() ? 0 : std::stoull(digits);
        for (unsigned long long k = 0; k < n && next_token(&token); ++k) {
        }
      }
    }
  }
  return {};
}

template <typename T>
T read_as(const unsigned char* bytes, int size, bool swap) {
  unsigned char b[8];
  for (int k = 0; k < size; ++k) b[k] = bytes[swap ? size - 1 - k : k];
  T value;
  std::memcpy(&value, b, sizeof(T));
  return value;
}

// Binary body: a list's count read in its type and the file's byte order.
std::string check_binary_body(std::istream& in, const std::vector<PlyElement>& elements,
                              std::uintmax_t file_bytes, bool big_endian) {
  // Lists with a count of one byte cannot ask for much: only walk up to the last element
  // holding a wider count.
  size_t last = elements.size();
  for (size_t e = 0; e < elements.size(); ++e)
    for (const PlyProperty& p : elements[e].properties)
      if (p.count_bytes > 1) last = e;
  if (last == elements.size()) return {};
  const uint16_t probe = 1;
  unsigned char first_byte;
  std::memcpy(&first_byte, &probe, 1);
  const bool swap = big_endian == (first_byte == 1);
  std::uintmax_t at = in.tellg() < 0 ? file_bytes : std::uintmax_t(in.tellg());
  for (size_t e = 0; e <= last; ++e) {
    const PlyElement& element = elements[e];
    bool has_list = false;
    std::uintmax_t stride = 0;
    for (const PlyProperty& p : element.properties) {
      has_list |= p.count_bytes > 0;
      stride += p.value_bytes;
    }
    if (!has_list) {  // fixed-size entries: skip them at once
      if (stride != 0 && element.count > (file_bytes - at) / stride) return {};
      at += element.count * stride;
      in.ignore(std::streamsize(element.count * stride));
      continue;
    }
    for (unsigned long long i = 0; i < element.count; ++i)
      for (const PlyProperty& p : element.properties) {
        if (p.count_bytes == 0) {
          if (!in.ignore(p.value_bytes)) return {};
          at += p.value_bytes;
          continue;
        }
        unsigned char raw[8];
        if (!in.read(reinterpret_cast<char*>(raw), p.count_bytes)) return {};
        at += p.count_bytes;
        long long n = 0;
        switch (p.count_bytes) {
          case 1: n = p.count_signed ? read_as<int8_t>(raw, 1, swap) : read_as<uint8_t>(raw, 1, swap); break;
          case 2: n = p.count_signed ? read_as<int16_t>(raw, 2, swap) : read_as<uint16_t>(raw, 2, swap); break;
          case 4: n = p.count_signed ? read_as<int32_t>(raw, 4, swap) : read_as<uint32_t>(raw, 4, swap); break;
          default: return {};  // a float count: assimp's to judge
        }
        const std::uintmax_t left = file_bytes - std::min(file_bytes, at);
        if (n < 0 || std::uintmax_t(n) * std::uintmax_t(p.value_bytes) > left)
          return too_many(element.name, i, std::to_string(n), left);
        if (!in.ignore(std::streamsize(n * p.value_bytes))) return {};
        at += std::uintmax_t(n) * p.value_bytes;
      }
  }
  return {};
}

}  // namespace

std::string ply_problem(const std::string& path, std::uintmax_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  // The magic may follow blank lines and spaces: assimp's reader skips them too.
  size_t magic = std::string::npos;
  while (magic == std::string::npos && std::getline(in, line))
    magic = line.find_first_not_of(" \t\r\v\f");
  if (magic == std::string::npos || line.compare(magic, 3, "ply") != 0) return {};
  std::string format;
  std::vector<PlyElement> elements;
  bool layout_known = true;  // every property's type understood
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      words >> format;
    } else if (keyword == "element") {
      PlyElement element;
      if (words >> element.name >> element.count && element.count > file_bytes)
        return "PLY element '" + element.name + "' claims " + std::to_string(element.count) +
               " entries, more than the file's " + std::to_string(file_bytes) + " bytes";
      elements.push_back(element);
    } else if (keyword == "property") {
      std::string type;
      words >> type;
      PlyProperty property;
      if (type == "list") {
        std::string count_type, value_type;
        words >> count_type >> value_type;
        property.count_bytes = type_bytes(count_type, &property.count_signed);
        property.value_bytes = type_bytes(value_type);
        layout_known &= property.count_bytes > 0 && property.value_bytes > 0;
      } else {
        property.value_bytes = type_bytes(type);
        layout_known &= property.value_bytes > 0;
      }
      if (elements.empty())
        layout_known = false;
      else
        elements.back().properties.push_back(property);
    }
    const size_t begin = line.find_first_not_of(" \t\r");
    const size_t end = line.find_last_not_of(" \t\r");
    if (begin != std::string::npos && line.compare(begin, end + 1 - begin, "end_header") == 0) {
      if (!layout_known) return {};
      if (format == "ascii") return check_ascii_body(in, elements, file_bytes);
      if (format == "binary_little_endian" || format == "binary_big_endian")
        return check_binary_body(in, elements, file_bytes, format == "binary_big_endian");
      return {};
    }
  }
  return "PLY header without an 'end_header' line";
}

}  // namespace cordgrasp::detail
