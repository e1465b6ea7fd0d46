// The MSH check (msh_check.hpp), one pass over the file's bytes:
//
//   1. $MeshFormat: version 2.2 or 4.1, ASCII (0) or binary (1), data size 8, and in a binary
//      file the integer 1 (the byte order);
//   2. each further section by name, once: its counts, then its entries, then its $End line;
//   3. $Nodes and $Elements present (and $Entities in 4.1).
//
// An ASCII number is one whitespace-separated word, parsed in full; a binary number is read as
// Gmsh reads it (int: 4 bytes, size_t and double: 8). Nothing is allocated from a declared count:
// the entries are read until the count is met or the file ends.
#include "mesh/msh_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/special_file.hpp"

namespace flotsam {
namespace {

constexpr long largest_tag = std::numeric_limits<std::int32_t>::max();  // Gmsh reads tags as int
constexpr long largest_count = largest_tag;
constexpr std::size_t longest_name = 200;  // [chars] a physical name (Gmsh reads 256 a line)

struct ElementType {
  int type;   // Gmsh element type
  int dim;    // its dimension
  int nodes;  // its node count
};

// The element types Gmsh 4.8 creates from an MSH file that flotsam lets through: flotsam reads the
// lines and triangles; the others are named in read_msh's error.
constexpr ElementType element_types[] = {
    {15, 0, 1},                           // point
    {1, 1, 2},  {8, 1, 3},                // 2- and 3-node line
    {2, 2, 3},  {9, 2, 6},                // 3- and 6-node triangle
    {3, 2, 4},  {10, 2, 9},  {16, 2, 8},  // 4-, 9- and 8-node quadrangle
    {4, 3, 4},  {11, 3, 10},              // 4- and 10-node tetrahedron
    {5, 3, 8},  {6, 3, 6},   {7, 3, 5},   // hexahedron, prism, pyramid
};

const ElementType* element_type(long type) {
  for (const ElementType& t : element_types)
    if (t.type == type) return &t;
  return nullptr;
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// What a value is, for messages: a format with up to two numbers, formatted only when a message
// is made (a mesh holds millions of values).
struct What {
  What(const char* text) : format_(text) {}  // NOLINT: plain text converts
  What(const char* format, long first, long second = 0)
      : format_(format), first_(first), second_(second) {}
  std::string text() const { return fmt::format(fmt::runtime(format_), first_, second_); }

 private:
  const char* format_;
  long first_ = 0, second_ = 0;
};

// A read position in the file with the location of what it reads, for messages.
class Cursor {
 public:
  Cursor(const std::string& path, std::string_view bytes) : path_(path), bytes_(bytes) {}

  bool binary = false;       // the data being read is binary
  bool binary_file = false;  // places are given as bytes, not lines
  std::string section;       // the section being read, for messages

  template <class... Args>
  [[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) const {
    const std::string where =
        binary_file ? fmt::format("{}: byte {}", path_, pos_) : fmt::format("{}:{}", path_, line_);
    throw_input_error("{}: {}{}", where, section.empty() ? "" : "$" + section + ": ",
                      fmt::format(format, std::forward<Args>(args)...));
  }

  bool at_end() {
    skip_space();
    return pos_ == bytes_.size();
  }

  // The rest of the current line without its end, and the line end it had ("\n", "\r\n", "").
  std::string_view rest_of_line(std::string_view* end = nullptr) {
    const std::size_t start = pos_;
    const std::size_t newline = bytes_.find('\n', pos_);
    std::size_t stop = newline == std::string_view::npos ? bytes_.size() : newline;
    pos_ = newline == std::string_view::npos ? bytes_.size() : newline + 1;
    if (newline != std::string_view::npos) ++line_;
    std::size_t text_end = stop;
    if (text_end > start && bytes_[text_end - 1] == '\r') --text_end;
    if (end != nullptr) *end = bytes_.substr(text_end, pos_ - text_end);
    return bytes_.substr(start, text_end - start);
  }

  // "$Name" alone on its line (after blank lines): returns Name and keeps the line end for the
  // $EndName line, which Gmsh compares with it.
  std::string start_marker() {
    std::string name = peek_marker();
    rest_of_line(&marker_end_);
    return name;
  }

  // The Name of the "$Name" line start_marker would read, which stays unread.
  std::string peek_marker() {
    skip_space();
    at_line_start("a section's first line ($Name)");
    const std::string_view text = peek_line();
    if (text.empty() || text[0] != '$' || text.size() > 64)
      fail("expected a section's first line ($Name), got '{}'", shorten(text));
    return std::string(text.substr(1));
  }

  // "$EndName" alone on its line: in an ASCII section after blank space, in a binary section
  // right after the data or after one line end.
  void end_marker(const std::string& name) {
    if (binary) {
      if (bytes_.substr(pos_, 2) == "\r\n")
        pos_ += 2;
      else if (bytes_.substr(pos_, 1) == "\n")
        pos_ += 1;
    } else {
      skip_space();
      at_line_start("$End" + name);
    }
    const std::string_view text = peek_line();
    if (text != "$End" + name)
      fail("expected $End{} (the declared counts are met), got '{}'", name, shorten(text));
    std::string_view end;
    rest_of_line(&end);
    if (end != marker_end_ && !(end.empty() && pos_ == bytes_.size()))
      fail("$End{} ends its line differently from ${} (\\n and \\r\\n mixed)", name, name);
  }

  // A line holding one integer (the count lines Gmsh reads with fgets).
  long count_line(const What& what) {
    const std::string_view text = peek_line();
    long value = 0;
    if (!parse_integer(trim(text), value) || value < 0 || value > largest_count)
      fail("expected {} alone on the next line (an integer from 0 to {}), got '{}'", what.text(),
           largest_count, shorten(text));
    rest_of_line();
    return value;
  }

  // The current line without its end, not consumed (rest_of_line consumes it).
  std::string_view peek_line() const {
    std::string_view text = bytes_.substr(pos_, bytes_.find('\n', pos_) - pos_);
    if (text.ends_with('\r')) text.remove_suffix(1);
    return text;
  }

  // The words of the current line, not consumed (the format line Gmsh reads with fgets).
  std::vector<std::string_view> words_of_line() const {
    std::vector<std::string_view> words;
    std::string_view text = peek_line();
    while (!(text = trim(text)).empty()) {
      std::size_t n = 0;
      while (n < text.size() && !is_space(text[n])) ++n;
      words.push_back(text.substr(0, n));
      text.remove_prefix(n);
    }
    return words;
  }

  // An integer Gmsh reads as int (4 bytes in binary).
  long integer(const What& what, long lo, long hi) {
    if (binary) return binary_integer<std::int32_t>(what, lo, hi);
    return text_integer(next_word(), what, lo, hi);
  }

  // An integer Gmsh reads as size_t (8 bytes in a binary 4.1 file).
  long size(const What& what, long lo, long hi) {
    if (binary) return binary_integer<std::uint64_t>(what, lo, hi);
    return text_integer(next_word(), what, lo, hi);
  }

  // A finite real (8 bytes in binary).
  double real(const What& what) {
    double value = 0.0;
    if (!binary) return text_real(next_word(), what);
    read_bytes(&value, sizeof value, what);
    if (!std::isfinite(value)) fail("expected {} (a finite number), got {}", what.text(), value);
    return value;
  }

  double text_real(std::string_view word, const What& what) {
    double value = 0.0;
    const std::string_view digits = word.substr(word.starts_with('+') ? 1 : 0);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || error != std::errc() || end != digits.data() + digits.size() ||
        !std::isfinite(value))
      fail("expected {} (a finite number), got {}", what.text(), quoted(word));
    return value;
  }

  // An integer on the current line after spaces (an ASCII element's node tags).
  long integer_on_line(const What& what, long lo, long hi) {
    while (pos_ < bytes_.size() && bytes_[pos_] == ' ') ++pos_;
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !is_space(bytes_[pos_])) ++pos_;
    if (start == pos_)
      fail("expected {} on the same line, after spaces (Gmsh reads the line at once)", what.text());
    return text_integer(bytes_.substr(start, pos_ - start), what, lo, hi);
  }

  // Nothing but blanks up to the end of the line.
  void end_of_line(const What& what) {
    while (pos_ < bytes_.size() &&
           (bytes_[pos_] == ' ' || bytes_[pos_] == '\t' || bytes_[pos_] == '\r'))
      ++pos_;
    if (pos_ < bytes_.size() && bytes_[pos_] != '\n')
      fail("expected the end of {}'s line, got '{}'", what.text(), shorten(rest_of_line()));
  }

 private:
  static std::string_view trim(std::string_view s) {
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
  }

  static std::string shorten(std::string_view s) {
    std::string out;
    for (char c : s.substr(0, 40)) out += (c >= 32 && c < 127) ? c : '?';
    return s.size() > 40 ? out + "..." : out;
  }

  static std::string quoted(std::string_view word) {
    return word.empty() ? std::string("the end of the file") : "'" + shorten(word) + "'";
  }

  static bool parse_integer(std::string_view word, long& value) {
    if (word.starts_with('+')) word.remove_prefix(1);
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    return !word.empty() && error == std::errc() && end == word.data() + word.size();
  }

  void skip_space() {
    while (pos_ < bytes_.size() && is_space(bytes_[pos_])) {
      if (bytes_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  void at_line_start(std::string_view what) {
    if (pos_ > 0 && pos_ < bytes_.size() && bytes_[pos_ - 1] != '\n')
      fail("expected {} at the start of a line, got '{}'", what, shorten(rest_of_line()));
  }

  std::string_view next_word() {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !is_space(bytes_[pos_])) ++pos_;
    return bytes_.substr(start, pos_ - start);
  }

 public:
  long text_integer(std::string_view word, const What& what, long lo, long hi) {
    long value = 0;
    if (!parse_integer(word, value) || value < lo || value > hi)
      fail("expected {} (an integer from {} to {}), got {}", what.text(), lo, hi, quoted(word));
    return value;
  }

 private:
  template <class T>
  long binary_integer(const What& what, long lo, long hi) {
    T value{};
    read_bytes(&value, sizeof value, what);
    if (value < static_cast<T>(lo) || value > static_cast<T>(hi))
      fail("expected {} (an integer from {} to {}), got {}", what.text(), lo, hi, value);
    return static_cast<long>(value);
  }

  void read_bytes(void* out, std::size_t n, const What& what) {
    if (bytes_.size() - pos_ < n) fail("expected {}, got the end of the file", what.text());
    std::memcpy(out, bytes_.data() + pos_, n);
    pos_ += n;
  }

  const std::string& path_;
  std::string_view bytes_;
  std::size_t pos_ = 0;
  long line_ = 1;
  std::string_view marker_end_;  // the line end of the last section's first line
};

// What the sections read so far hold.
struct MshFile {
  double version = 0.0;
  std::set<long> entities[4];      // 4.1: entity tags by dimension
  std::vector<long> node_tags;     // sorted once $Nodes is read
  std::vector<bool> node_defined;  // by tag, when the tags are dense enough (else binary search)

  bool has_node(long tag) const {
    if (!node_defined.empty())
      return tag < static_cast<long>(node_defined.size()) && node_defined[tag];
    return std::binary_search(node_tags.begin(), node_tags.end(), tag);
  }
  std::vector<long> element_tags;
  std::map<std::pair<int, long>, int> entity_type;  // (dimension, entity tag) -> element type
  MshCounts counts;
};

// Gmsh 4.8 keeps one element type per entity: a surface holding both 3- and 6-node triangles
// corrupts its memory while it reads the file (tests/fuzz/gmsh_crashes), and flotsam reads
// one kind of triangle and of line per mesh anyway. `element` names the element or block.
void one_type_per_entity(Cursor& in, MshFile& msh, int dim, long entity, const ElementType& type,
                         const std::string& element) {
  const auto [at, added] = msh.entity_type.try_emplace({dim, entity}, type.type);
  if (!added && at->second != type.type)
    in.fail(
        "{} is of type {}, but entity {} of dimension {} already holds elements of type {} "
        "(Gmsh reads one element type per entity; flotsam one order of triangles and lines)",
        element, type.type, entity, dim, at->second);
}

// 1. The format line ("4.1 0 8", read by Gmsh with fgets) and, in a binary file, the integer 1
// in the file's byte order.
void read_format(Cursor& in, MshFile& msh) {
  in.section = "MeshFormat";
  const std::vector<std::string_view> words = in.words_of_line();
  if (words.size() != 3)
    in.fail("expected the line 'version file-type data-size' (4.1 0 8), got {} words",
            words.size());
  const long version_x10 = std::lround(10.0 * in.text_real(words[0], "the format version"));
  if (version_x10 != 22 && version_x10 != 41)
    in.fail(
        "flotsam reads MSH 2.2 and 4.1 files, not version {}; write the mesh in one of them "
        "(Gmsh: -format msh22 or msh41)",
        words[0]);
  msh.version = static_cast<double>(version_x10) / 10.0;
  const long file_type = in.text_integer(words[1], "the file type (0: ASCII, 1: binary)", 0, 1);
  in.text_integer(words[2], "the data size", 8, 8);
  in.rest_of_line();
  msh.counts.format = fmt::format("{:.1f} {}", msh.version, file_type == 1 ? "binary" : "ASCII");
  if (file_type == 1) {
    in.binary = in.binary_file = true;
    const long one = in.integer("the integer 1 (the byte order)", -largest_tag - 1, largest_tag);
    if (one != 1)
      in.fail(
          "the file was written with the other byte order (big-endian); write it again on "
          "this machine");
  }
  in.end_marker("MeshFormat");
}

// $PhysicalNames (text in binary files too): the count on its line, then per group its
// dimension, its tag and its name in double quotes on one line (Gmsh reads the name with fgets).
void read_physical_names(Cursor& in) {
  const long count = in.count_line("the number of physical names");
  const bool was_binary = in.binary;
  in.binary = false;
  const auto blank = [](std::string_view s) { return std::all_of(s.begin(), s.end(), is_space); };
  const auto printable = [](std::string_view s) {
    return std::all_of(s.begin(), s.end(),
                       [](char c) { return c == '\t' || static_cast<unsigned char>(c) >= 32; });
  };
  for (long i = 0; i < count; ++i) {
    in.integer("a physical group's dimension", 0, 3);
    in.integer_on_line("a physical group's tag", 1, largest_tag);
    const std::string_view name = in.peek_line();
    const std::size_t first = name.find('"');
    const std::size_t last = name.rfind('"');
    if (first == std::string_view::npos || last == first || !blank(name.substr(0, first)) ||
        !blank(name.substr(last + 1)) || last - first - 1 > longest_name ||
        !printable(name.substr(first + 1, last - first - 1)) ||
        name.substr(first + 1, last - first - 1).find('"') != std::string_view::npos)
      in.fail(
          "expected a physical group's name in double quotes (at most {} printable "
          "characters) after its dimension and tag, on their line",
          longest_name);
    in.rest_of_line();
  }
  in.binary = was_binary;
}

// 4.1 $Entities: points, curves, surfaces and volumes with their physical tags and, from curves
// on, the tags of the entities of one dimension less that bound them (which must exist).
void read_entities(Cursor& in, MshFile& msh) {
  long count[4];
  for (int dim = 0; dim < 4; ++dim)
    count[dim] = in.size(What("the number of entities of dimension {}", dim), 0, largest_count);
  for (int dim = 0; dim < 4; ++dim) {
    for (long i = 0; i < count[dim]; ++i) {
      const long tag =
          in.integer(What("the tag of entity {} of dimension {}", i + 1, dim), 1, largest_tag);
      if (!msh.entities[dim].insert(tag).second)
        in.fail("entity {} of dimension {} is defined twice", tag, dim);
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k)
        in.real(What("a coordinate of entity {}'s bounding box", tag));
      const long physicals =
          in.size(What("entity {}'s number of physical tags", tag), 0, largest_count);
      for (long p = 0; p < physicals; ++p)
        in.integer(What("a physical tag of entity {}", tag), -largest_tag, largest_tag);
      if (dim == 0) continue;
      const long bounds =
          in.size(What("entity {}'s number of bounding entities", tag), 0, largest_count);
      for (long b = 0; b < bounds; ++b) {
        const long bound =
            in.integer(What("a bounding entity of entity {}", tag), -largest_tag, largest_tag);
        if (!msh.entities[dim - 1].contains(std::abs(bound)))
          in.fail(
              "entity {} of dimension {} is bounded by entity {} of dimension {}, which "
              "$Entities does not define before it",
              tag, dim, std::abs(bound), dim - 1);
      }
    }
  }
}

// A 4.1 block header's entity: its dimension and tag, which $Entities must define.
struct BlockEntity {
  int dim;
  long tag;
};
BlockEntity block_entity(Cursor& in, const MshFile& msh, long block) {
  const int dim = static_cast<int>(in.integer(What("block {}'s entity dimension", block), 0, 3));
  const long tag = in.integer(What("block {}'s entity tag", block), 1, largest_tag);
  if (!msh.entities[dim].contains(tag))
    in.fail("block {} belongs to entity {} of dimension {}, which $Entities does not define", block,
            tag, dim);
  return {dim, tag};
}

// Sorts `tags`, refuses a repeated one, and in 4.1 compares the smallest and largest with the
// section's header.
void check_tags(Cursor& in, std::vector<long>& tags, const What& what, long declared_min,
                long declared_max, bool declared) {
  std::sort(tags.begin(), tags.end());
  const auto twice = std::adjacent_find(tags.begin(), tags.end());
  if (twice != tags.end()) in.fail("{} tag {} is defined twice", what.text(), *twice);
  if (declared && !tags.empty() && (tags.front() != declared_min || tags.back() != declared_max))
    in.fail("the header declares {} tags from {} to {}, the blocks hold {} to {}", what.text(),
            declared_min, declared_max, tags.front(), tags.back());
}

void read_nodes(Cursor& in, MshFile& msh) {
  if (msh.version > 4.0) {
    const long blocks = in.size("the number of node blocks", 0, largest_count);
    const long total = in.size("the number of nodes", 0, largest_count);
    const long min_tag = in.size("the smallest node tag", 0, largest_tag);
    const long max_tag = in.size("the largest node tag", 0, largest_tag);
    for (long b = 1; b <= blocks; ++b) {
      block_entity(in, msh, b);
      in.integer(What("block {}'s parametric flag (0: flotsam reads no parametric "
                      "coordinates; Gmsh: Mesh.SaveParametric = 0)",
                      b),
                 0, 0);
      const long n = in.size(What("block {}'s number of nodes", b), 0, largest_count);
      if (n > total - static_cast<long>(msh.node_tags.size()))
        in.fail("block {} holds {} nodes, more than the {} the header declares are left", b, n,
                total - static_cast<long>(msh.node_tags.size()));
      for (long i = 0; i < n; ++i) msh.node_tags.push_back(in.size("a node tag", 1, largest_tag));
      for (long i = 0; i < 3 * n; ++i) in.real("a node coordinate");
    }
    if (static_cast<long>(msh.node_tags.size()) != total)
      in.fail("the header declares {} nodes, the blocks hold {}", total, msh.node_tags.size());
    check_tags(in, msh.node_tags, "node", min_tag, max_tag, true);
  } else {
    const long total = in.count_line("the number of nodes");
    for (long i = 0; i < total; ++i) {
      msh.node_tags.push_back(in.integer("a node tag", 1, largest_tag));
      for (int k = 0; k < 3; ++k) in.real("a node coordinate");
    }
    check_tags(in, msh.node_tags, "node", 0, 0, false);
  }
  msh.counts.nodes = msh.node_tags.size();
  const long largest = msh.node_tags.empty() ? 0 : msh.node_tags.back();
  if (largest <= 8 * static_cast<long>(msh.node_tags.size()) + 1024) {  // at most 8 bits a node
    msh.node_defined.assign(largest + 1, false);
    for (long tag : msh.node_tags) msh.node_defined[tag] = true;
  }
}

// One element's tag and node tags (on one line in ASCII), its type's count updated.
void read_element(Cursor& in, MshFile& msh, const ElementType& type, bool size_tags) {
  const long tag = size_tags ? in.size("an element tag", 1, largest_tag)
                             : in.integer("an element tag", 1, largest_tag);
  msh.element_tags.push_back(tag);
  for (int k = 0; k < type.nodes; ++k) {
    const What what("node {} of element {}", k + 1, tag);
    const long node =
        in.binary ? (size_tags ? in.size(what, 1, largest_tag) : in.integer(what, 1, largest_tag))
                  : in.integer_on_line(what, 1, largest_tag);
    if (!msh.has_node(node))
      in.fail("element {} refers to node {}, which $Nodes does not define", tag, node);
  }
  if (!in.binary) in.end_of_line(What("element {}", tag));
  if (type.type == 2 || type.type == 9) ++msh.counts.triangles;
  if (type.type == 1 || type.type == 8) ++msh.counts.lines;
}

const ElementType& known_type(Cursor& in, long type) {
  const ElementType* known = element_type(type);
  if (known == nullptr)
    in.fail(
        "element type {} is not one flotsam reads (points, lines, triangles, quadrangles and "
        "the 3D elements of order 1 and 2)",
        type);
  return *known;
}

void read_elements(Cursor& in, MshFile& msh) {
  const auto left = [&](long total) { return total - static_cast<long>(msh.element_tags.size()); };
  long total = 0;
  if (msh.version > 4.0) {
    const long blocks = in.size("the number of element blocks", 0, largest_count);
    total = in.size("the number of elements", 0, largest_count);
    const long min_tag = in.size("the smallest element tag", 0, largest_tag);
    const long max_tag = in.size("the largest element tag", 0, largest_tag);
    for (long b = 1; b <= blocks; ++b) {
      const auto [dim, entity] = block_entity(in, msh, b);
      const ElementType& type =
          known_type(in, in.integer(What("block {}'s element type", b), 1, largest_tag));
      if (type.dim != dim)
        in.fail("block {} holds elements of type {} (dimension {}) in an entity of dimension {}", b,
                type.type, type.dim, dim);
      one_type_per_entity(in, msh, dim, entity, type, fmt::format("block {}", b));
      const long n = in.size(What("block {}'s number of elements", b), 0, largest_count);
      if (n > left(total))
        in.fail("block {} holds {} elements, more than the {} the header declares are left", b, n,
                left(total));
      for (long i = 0; i < n; ++i) read_element(in, msh, type, true);
    }
    if (left(total) != 0)
      in.fail("the header declares {} elements, the blocks hold {}", total,
              msh.element_tags.size());
    check_tags(in, msh.element_tags, "element", min_tag, max_tag, true);
  } else {
    total = in.count_line("the number of elements");
    // 2.2 ASCII: tag type 2 physical elementary nodes...; binary: blocks of one type with the
    // header type, count, 2 (tags), then tag physical elementary nodes... per element.
    const auto tags = [&](long element) {
      in.integer(What("the number of tags of element {} (2: physical and elementary)", element), 2,
                 2);
    };
    const auto physical_elementary_and_nodes = [&](long tag, const ElementType& type) {
      in.integer(What("element {}'s physical tag", tag), 0, largest_tag);
      const long entity = in.integer(What("element {}'s elementary tag", tag), 1, largest_tag);
      one_type_per_entity(in, msh, type.dim, entity, type, fmt::format("element {}", tag));
      for (int k = 0; k < type.nodes; ++k) {
        const long node = in.integer(What("node {} of element {}", k + 1, tag), 1, largest_tag);
        if (!msh.has_node(node))
          in.fail("element {} refers to node {}, which $Nodes does not define", tag, node);
      }
      if (type.type == 2 || type.type == 9) ++msh.counts.triangles;
      if (type.type == 1 || type.type == 8) ++msh.counts.lines;
    };
    while (left(total) > 0) {
      if (in.binary) {
        const ElementType& type =
            known_type(in, in.integer("a block's element type", 1, largest_tag));
        const long n = in.integer("a block's number of elements", 1, left(total));
        tags(static_cast<long>(msh.element_tags.size()) + 1);
        for (long i = 0; i < n; ++i) {
          const long tag = in.integer("an element tag", 1, largest_tag);
          msh.element_tags.push_back(tag);
          physical_elementary_and_nodes(tag, type);
        }
      } else {
        const long tag = in.integer("an element tag", 1, largest_tag);
        msh.element_tags.push_back(tag);
        const ElementType& type =
            known_type(in, in.integer(What("element {}'s type", tag), 1, largest_tag));
        tags(tag);
        physical_elementary_and_nodes(tag, type);
      }
    }
    check_tags(in, msh.element_tags, "element", 0, 0, false);
  }
  msh.counts.elements = msh.element_tags.size();
}

}  // namespace

MshCounts check_msh_bytes(const std::string& path, std::string_view bytes) {
  Cursor in(path, bytes);
  MshFile msh;
  // Gmsh picks its reader by the first line: anything but $MeshFormat there is not an MSH file.
  if (!bytes.starts_with("$MeshFormat") || in.peek_marker() != "MeshFormat")
    in.fail("expected $MeshFormat alone on the file's first line (is it a Gmsh .msh file?)");
  in.start_marker();
  read_format(in, msh);

  // 2. The sections, each once, in an order Gmsh can read.
  std::set<std::string> seen;
  const bool v4 = msh.version > 4.0;
  while (!in.at_end()) {
    in.section.clear();
    const std::string name = in.peek_marker();
    if (name != "PhysicalNames" && name != "Nodes" && name != "Elements" &&
        !(v4 && name == "Entities"))
      in.fail(
          "section ${} is not one flotsam reads; an MSH {} file may hold only $MeshFormat, "
          "$PhysicalNames{}, $Nodes and $Elements",
          name, v4 ? "4.1" : "2.2", v4 ? ", $Entities" : "");
    if (!seen.insert(name).second) in.fail("section ${} appears twice", name);
    in.section = name;
    if (name == "Nodes" && v4 && !seen.contains("Entities"))
      in.fail("$Nodes comes before $Entities (Gmsh writes $Entities first)");
    if (name == "Elements" && !seen.contains("Nodes")) in.fail("$Elements comes before $Nodes");
    if (name == "Entities" && seen.contains("Nodes"))
      in.fail("$Entities comes after $Nodes (Gmsh writes $Entities first)");
    in.start_marker();
    if (name == "PhysicalNames") read_physical_names(in);
    if (name == "Entities") read_entities(in, msh);
    if (name == "Nodes") read_nodes(in, msh);
    if (name == "Elements") read_elements(in, msh);
    in.end_marker(name);
  }

  // 3. What every mesh needs.
  in.section.clear();
  if (!seen.contains("Nodes") || !seen.contains("Elements"))
    in.fail("the file ends without {}", seen.contains("Nodes") ? "$Elements" : "$Nodes");
  return msh.counts;
}

MshCounts check_msh(const std::string& path) {
  if (!path.ends_with(".msh") && !path.ends_with(".msh2"))
    throw_input_error(
        "{}: a Gmsh mesh file's name must end in .msh or .msh2 (Gmsh chooses its "
        "reader by the name: another ending may be read as another format)",
        path);
  if (const std::string kind = special_file_kind(path); !kind.empty())
    throw_input_error("{}: the mesh file is {}, not a file: flotsam reads it whole", path, kind);
  std::ifstream file(path, std::ios::binary);
  if (!file)
    throw_input_error("{}: cannot open the mesh file (it does not exist or is not readable)", path);
  std::ostringstream bytes;
  bytes << file.rdbuf();
  if (file.bad()) throw_input_error("{}: cannot read the mesh file", path);
  return check_msh_bytes(path, bytes.str());
}

}  // namespace flotsam
