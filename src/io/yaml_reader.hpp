#pragma once
// Checked access to a YAML document (docs/case-format.md). Every read names what it expects;
// anything else is an InputError "file:line: key.path: what was expected, what was found".
// Every key read is recorded, so that after parsing `check_no_unknown_keys` can reject the keys
// nobody asked for (typos), with the allowed keys and the nearest one.
//
//   YamlDocument doc(text, "case.yaml");
//   YamlMap flow = doc.root().map("flow");
//   double g = flow.number("gravity", 9.81, Range::positive());   // optional, with default
//   FrictionLaw law = flow.map("friction").get("law").choice<FrictionLaw>({{"manning", ...}});
//   doc.check_no_unknown_keys();
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/expression.hpp"
#include "core/time_series.hpp"
#include "core/vec.hpp"

namespace flotsam {

/// The interval a number must lie in, for the check and for the message.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  // min itself excluded
  bool max_open = false;

  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity()}; }
  static Range at_least(double lo) { return {lo, std::numeric_limits<double>::infinity()}; }
  static Range between(double lo, double hi) { return {lo, hi}; }
  static Range up_to(double hi) { return {0.0, hi, true, false}; }  // (0, hi]

  /// No number in a case exceeds this magnitude (docs/case-format.md "Ranges"): larger ones
  /// are typos of an exponent, and would overflow the run's arithmetic.
  static constexpr double largest = 1e9;

  bool contains(double x) const;
  /// "a number > 0", "a number in [0, 1]", "a number".
  std::string describe(std::string_view what = "a number") const;
};

/// The closest of `candidates` to `word` by edit distance, or "" when none is close enough to be
/// a likely typo.
std::string nearest_word(std::string_view word, const std::vector<std::string>& candidates);

class YamlDocument;
class YamlMap;

/// One node of the document with its key path ("flow.friction.law", "bodies.list[2].x").
class YamlValue {
 public:
  /// `key_line`: the line of the key this value belongs to (0: none, a list item), which is where
  /// a map's missing keys are reported.
  YamlValue(YamlDocument* document, YAML::Node node, std::string path, int parent_line,
            int key_line = 0);

  const std::string& path() const { return path_; }
  int line() const { return line_; }  // 1-based
  int key_line() const { return key_line_; }
  bool is_list() const { return node_.IsSequence(); }
  bool is_map() const { return node_.IsMap(); }

  /// A plain number (a quoted "10" is text, not a number).
  bool is_number() const;
  double number(Range range = Range::any()) const;
  long integer(Range range = Range::any()) const;
  bool boolean() const;
  std::string text() const;
  Vec2 vec2() const;  // [x, y]
  /// A formula in x and y (and z with `uses_z`, core/expression.hpp) whose errors name
  /// "file:line: path".
  Expression expression(bool uses_z = false) const;
  /// "file:line: path", where this value was written (for messages raised later).
  std::string origin() const;
  /// The text as the path of a file the run reads, relative to `case_folder` unless absolute;
  /// recorded as one of the case's input files (YamlDocument::input_files).
  std::string input_path(const std::string& case_folder) const;
  /// A constant or a table [[x, value], ...] with strictly increasing x (named `abscissa` in
  /// messages) -> TimeSeries.
  TimeSeries series(std::string_view abscissa, Range range = Range::any()) const;
  YamlMap map() const;  // a map; an empty value counts as an empty map
  std::vector<YamlValue> list() const;

  /// One of the allowed words, e.g. {{"manning", FrictionLaw::manning}, ...}.
  template <class E>
  E choice(std::initializer_list<std::pair<std::string_view, E>> allowed) const {
    const std::string word = text();
    std::vector<std::string> names;
    for (const auto& [name, value] : allowed) {
      if (name == word) return value;
      names.emplace_back(name);
    }
    fail_choice(word, names);
  }

  /// Throws InputError "file:line: path: what".
  [[noreturn]] void fail(std::string_view what) const;

 private:
  [[noreturn]] void fail_choice(const std::string& word,
                                const std::vector<std::string>& names) const;
  std::string kind_found() const;  // "a list", "a map", "no value", "'abc'"

  YamlDocument* document_;
  YAML::Node node_;
  std::string path_;
  int line_;
  int key_line_;
};

/// A YAML map whose keys are read through this class, and so recorded as known.
class YamlMap {
 public:
  YamlMap(YamlDocument* document, YAML::Node node, std::string path, int line);

  const std::string& path() const { return path_; }
  int line() const { return line_; }

  bool has(std::string_view key) const;
  /// A required key; missing -> error naming the key (and a present key that looks like it).
  YamlValue get(std::string_view key, std::string_view hint = "") const;
  std::optional<YamlValue> find(std::string_view key) const;

  // Optional keys with their defaults.
  double number(std::string_view key, double fallback, Range range = Range::any()) const;
  long integer(std::string_view key, long fallback, Range range = Range::any()) const;
  bool boolean(std::string_view key, bool fallback) const;
  std::string text(std::string_view key, const std::string& fallback) const;
  Vec2 vec2(std::string_view key, const Vec2& fallback) const;
  /// A sub-map; absent -> an empty map (all its keys take their defaults).
  YamlMap map(std::string_view key) const;

  /// At most one of `keys` is present: returns it, or "" when none is. Two present -> error.
  std::string only_one_of(std::initializer_list<std::string_view> keys) const;
  /// Records `key` as known but rejects it when present, saying why ("not used with law none").
  void forbid(std::string_view key, std::string_view why) const;
  /// All entries, in document order, each recorded as read (maps keyed by user names).
  std::vector<std::pair<std::string, YamlValue>> entries() const;

  /// Rejects this map's keys that no read so far asked for (the final check does all maps; call
  /// this early when a typo would otherwise surface as a less helpful error).
  void check_keys() const;

  [[noreturn]] void fail(std::string_view what) const;

 private:
  std::string key_path(std::string_view key) const;

  YamlDocument* document_;
  YAML::Node node_;  // a map or null
  std::string path_;
  int line_;
};

/// A parsed YAML text and the record of what was read from it.
class YamlDocument {
 public:
  /// Parses `text`; a syntax error is an InputError naming `file_name` and the line.
  YamlDocument(const std::string& text, std::string file_name);

  const std::string& file_name() const { return file_name_; }
  /// The top level, which must be a non-empty map.
  YamlMap root();

  /// Rejects every key that no reader asked for, and keys given twice; call after parsing.
  void check_no_unknown_keys() const;

  [[noreturn]] void fail(int line, std::string_view path, std::string_view what) const;

  /// The parsed document, for walks over every value (io/case_digest.hpp).
  const YAML::Node& node() const { return root_; }
  /// The files the case reads (key path, path), in the order read (YamlValue::input_path).
  const std::vector<std::pair<std::string, std::string>>& input_files() const {
    return input_files_;
  }

 private:
  friend class YamlMap;
  friend class YamlValue;
  void note_known(const std::string& map_path, std::string_view key);
  void note_read(const std::string& key_path) { read_.insert(key_path); }
  void check_node(const YAML::Node& node, const std::string& path) const;
  void check_map_keys(const YAML::Node& node, const std::string& path) const;

  std::string file_name_;
  YAML::Node root_;
  std::set<std::string> read_;                                    // key paths read
  std::map<std::string, std::vector<std::string>> known_;         // map path -> keys asked for
  std::vector<std::pair<std::string, std::string>> input_files_;  // key path, file
};

/// 1-based line of a node, or `fallback` when yaml-cpp has no mark for it (null nodes).
int line_of(const YAML::Node& node, int fallback);

}  // namespace flotsam
