#include "ply_check.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <set>
#include <vector>

#include "mesh_text.h"

// The rules below follow the reader of assimp 5.2.5 (Debian 12's libassimp5; its source:
// code/AssetLib/Ply/PlyParser.cpp, PlyLoader.cpp, include/assimp/IOStreamBuffer.h), read, not
// copied: how it splits lines, reads the header and walks the body.

namespace cordgrasp::detail {
namespace {

enum class Kind { kUnsigned, kSigned, kReal };

struct PlyType {
  const char* name;
  int bytes;
  Kind kind;
};

constexpr PlyType kPlyTypes[] = {
    {"char", 1, Kind::kSigned},     {"int8", 1, Kind::kSigned},     {"uchar", 1, Kind::kUnsigned},
    {"uint8", 1, Kind::kUnsigned},  {"short", 2, Kind::kSigned},    {"int16", 2, Kind::kSigned},
    {"ushort", 2, Kind::kUnsigned}, {"uint16", 2, Kind::kUnsigned}, {"int", 4, Kind::kSigned},
    {"int32", 4, Kind::kSigned},    {"uint", 4, Kind::kUnsigned},   {"uint32", 4, Kind::kUnsigned},
    {"float", 4, Kind::kReal},      {"float32", 4, Kind::kReal},    {"double", 8, Kind::kReal},
    {"float64", 8, Kind::kReal}};

// The element names whose entry counts assimp reads (it takes any other for 0 entries).
constexpr const char* kElementNames[] = {"vertex", "face", "tristrips", "edge", "material"};

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

bool is_line_end(int c) { return c >= 0 && is_assimp_line_end(static_cast<char>(c)); }

// The file through a buffer, split into lines as assimp's IOStreamBuffer::getNextLine splits
// it: a line ends at CR, LF, NUL or FF (the one character is consumed), and a line that starts
// at such a character is skipped through the next LF (so "\r\n" ends one line, one blank line
// disappears, two give an empty line, and "\n\0text\n" hides "text").
class AssimpLines {
 public:
  explicit AssimpLines(const std::string& path) : in_(path, std::ios::binary), buffer_(1 << 20) {}

  /// The next line, false at the end of the file. `number` is its line in an editor (LFs + 1).
  bool next(std::string& line, size_t* number) {
    if (peek() < 0) return false;
    if (is_line_end(peek()))
      for (int c = get(); c != '\n'; c = get())
        if (c < 0) return false;
    if (number) *number = line_feeds_ + 1;
    line.clear();
    for (int c = peek(); c >= 0 && !is_line_end(c); c = peek()) {
      // Copy the run up to the next line end at once.
      const char* begin = buffer_.data() + pos_;
      const char* end = buffer_.data() + size_;
      const char* stop = begin;
      while (stop != end && !is_line_end(static_cast<unsigned char>(*stop))) ++stop;
      line.append(begin, stop);
      pos_ += size_t(stop - begin);
    }
    terminator_ = get();
    return true;
  }

  /// What ended the last line (-1: the end of the file).
  int terminator() const { return terminator_; }
  int peek() {
    if (pos_ == size_ && !fill()) return -1;
    return static_cast<unsigned char>(buffer_[pos_]);
  }
  int get() {
    const int c = peek();
    if (c >= 0) ++pos_;
    if (c == '\n') ++line_feeds_;
    return c;
  }
  /// Reads n bytes (n <= 8); false at the end of the file.
  bool read(unsigned char* out, size_t n) {
    for (size_t k = 0; k < n; ++k) {
      const int c = get();
      if (c < 0) return false;
      out[k] = static_cast<unsigned char>(c);
    }
    return true;
  }
  /// Skips n bytes; false if the file ends first.
  bool skip(std::uintmax_t n) {
    while (n > 0) {
      if (pos_ == size_ && !fill()) return false;
      const std::uintmax_t step = std::min<std::uintmax_t>(n, size_ - pos_);
      pos_ += size_t(step);
      n -= step;
    }
    return true;
  }
  std::uintmax_t offset() const { return consumed_ - (size_ - pos_); }

 private:
  bool fill() {
    in_.read(buffer_.data(), std::streamsize(buffer_.size()));
    size_ = size_t(in_.gcount());
    pos_ = 0;
    consumed_ += size_;
    return size_ > 0;
  }

  std::ifstream in_;
  std::vector<char> buffer_;
  size_t pos_ = 0, size_ = 0;
  std::uintmax_t consumed_ = 0;  // bytes read into the buffer so far
  size_t line_feeds_ = 0;
  int terminator_ = -1;
};

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


std::string at_line(size_t line) { return "PLY line " + std::to_string(line) + ": "; }

std::string entry_of(const PlyElement& element, unsigned long long entry) {
  return "element " + quoted_text(element.name) + " entry " + std::to_string(entry);
}

// ASCII body: one entry per line (as assimp splits lines), its values separated by spaces or
// tabs, each a whole value of its type (assimp reads a value up to the first character it
// cannot use and the next one from there), no fewer values than properties (past the line's
// end assimp reads the bytes of earlier lines) and a list's count no more than the values left
// on its line.
std::string check_ascii_body(AssimpLines& lines, const std::vector<PlyElement>& elements) {
  std::string line;
  size_t number = 0;
  for (const PlyElement& element : elements)
    for (unsigned long long i = 0; i < element.count; ++i) {
      if (!lines.next(line, &number))
        return "PLY file ends before " + entry_of(element, i) + " (of " +
               std::to_string(element.count) + ")";
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
      if (values_left == 0 && !element.properties.empty())
        return at_line(number) + "blank where " + entry_of(element, i) + " should be";
      c = line.c_str();
      for (const PlyProperty& p : element.properties) {
        const char* b = nullptr;
        const char* e = nullptr;
        if (!next(&b, &e))
          return at_line(number) + entry_of(element, i) + " has fewer values than properties";
        --values_left;
        if (!p.count) {
          if (!is_value(b, e, p.value->kind))
            return at_line(number) + quoted_text(b, e) + " is not a " + p.value->name + " (" +
                   entry_of(element, i) + ")";
          continue;
        }
        if (!is_value(b, e, Kind::kUnsigned))
          return at_line(number) + quoted_text(b, e) + " is not a list count (" +
                 entry_of(element, i) + ")";
        unsigned long long n = 0;
        for (const char* d = b; d != e && n <= values_left; ++d) n = 10 * n + unsigned(*d - '0');
        if (n > values_left)
          return at_line(number) + entry_of(element, i) + " lists " + quoted_text(b, e) +
                 " values, more than the " + std::to_string(values_left) + " on its line";
        for (unsigned long long k = 0; k < n; ++k) {
          next(&b, &e);
          --values_left;
          if (!is_value(b, e, p.value->kind))
            return at_line(number) + quoted_text(b, e) + " is not a " + p.value->name + " (" +
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
std::string check_binary_body(AssimpLines& bytes, const std::vector<PlyElement>& elements,
                              std::uintmax_t file_bytes, bool big_endian) {
  size_t walk_to = 0;
  for (size_t e = 0; e < elements.size(); ++e)
    for (const PlyProperty& p : elements[e].properties)
      if (p.count && (p.count->bytes > 1 || p.count->kind == Kind::kSigned)) walk_to = e + 1;
  const uint16_t probe = 1;
  unsigned char first_byte;
  std::memcpy(&first_byte, &probe, 1);
  const bool swap = big_endian == (first_byte == 1);
  auto ends_before = [](const PlyElement& element, unsigned long long i) {
    return "PLY file ends before " + entry_of(element, i) + " (of " +
           std::to_string(element.count) + ")";
  };
  for (size_t e = 0; e < walk_to; ++e) {
    const PlyElement& element = elements[e];
    bool has_list = false;
    std::uintmax_t stride = 0;
    for (const PlyProperty& p : element.properties) {
      has_list |= p.count != nullptr;
      stride += p.value->bytes;
    }
    if (!has_list) {  // entries of one size: skip them at once
      if (!bytes.skip(element.count * stride)) return ends_before(element, 0);
      continue;
    }
    for (unsigned long long i = 0; i < element.count; ++i)
      for (const PlyProperty& p : element.properties) {
        if (!p.count) {
          if (!bytes.skip(p.value->bytes)) return ends_before(element, i);
          continue;
        }
        unsigned char raw[4];
        if (!bytes.read(raw, size_t(p.count->bytes))) return ends_before(element, i);
        const bool s = p.count->kind == Kind::kSigned;
        long long n = 0;
        if (p.count->bytes == 1)
          n = s ? read_count<int8_t>(raw, swap) : read_count<uint8_t>(raw, swap);
        else if (p.count->bytes == 2)
          n = s ? read_count<int16_t>(raw, swap) : read_count<uint16_t>(raw, swap);
        else
          n = s ? read_count<int32_t>(raw, swap) : read_count<uint32_t>(raw, swap);
        const std::uintmax_t left = file_bytes - std::min(file_bytes, bytes.offset());
        if (n < 0 || std::uintmax_t(n) * std::uintmax_t(p.value->bytes) > left)
          return "PLY " + entry_of(element, i) + " lists " + std::to_string(n) +
                 " values, more than the " + std::to_string(left) + " bytes left in the file";
        if (!bytes.skip(std::uintmax_t(n) * p.value->bytes)) return ends_before(element, i);
      }
  }
  return {};
}

}  // namespace

std::string ply_problem(const std::string& path, std::uintmax_t file_bytes) {
  AssimpLines lines(path);
  std::string line;
  size_t number = 0;
  // assimp takes the file for PLY when its first line starts with "ply" in any case.
  if (!lines.next(line, &number) || line.size() < 3 ||
      std::tolower(static_cast<unsigned char>(line[0])) != 'p' ||
      std::tolower(static_cast<unsigned char>(line[1])) != 'l' ||
      std::tolower(static_cast<unsigned char>(line[2])) != 'y')
    return {};
  // The format on the second line.
  if (!lines.next(line, &number)) return "PLY header without an 'end_header' line";
  const std::vector<std::string> format_words = split_words(line);
  const std::string format = format_words.size() >= 2 && format_words[0] == "format"
                                 ? format_words[1]
                                 : std::string();
  if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
    return at_line(number) +
           "the line after 'ply' must be 'format ascii|binary_little_endian|binary_big_endian'";
  // The header, within what assimp reads the same way: comments and obj_info lines before the
  // first element; then element lines, each followed by its property lines, where a comment,
  // obj_info or blank line ends the element's properties (assimp 5.2 ignores later ones) and
  // only an element line or end_header may follow it.
  std::vector<PlyElement> elements;
  std::set<std::string> names;
  bool in_properties = false;  // the last line was an element or a property line
  while (lines.next(line, &number)) {
    const std::vector<std::string> words = split_words(line);
    const std::string keyword = words.empty() ? std::string() : words[0];
    if (keyword == "end_header") {
      if (words.size() != 1) return at_line(number) + "text after 'end_header'";
      if (format == "ascii") return check_ascii_body(lines, elements);
      // assimp drops an LF that opens the body, there to skip the LF of "end_header\r\n":
      // after "end_header\n" it drops a data byte.
      if (lines.peek() == '\n') {
        if (lines.terminator() == '\n')
          return "a binary PLY body starting with a line-feed byte (0x0A) after "
                 "\"end_header\\n\": assimp 5.2 drops it and would read every value a byte late";
        lines.get();
      }
      return check_binary_body(lines, elements, file_bytes, format == "binary_big_endian");
    }
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") {
      in_properties = false;
      // Newer assimp opens an element at any comment: "comment vertex 12" and "comment 12"
      // would have 12 entries.
      const bool named = words.size() > 2 && std::find(std::begin(kElementNames),
                                                       std::end(kElementNames), words[1]) !=
                                                 std::end(kElementNames);
      const std::string* count = named ? &words[2] : words.size() > 1 ? &words[1] : nullptr;
      const std::string digits =
          count ? count->substr(0, count->find_first_not_of("0123456789")) : std::string();
      if (keyword == "comment" && digits.find_first_not_of('0') != std::string::npos)
        return at_line(number) + "a comment assimp would read as an element of " +
               quoted_text(*count) + " entries";
    } else if (keyword == "element") {
      PlyElement element;
      if (words.size() != 3 || !all_digits(words[2].data(), words[2].data() + words[2].size()))
        return at_line(number) + "an element line is 'element NAME COUNT'";
      element.name = words[1];
      if (words[2].size() > 18 || (element.count = std::stoull(words[2])) > file_bytes)
        return "PLY element " + quoted_text(element.name) + " claims " + words[2].substr(0, 24) +
               " entries, more than the file's " + std::to_string(file_bytes) + " bytes";
      if (element.count > 0 && std::find(std::begin(kElementNames), std::end(kElementNames),
                                         element.name) == std::end(kElementNames))
        return at_line(number) + "element " + quoted_text(element.name) +
               ": assimp 5.2 reads the entries of vertex, face, tristrips, edge and material "
               "elements only (it would take these for none and misread the rest)";
      if (!names.insert(element.name).second)
        return at_line(number) + "element " + quoted_text(element.name) + " defined twice";
      elements.push_back(element);
      in_properties = true;
    } else if (keyword == "property") {
      if (elements.empty()) return at_line(number) + "a property before any element";
      if (!in_properties)
        return at_line(number) +
               "a property after a comment or a blank line (assimp 5.2 ends the element's "
               "properties there)";
      PlyProperty property;
      const bool list = words.size() == 5 && words[1] == "list";
      // assimp reads the count type right after "list" and one space or tab.
      const size_t after_list = line.find("list") + 4;
      if (list && (line.size() <= after_list + 1 || line[after_list + 1] == ' ' ||
                   line[after_list + 1] == '\t'))
        return at_line(number) + "more than one space after 'list'";
      if (!list && words.size() != 3)
        return at_line(number) +
               "a property line is 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'";
      property.value = find_type(words[list ? 3 : 1]);
      if (!property.value)
        return at_line(number) + "unknown property type " + quoted_text(words[list ? 3 : 1]);
      if (list) {
        property.count = find_type(words[2]);
        if (!property.count || property.count->kind == Kind::kReal)
          return at_line(number) + "a list's count type must be an integer type, not " +
                 quoted_text(words[2]);
      }
      elements.back().properties.push_back(property);
    } else {
      return at_line(number) + quoted_text(keyword) + " is not a PLY header keyword";
    }
  }
  return "PLY header without an 'end_header' line";
}

}  // namespace cordgrasp::detail
