// Checked access to YAML (see yaml_reader.hpp): typed reads with ranges, and the record of
// every key read so that unknown keys can be reported with the allowed ones.
#include "io/yaml_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/special_file.hpp"
#include "io/table_file.hpp"

namespace flotsam {

namespace {

std::string join_key(const std::string& map_path, std::string_view key) {
  return map_path.empty() ? std::string(key) : fmt::format("{}.{}", map_path, key);
}

std::string join_index(const std::string& list_path, std::size_t index) {
  return fmt::format("{}[{}]", list_path, index);
}

// Edit distance counting an insertion, a deletion, a substitution or a swap of two neighbours as
// one edit (optimal string alignment), the usual typos.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  const std::size_t n = b.size() + 1;
  std::vector<std::size_t> d((a.size() + 1) * n);
  const auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return d[i * n + j]; };
  for (std::size_t i = 0; i <= a.size(); ++i) at(i, 0) = i;
  for (std::size_t j = 0; j <= b.size(); ++j) at(0, j) = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
    }
  }
  return at(a.size(), b.size());
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string near = nearest_word(word, candidates);
  return near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near);
}

}  // namespace

bool Range::contains(double x) const {
  const bool above = min_open ? x > min : x >= min;
  const bool below = max_open ? x < max : x <= max;
  return above && below;
}

std::string Range::describe(std::string_view what) const {
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max) {
    return fmt::format("{} in {}{}, {}{}", what, min_open ? '(' : '[', min, max,
                       max_open ? ')' : ']');
  }
  if (has_min) return fmt::format("{} {} {}", what, min_open ? ">" : ">=", min);
  if (has_max) return fmt::format("{} {} {}", what, max_open ? "<" : "<=", max);
  return std::string(what);
}

std::string nearest_word(std::string_view word, const std::vector<std::string>& candidates) {
  // Close enough: one edit, plus one per five letters, and never the whole word.
  std::size_t best_distance = std::min(word.size(), 2 + word.size() / 5);
  std::string best;
  for (const auto& candidate : candidates) {
    const std::size_t d = edit_distance(word, candidate);
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  return best;
}

int line_of(const YAML::Node& node, int fallback) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? fallback : mark.line + 1;
}

// ---- YamlValue ----------------------------------------------------------------------------

YamlValue::YamlValue(YamlDocument* document, YAML::Node node, std::string path, int parent_line,
                     int key_line)
    : document_(document),
      node_(std::move(node)),
      path_(std::move(path)),
      line_(node_.IsNull() ? parent_line
                           : line_of(node_, parent_line)),  // a null's mark is past it
      key_line_(key_line > 0 ? key_line : line_) {}

void YamlValue::fail(std::string_view what) const {
  document_->fail(line_, path_, what);
}

std::string YamlValue::kind_found() const {
  if (node_.IsSequence()) return "a list";
  if (node_.IsMap()) return "a map";
  if (!node_.IsDefined() || node_.IsNull()) return "no value";
  if (node_.Tag() == "!") return fmt::format("the quoted text '{}'", node_.Scalar());
  return fmt::format("'{}'", node_.Scalar());
}

bool YamlValue::is_number() const {
  double x = 0.0;
  return node_.IsScalar() && node_.Tag() != "!" && YAML::convert<double>::decode(node_, x);
}

double YamlValue::number(Range range) const {
  // A quoted scalar ("10") is text, not a number: its tag is "!" where a plain one has "?".
  double x = 0.0;
  const bool ok = node_.IsScalar() && node_.Tag() != "!" && YAML::convert<double>::decode(node_, x);
  if (!ok) fail(fmt::format("expected {}, got {}", range.describe(), kind_found()));
  if (!std::isfinite(x)) fail(fmt::format("expected a finite number, got {}", kind_found()));
  if (std::abs(x) > Range::largest)
    fail(fmt::format("expected {} of magnitude at most {:g} (no key needs more), got {}",
                     range.describe(), Range::largest, node_.Scalar()));
  if (!range.contains(x))
    fail(fmt::format("expected {}, got {}", range.describe(), node_.Scalar()));
  return x;
}

long YamlValue::integer(Range range) const {
  long n = 0;
  const bool ok = node_.IsScalar() && node_.Tag() != "!" && YAML::convert<long>::decode(node_, n);
  if (!ok) fail(fmt::format("expected {}, got {}", range.describe("an integer"), kind_found()));
  if (!range.contains(static_cast<double>(n)))
    fail(fmt::format("expected {}, got {}", range.describe("an integer"), node_.Scalar()));
  return n;
}

bool YamlValue::boolean() const {
  bool b = false;
  const bool ok = node_.IsScalar() && node_.Tag() != "!" && YAML::convert<bool>::decode(node_, b);
  if (!ok) fail(fmt::format("expected true or false, got {}", kind_found()));
  return b;
}

std::string YamlValue::text() const {
  if (!node_.IsScalar()) fail(fmt::format("expected a word or text, got {}", kind_found()));
  return node_.Scalar();
}

Vec2 YamlValue::vec2() const {
  if (!node_.IsSequence() || node_.size() != 2)
    fail(fmt::format("expected a pair of numbers [x, y], got {}", kind_found()));
  const auto items = list();
  return {items[0].number(), items[1].number()};
}

Expression YamlValue::expression(bool uses_z) const {
  if (!node_.IsScalar())
    fail(fmt::format("expected a formula in x and y (or a number), got {}", kind_found()));
  return Expression(node_.Scalar(), origin(), uses_z);
}

std::string YamlValue::origin() const {
  return fmt::format("{}:{}: {}", document_->file_name(), line_, path_);
}

TimeSeries YamlValue::series(std::string_view abscissa, Range range) const {
  if (node_.IsScalar()) return TimeSeries(number(range));
  if (node_.IsMap() && node_["file"]) {  // {file: table.csv}, a long table (io/table_file.hpp)
    const std::string folder = std::filesystem::path(document_->file_name()).parent_path().string();
    const std::string path =
        map()
            .get("file", "a CSV file of two columns: " + std::string(abscissa) + ", value")
            .input_path(folder);
    return TimeSeries(read_table_file(path, abscissa, [&](double value) {
      return range.contains(value) ? std::string() : range.describe();
    }));
  }
  if (!node_.IsSequence() || node_.size() == 0) {
    fail(fmt::format("expected {}, a table [[{}, value], ...] or {{file: table.csv}}, got {}",
                     range.describe(), abscissa,
                     node_.IsSequence() ? "an empty list" : kind_found()));
  }
  std::vector<std::pair<double, double>> points;
  for (const YamlValue& row : list()) {
    if (!row.node_.IsSequence() || row.node_.size() != 2) {
      row.fail(fmt::format("expected a table row [{}, value], got {}", abscissa,
                           row.node_.IsSequence() ? "a list of " + std::to_string(row.node_.size())
                                                  : row.kind_found()));
    }
    const auto pair = row.list();
    const double x = pair[0].number();
    if (!points.empty() && !(x > points.back().first)) {
      row.fail(
          fmt::format("{} = {} does not come after the previous row's {} = {}; a table's {} "
                      "must be strictly increasing",
                      abscissa, x, abscissa, points.back().first, abscissa));
    }
    points.emplace_back(x, pair[1].number(range));
  }
  return TimeSeries(std::move(points));
}

YamlMap YamlValue::map() const {
  if (!node_.IsMap() && !node_.IsNull())
    fail(fmt::format("expected a map of keys, got {}", kind_found()));
  return YamlMap(document_, node_, path_, key_line_);
}

std::vector<YamlValue> YamlValue::list() const {
  if (!node_.IsSequence()) fail(fmt::format("expected a list, got {}", kind_found()));
  std::vector<YamlValue> items;
  for (std::size_t i = 0; i < node_.size(); ++i)
    items.emplace_back(document_, node_[i], join_index(path_, i), line_);
  return items;
}

void YamlValue::fail_choice(const std::string& word, const std::vector<std::string>& names) const {
  fail(fmt::format("unknown value '{}'; expected one of: {}{}", word, fmt::join(names, ", "),
                   did_you_mean(word, names)));
}

// ---- YamlMap ------------------------------------------------------------------------------

YamlMap::YamlMap(YamlDocument* document, YAML::Node node, std::string path, int line)
    : document_(document), node_(std::move(node)), path_(std::move(path)), line_(line) {}

std::string YamlMap::key_path(std::string_view key) const {
  return join_key(path_, key);
}

void YamlMap::check_keys() const {
  document_->check_map_keys(node_, path_);
}

void YamlMap::fail(std::string_view what) const {
  document_->fail(line_, path_, what);
}

bool YamlMap::has(std::string_view key) const {
  return find(key).has_value();
}

std::optional<YamlValue> YamlMap::find(std::string_view key) const {
  document_->note_known(path_, key);
  if (!node_.IsMap()) return std::nullopt;
  for (const auto& entry : node_) {
    if (entry.first.IsScalar() && entry.first.Scalar() == key) {
      document_->note_read(key_path(key));
      const int key_line = line_of(entry.first, line_);
      return YamlValue(document_, entry.second, key_path(key), key_line, key_line);
    }
  }
  return std::nullopt;
}

YamlValue YamlMap::get(std::string_view key, std::string_view hint) const {
  if (auto value = find(key)) return *value;
  // A present key that looks like the missing one is probably a typo of it.
  std::string typo;
  if (node_.IsMap()) {
    for (const auto& entry : node_) {
      if (!entry.first.IsScalar()) continue;
      if (nearest_word(entry.first.Scalar(), {std::string(key)}) == key) {
        typo = fmt::format(" (is '{}' on line {} a misspelling of it?)", entry.first.Scalar(),
                           line_of(entry.first, line_));
        break;
      }
    }
  }
  document_->fail(
      line_, key_path(key),
      fmt::format("missing; this key is required{}{}{}", hint.empty() ? "" : ": ", hint, typo));
}

double YamlMap::number(std::string_view key, double fallback, Range range) const {
  const auto value = find(key);
  return value ? value->number(range) : fallback;
}

long YamlMap::integer(std::string_view key, long fallback, Range range) const {
  const auto value = find(key);
  return value ? value->integer(range) : fallback;
}

bool YamlMap::boolean(std::string_view key, bool fallback) const {
  const auto value = find(key);
  return value ? value->boolean() : fallback;
}

std::string YamlMap::text(std::string_view key, const std::string& fallback) const {
  const auto value = find(key);
  return value ? value->text() : fallback;
}

Vec2 YamlMap::vec2(std::string_view key, const Vec2& fallback) const {
  const auto value = find(key);
  return value ? value->vec2() : fallback;
}

YamlMap YamlMap::map(std::string_view key) const {
  if (const auto value = find(key)) return value->map();
  return YamlMap(document_, YAML::Node(YAML::NodeType::Null), key_path(key), line_);
}

std::string YamlMap::only_one_of(std::initializer_list<std::string_view> keys) const {
  std::optional<YamlValue> first;
  std::string first_key;
  for (const auto key : keys) {
    auto value = find(key);
    if (!value) continue;
    if (first) {
      value->fail(fmt::format("give either '{}' (line {}) or '{}', not both", first_key,
                              first->line(), key));
    }
    first = value;
    first_key = key;
  }
  return first_key;
}

void YamlMap::forbid(std::string_view key, std::string_view why) const {
  if (const auto value = find(key)) value->fail(fmt::format("not allowed here: {}", why));
}

std::vector<std::pair<std::string, YamlValue>> YamlMap::entries() const {
  std::vector<std::pair<std::string, YamlValue>> out;
  if (!node_.IsMap()) return out;
  for (const auto& entry : node_) {
    const int key_line = line_of(entry.first, line_);
    if (!entry.first.IsScalar()) document_->fail(key_line, path_, "expected a word as key");
    const std::string& key = entry.first.Scalar();
    document_->note_known(path_, key);
    document_->note_read(key_path(key));
    out.emplace_back(key, YamlValue(document_, entry.second, key_path(key), key_line, key_line));
  }
  return out;
}

// ---- YamlDocument -------------------------------------------------------------------------

std::string YamlValue::input_path(const std::string& case_folder) const {
  std::filesystem::path file = text();
  if (file.is_relative()) file = (std::filesystem::path(case_folder) / file).lexically_normal();
  if (const std::string kind = special_file_kind(file); !kind.empty())
    fail(fmt::format("'{}' is {}, not a file: flotsam reads its inputs whole from files",
                     file.string(), kind));
  document_->input_files_.emplace_back(path_, file.string());
  return file.string();
}

// yaml-cpp holds about 110 bytes of memory per byte of text while a case is read (a 27 MB
// case of one 1.6-million-row table: 3.06 GB peak; issue 39 item 10); 120 errs on the safe side.
constexpr double yaml_bytes_per_byte = 120.0;

YamlDocument::YamlDocument(const std::string& text, std::string file_name)
    : file_name_(std::move(file_name)) {
  // Half of what the process may use: the libraries, the mesh and the run need the rest.
  const double needed = yaml_bytes_per_byte * static_cast<double>(text.size());  // [bytes]
  const double usable = usable_memory();                                         // [bytes]
  const auto too_large = [&](const char* what) {
    throw_input_error(
        "{}: {}: a file of {} takes about {} of memory to read (YAML), and this process may use "
        "{}; give long tables as CSV files, `value: {{file: table.csv}}` (docs/case-format.md "
        "\"Tables from files\")",
        file_name_, what, format_bytes(static_cast<double>(text.size())), format_bytes(needed),
        format_bytes(usable));
  };
  if (needed > 0.5 * usable) too_large("too large to read");
  try {
    root_ = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    fail(e.mark.line + 1, "", fmt::format("YAML syntax error: {}", e.msg));
  } catch (const std::bad_alloc&) {
    too_large("out of memory while reading it");
  }
}

void YamlDocument::fail(int line, std::string_view path, std::string_view what) const {
  if (path.empty()) throw_input_error("{}:{}: {}", file_name_, line, what);
  throw_input_error("{}:{}: {}: {}", file_name_, line, path, what);
}

YamlMap YamlDocument::root() {
  if (!root_.IsMap()) {
    fail(line_of(root_, 1), "",
         root_.IsNull() ? "the file is empty; expected a map of sections (mesh, flow, time, ...)"
                        : "expected a map of sections (mesh, flow, time, ...) at the top level");
  }
  return YamlMap(this, root_, "", line_of(root_, 1));
}

void YamlDocument::note_known(const std::string& map_path, std::string_view key) {
  auto& keys = known_[map_path];
  if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.emplace_back(key);
}

void YamlDocument::check_no_unknown_keys() const {
  check_node(root_, "");
}

// Walks the document in order; in each map the first key nobody read (or given twice) is the
// error. A key that was not read is not descended into: it is the typo to report.
void YamlDocument::check_node(const YAML::Node& node, const std::string& path) const {
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) check_node(node[i], join_index(path, i));
    return;
  }
  if (!node.IsMap()) return;
  check_map_keys(node, path);
  for (const auto& entry : node) check_node(entry.second, join_key(path, entry.first.Scalar()));
}

void YamlDocument::check_map_keys(const YAML::Node& node, const std::string& path) const {
  if (!node.IsMap()) return;
  std::map<std::string, int> seen;  // key -> line
  const auto known = known_.find(path);
  const std::vector<std::string> allowed =
      known == known_.end() ? std::vector<std::string>{} : known->second;
  for (const auto& entry : node) {
    const int line = line_of(entry.first, 1);
    if (!entry.first.IsScalar()) fail(line, path, "expected a word as key");
    const std::string& key = entry.first.Scalar();
    const std::string full = join_key(path, key);
    if (const auto [it, inserted] = seen.emplace(key, line); !inserted)
      fail(line, full, fmt::format("given twice (first on line {})", it->second));
    if (!read_.count(full)) {
      fail(line, full,
           fmt::format("unknown key{}; allowed here: {}", did_you_mean(key, allowed),
                       allowed.empty() ? "none" : fmt::format("{}", fmt::join(allowed, ", "))));
    }
  }
}

}  // namespace flotsam
