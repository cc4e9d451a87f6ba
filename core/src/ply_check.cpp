#include "ply_check.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <set>
#include <vector>

namespace cordgrasp::detail {
namespace {

enum class Kind { kUnsigned, kSigned, kReal };

struct PlyType {
  const char* name;
  int bytes;
  Kind kind;
};

constexpr PlyType kPlyTypes[] = {
    {"char", 1, Kind::kSigned},    {"int8", 1, Kind::kSigned},     {"uchar", 1, Kind::kUnsigned},
    {"uint8", 1, Kind::kUnsigned}, {"short", 2, Kind::kSigned},    {"int16", 2, Kind::kSigned},
    {"ushort", 2, Kind::kUnsigned}, {"uint16", 2, Kind::kUnsigned}, {"int", 4, Kind::kSigned},
    {"int32", 4, Kind::kSigned},   {"uint", 4, Kind::kUnsigned},   {"uint32", 4, Kind::kUnsigned},
    {"float", 4, Kind::kReal},     {"float32", 4, Kind::kReal},    {"double", 8, Kind::kReal},
    {"float64", 8, Kind::kReal}};

const PlyType* find_type(const std::string& name) {
  for (const PlyType& t : kPlyTypes)
    if (name == t.name) return &t;
  return nullptr;
}

struct PlyProperty {
  const PlyType* count = nullptr;  // a list's count type; null for a scalar
  const PlyType* value = nullptr;  // the scalar's or the list items' type
};

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::vector<PlyProperty> properties;
};

// What ends a line for assimp's PLY reader besides a line feed.
const std::string kLineEnds("\r\f\0", 3);

std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  for (size_t b = line.find_first_not_of(" \t"); b != std::string::npos;) {
    const size_t e = std::min(line.size(), line.find_first_of(" \t", b));
    words.push_back(line.substr(b, e - b));
    b = line.find_first_not_of(" \t", e);
  }
  return words;
}

bool all_digits(const char* b, const char* e) {
  if (b == e) return false;
  for (; b != e; ++b)
    if (*b < '0' || *b > '9') return false;
  return true;
}

// Whether the text is one whole value of the kind, as assimp's readers (strtoul10, strtol10,
// fast_atoreal_move) would consume it to its end.
bool is_value(const char* b, const char* e, Kind kind) {
  if (kind == Kind::kUnsigned) return all_digits(b, e);
  if (b != e && (*b == '-' || *b == '+')) ++b;
  if (kind == Kind::kSigned) return all_digits(b, e);
  const char* digits = b;
  while (b != e && *b >= '0' && *b <= '9') ++b;
  bool mantissa = b != digits;
  if (b != e && *b == '.') {
    const char* fraction = ++b;
    while (b != e && *b >= '0' && *b <= '9') ++b;
    mantissa |= b != fraction;
  }
  if (!mantissa) return false;
  if (b != e && (*b == 'e' || *b == 'E')) {
    ++b;
    if (b != e && (*b == '-' || *b == '+')) ++b;
    return all_digits(b, e);
  }
  return b == e;
}

// Up to 24 characters of file text for a message, bytes outside printable ASCII as '?'.
std::string quoted(const char* b, const char* e) {
  std::string text = "'";
  for (const char* c = b; c != e && c != b + 24; ++c) text += (*c >= 0x20 && *c < 0x7f) ? *c : '?';
  return text + (e - b > 24 ? "...'" : "'");
}
std::string quoted(const std::string& s) { return quoted(s.data(), s.data() + s.size()); }

std::string at_line(size_t line) { return "PLY line " + std::to_string(line) + ": "; }

std::string entry_of(const PlyElement& element, unsigned long long entry) {
  return "element " + quoted(element.name) + " entry " + std::to_string(entry);
}

// ASCII body: one entry per line, its values separated by spaces or tabs, each a whole number
// of its type; a list's count no more than the values left on its line.
std::string check_ascii_body(std::istream& in, size_t line_number,
                             const std::vector<PlyElement>& elements) {
  std::string line;
  for (const PlyElement& element : elements)
    for (unsigned long long i = 0; i < element.count; ++i) {
      ++line_number;
      if (!std::getline(in, line)) return {};  // a short file: assimp's to judge
      if (!line.empty() && line.back() == '\r') line.pop_back();
      // assimp reads the body line by line, a CR, NUL or form feed also ending a line, and skips
      // some blank lines but not others: such lines would shift its entries against these.
      if (line.find_first_of(kLineEnds) != std::string::npos)
        return at_line(line_number) + "a carriage return, form feed or NUL inside a line";
      const char* c = line.c_str();
      const char* end = c + line.size();
      auto next = [&c, end](const char** b, const char** e) {
        while (c != end && (*c == ' ' || *c == '\t')) ++c;
        *b = c;
        while (c != end && *c != ' ' && *c != '\t') ++c;
        *e = c;
        return *e != *b;
      };
      size_t values_left = 0;
      for (const char *b, *e; next(&b, &e);) ++values_left;
      if (values_left == 0)
        return at_line(line_number) + "blank where " + entry_of(element, i) + " should be";
      c = line.c_str();
      for (const PlyProperty& p : element.properties) {
        const char* b = nullptr;
        const char* e = nullptr;
        if (!next(&b, &e))
          return at_line(line_number) + entry_of(element, i) + " has fewer values than its properties";
        --values_left;
        if (!p.count) {
          if (!is_value(b, e, p.value->kind))
            return at_line(line_number) + quoted(b, e) + " is not a " + p.value->name + " (" +
                 entry_of(element, i) + ")";
          continue;
        }
        if (!is_value(b, e, Kind::kUnsigned))
          return at_line(line_number) + quoted(b, e) + " is not a list count (" +
                 entry_of(element, i) + ")";
        unsigned long long n = 0;
        for (const char* d = b; d != e && n <= values_left; ++d) n = 10 * n + unsigned(*d - '0');
        if (n > values_left)
          return at_line(line_number) + entry_of(element, i) + " lists " + quoted(b, e) +
                 " values, more than the " + std::to_string(values_left) + " on its line";
        for (unsigned long long k = 0; k < n; ++k) {
          next(&b, &e);
          --values_left;
          if (!is_value(b, e, p.value->kind))
            return at_line(line_number) + quoted(b, e) + " is not a " + p.value->name + " (" +
                 entry_of(element, i) + ")";
        }
      }
    }
  return {};
}

template <typename T>
long long read_count(const unsigned char* raw, bool swap) {
  unsigned char b[sizeof(T)];
  for (size_t k = 0; k < sizeof(T); ++k) b[k] = raw[swap ? sizeof(T) - 1 - k : k];
  T value;
  std::memcpy(&value, b, sizeof(T));
  return static_cast<long long>(value);
}

// Binary body: each list's count, read in its type and the file's byte order, is >= 0 and its
// values fit in the bytes left. Elements after the last list that could ask for much (a count
// wider than a byte, or signed) need no walk.
std::string check_binary_body(std::istream& in, std::uintmax_t at,
                              const std::vector<PlyElement>& elements, std::uintmax_t file_bytes,
                              bool big_endian) {
  size_t walk_to = 0;
  for (size_t e = 0; e < elements.size(); ++e)
    for (const PlyProperty& p : elements[e].properties)
      if (p.count && (p.count->bytes > 1 || p.count->kind == Kind::kSigned)) walk_to = e + 1;
  const uint16_t probe = 1;
  unsigned char first_byte;
  std::memcpy(&first_byte, &probe, 1);
  const bool swap = big_endian == (first_byte == 1);
  for (size_t e = 0; e < walk_to; ++e) {
    const PlyElement& element = elements[e];
    bool has_list = false;
    std::uintmax_t stride = 0;
    for (const PlyProperty& p : element.properties) {
      has_list |= p.count != nullptr;
      stride += p.value->bytes;
    }
    if (!has_list) {  // entries of one size: skip them at once
      if (stride != 0 && element.count > (file_bytes - at) / stride) return {};
      at += element.count * stride;
      in.ignore(std::streamsize(element.count * stride));
      continue;
    }
    for (unsigned long long i = 0; i < element.count; ++i)
      for (const PlyProperty& p : element.properties) {
        if (!p.count) {
          if (!in.ignore(p.value->bytes)) return {};
          at += p.value->bytes;
          continue;
        }
        unsigned char raw[4];
        if (!in.read(reinterpret_cast<char*>(raw), p.count->bytes)) return {};
        at += p.count->bytes;
        const bool s = p.count->kind == Kind::kSigned;
        const long long n = p.count->bytes == 1 ? (s ? read_count<int8_t>(raw, swap) : read_count<uint8_t>(raw, swap))
                            : p.count->bytes == 2 ? (s ? read_count<int16_t>(raw, swap) : read_count<uint16_t>(raw, swap))
                                                  : (s ? read_count<int32_t>(raw, swap) : read_count<uint32_t>(raw, swap));
        const std::uintmax_t left = file_bytes - std::min(file_bytes, at);
        if (n < 0 || std::uintmax_t(n) * std::uintmax_t(p.value->bytes) > left)
          return "PLY " + entry_of(element, i) + " lists " + std::to_string(n) +
                 " values, more than the " + std::to_string(left) + " bytes left in the file";
        if (!in.ignore(std::streamsize(n * p.value->bytes))) return {};
        at += std::uintmax_t(n) * p.value->bytes;
      }
  }
  return {};
}

}  // namespace

std::string ply_problem(const std::string& path, std::uintmax_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  // The magic may follow blank lines and spaces: assimp's reader skips them too.
  size_t magic = std::string::npos, line_number = 0;
  while (magic == std::string::npos && std::getline(in, line)) {
    ++line_number;
    magic = line.find_first_not_of(" \t\r\v\f");
  }
  if (magic == std::string::npos || line.compare(magic, 3, "ply") != 0) return {};
  // assimp reads the header by its own rules (a comment can open an element, an unknown type
  // ends an element's properties, a CR or NUL ends a line): a header it could read otherwise
  // than this one is refused, so that the body below is walked as assimp walks it.
  std::string format;
  std::vector<PlyElement> elements;
  std::set<std::string> names;
  while (std::getline(in, line)) {
    ++line_number;
    const bool crlf = !line.empty() && line.back() == '\r';
    if (crlf) line.pop_back();
    if (line.find_first_of(kLineEnds) != std::string::npos)
      return at_line(line_number) + "a carriage return, form feed or NUL inside the header";
    const std::vector<std::string> words = split_words(line);
    if (words.empty()) continue;
    const std::string& keyword = words[0];
    if (keyword == "end_header" && words.size() == 1) {
      if (format == "ascii") return check_ascii_body(in, line_number, elements);
      if (format == "binary_little_endian" || format == "binary_big_endian") {
        // assimp 5.2 drops a line feed that opens its copy of the body, there to skip the LF
        // of "end_header\r\n": after "end_header\n" it drops a data byte.
        if (!crlf && in.peek() == '\n')
          return "a binary PLY body starting with a line-feed byte (0x0A) after \"end_header\\n\": "
                 "assimp 5.2 drops it and would read every value a byte late";
        const std::streamoff at = in.tellg();
        return check_binary_body(in, at < 0 ? file_bytes : std::uintmax_t(at), elements, file_bytes,
                                 format == "binary_big_endian");
      }
      return at_line(line_number) + "no 'format ascii|binary_little_endian|binary_big_endian' line";
    }
    if (keyword == "format") {
      if (words.size() < 2) return at_line(line_number) + "a 'format' line without its format";
      format = words[1];
    } else if (keyword == "comment" || keyword == "obj_info") {
      // assimp opens an element at a comment: "comment vertex 12 ..." has 12 entries, as has
      // "comment 12 ..." (a nameless one); with no properties each takes a line of the body.
      static const char* kElementWords[] = {"vertex", "face", "tristrips", "edge", "material"};
      const bool named = words.size() > 2 && std::find(std::begin(kElementWords),
                                                       std::end(kElementWords), words[1]) !=
                                                 std::end(kElementWords);
      const std::string* count = named ? &words[2] : words.size() > 1 ? &words[1] : nullptr;
      const std::string digits =
          count ? count->substr(0, count->find_first_not_of("0123456789")) : std::string();
      if (keyword == "comment" && digits.find_first_not_of('0') != std::string::npos)
        return at_line(line_number) + "a comment assimp would read as an element of " +
               quoted(*count) + " entries";
    } else if (keyword == "element") {
      PlyElement element;
      if (words.size() != 3 || !all_digits(words[2].data(), words[2].data() + words[2].size()))
        return at_line(line_number) + "an element line is 'element NAME COUNT'";
      element.name = words[1];
      if (words[2].size() > 18 || (element.count = std::stoull(words[2])) > file_bytes)
        return "PLY element " + quoted(element.name) + " claims " + words[2].substr(0, 24) +
               " entries, more than the file's " + std::to_string(file_bytes) + " bytes";
      if (!names.insert(element.name).second)
        return at_line(line_number) + "element " + quoted(element.name) + " defined twice";
      elements.push_back(element);
    } else if (keyword == "property") {
      if (elements.empty()) return at_line(line_number) + "a property before any element";
      PlyProperty property;
      const bool list = words.size() == 5 && words[1] == "list";
      if (!list && words.size() != 3)
        return at_line(line_number) + "a property line is 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'";
      property.value = find_type(words[list ? 3 : 1]);
      if (!property.value)
        return at_line(line_number) + "unknown property type " + quoted(words[list ? 3 : 1]);
      if (list) {
        property.count = find_type(words[2]);
        if (!property.count || property.count->kind == Kind::kReal)
          return at_line(line_number) + "a list's count type must be an integer type, not " +
                 quoted(words[2]);
      }
      elements.back().properties.push_back(property);
    } else {
      return at_line(line_number) + quoted(keyword) + " is not a PLY header keyword";
    }
  }
  return "PLY header without an 'end_header' line";
}

}  // namespace cordgrasp::detail
