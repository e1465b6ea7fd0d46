#include "io/case_digest.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <charconv>
#include <map>

#include "io/checksum.hpp"

namespace flotsam {

namespace {

/// A number in its shortest exact form ("1e-2" and "0.010" are both "0.01"); other text as is.
std::string canonical_scalar(const std::string& text) {
  double x = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, x);
  if (error == std::errc() && stop == end && !text.empty()) return fmt::format("{}", x);
  return text;
}

void collect(const YAML::Node& node, const std::string& path, std::vector<CaseSetting>& out) {
  if (node.IsMap()) {
    if (node.size() == 0) out.push_back({path, "{}"});
    for (const auto& entry : node) {
      const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
      collect(entry.second, path.empty() ? key : path + "." + key, out);
    }
  } else if (node.IsSequence()) {
    if (node.size() == 0) out.push_back({path, "[]"});
    for (std::size_t i = 0; i < node.size(); ++i)
      collect(node[i], fmt::format("{}[{}]", path, i), out);
  } else if (node.IsScalar()) {
    out.push_back({path, canonical_scalar(node.Scalar())});
  } else {
    out.push_back({path, "~"});
  }
}

bool starts_with_key(std::string_view key, std::string_view prefix) {
  return key.substr(0, prefix.size()) == prefix &&
         (key.size() == prefix.size() || key[prefix.size()] == '.' || key[prefix.size()] == ' ' ||
          key[prefix.size()] == '[');
}

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\')
      out += "\\\\";
    else if (c == '\t')
      out += "\\t";
    else if (c == '\n')
      out += "\\n";
    else
      out += c;
  }
  return out;
}

std::string unescaped(std::string_view text) {
  std::string out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] != '\\' || k + 1 == text.size()) {
      out += text[k];
      continue;
    }
    const char c = text[++k];
    out += c == 't' ? '\t' : c == 'n' ? '\n' : c;
  }
  return out;
}

std::string shortened(const std::string& value) {
  constexpr std::size_t longest = 60;  // [characters] of a value in a message
  return value.size() <= longest ? value : value.substr(0, longest - 3) + "...";
}

}  // namespace

SettingKind setting_kind(std::string_view key) {
  for (const char* free_key : {"time.end", "output.directory", "output.overwrite"})
    if (starts_with_key(key, free_key)) return SettingKind::free;
  for (const char* output_key :
       {"output.interval", "output.probe_interval", "output.rasters", "output.wet_depth"})
    if (starts_with_key(key, output_key)) return SettingKind::output;
  return SettingKind::run;
}

std::vector<CaseSetting> case_settings(const YAML::Node& root,
                                       const std::vector<InputFile>& input_files) {
  std::vector<CaseSetting> all, kept;
  collect(root, "", all);
  for (const InputFile& file : input_files)
    all.push_back(
        {file.key + std::string(file_contents_suffix), file_checksum(file.path, file.key)});
  for (CaseSetting& setting : all)
    if (setting_kind(setting.key) != SettingKind::free) kept.push_back(std::move(setting));
  return kept;
}

std::string format_settings(const std::vector<CaseSetting>& settings) {
  std::string text;
  for (const CaseSetting& s : settings) text += escaped(s.key) + '\t' + escaped(s.value) + '\n';
  return text;
}

std::vector<CaseSetting> parse_settings(const std::string& text) {
  std::vector<CaseSetting> settings;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
    const std::string_view line(text.data() + start, end - start);
    const std::size_t tab = line.find('\t');
    if (tab == std::string_view::npos) continue;
    settings.push_back({unescaped(line.substr(0, tab)), unescaped(line.substr(tab + 1))});
  }
  return settings;
}

std::vector<SettingChange> compare_settings(const std::vector<CaseSetting>& before,
                                            const std::vector<CaseSetting>& after) {
  std::map<std::string, std::string> old_values;
  for (const CaseSetting& s : before) old_values[s.key] = s.value;
  std::vector<SettingChange> changes;
  for (const CaseSetting& s : after) {
    const auto old = old_values.find(s.key);
    if (old == old_values.end()) {
      changes.push_back({s.key, "", s.value, setting_kind(s.key)});
      continue;
    }
    if (old->second != s.value)
      changes.push_back({s.key, old->second, s.value, setting_kind(s.key)});
    old_values.erase(old);
  }
  for (const CaseSetting& s : before)
    if (old_values.count(s.key)) changes.push_back({s.key, s.value, "", setting_kind(s.key)});
  return changes;
}

std::string describe_changes(const std::vector<SettingChange>& changes, std::size_t shown) {
  std::string text;
  for (std::size_t k = 0; k < changes.size() && k < shown; ++k) {
    const SettingChange& c = changes[k];
    if (c.before.empty())
      text += fmt::format("\n  {}: added ({})", c.key, shortened(c.after));
    else if (c.after.empty())
      text += fmt::format("\n  {}: removed (was {})", c.key, shortened(c.before));
    else
      text +=
          fmt::format("\n  {}: {} then, {} now", c.key, shortened(c.before), shortened(c.after));
  }
  if (changes.size() > shown) text += fmt::format("\n  and {} more", changes.size() - shown);
  return text;
}

}  // namespace flotsam
