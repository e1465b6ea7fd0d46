#include "ensemble/ensemble_config.hpp"

#include <algorithm>
#include <sstream>

#include "core/error.hpp"
#include "io/yaml_reader.hpp"

namespace flotsam {

namespace {

struct InputName {
  EnsembleInput input;
  const char* key;
  const char* unit;
  Range range;  // what a fixed value, a range's ends or a sweep's values must satisfy
};

const InputName input_names[] = {
    {EnsembleInput::log_length, "log_length", "m", Range::positive()},
    {EnsembleInput::log_length_over_gap, "log_length_over_gap", "-", Range::positive()},
    {EnsembleInput::log_diameter, "log_diameter", "m", Range::positive()},
    {EnsembleInput::log_density, "log_density", "kg m^-3", Range::positive()},
    {EnsembleInput::release_rate, "release_rate", "1/min", Range::positive()},
    {EnsembleInput::discharge_scale, "discharge_scale", "-", Range::non_negative()},
    {EnsembleInput::restitution, "restitution", "-", Range::between(0.0, 1.0)},
    {EnsembleInput::contact_friction, "contact_friction", "-", Range::non_negative()},
    {EnsembleInput::bed_friction, "bed_friction", "-", Range::non_negative()},
    {EnsembleInput::release_shift_x, "release_shift_x", "m", Range::any()},
    {EnsembleInput::release_shift_y, "release_shift_y", "m", Range::any()},
};

const InputName& name_of(EnsembleInput input) {
  return input_names[static_cast<int>(input)];
}

EnsembleInput read_input_key(const YamlValue& where, const std::string& key) {
  std::vector<std::string> keys;
  for (const InputName& n : input_names) {
    if (key == n.key) return n.input;
    keys.emplace_back(n.key);
  }
  const std::string near = nearest_word(key, keys);
  std::ostringstream allowed;
  for (std::size_t k = 0; k < keys.size(); ++k) allowed << (k ? ", " : "") << keys[k];
  where.fail("unknown input '" + key + "'" +
             (near.empty() ? "" : " (did you mean '" + near + "'?)") +
             "; inputs that can vary: " + allowed.str());
}

// A number (fixed), [a, b] or {uniform: [a, b]}, {normal: [mean, sd]}, {choice: [v, ...]}.
Distribution read_distribution(const YamlValue& value, const Range& range) {
  Distribution d;
  if (value.is_number()) {
    d.a = value.number(range);
    return d;
  }
  auto pair = [&](const YamlValue& v, const Range& first, const Range& second) {
    const std::vector<YamlValue> items = v.list();
    if (items.size() != 2) v.fail("expected two numbers [a, b]");
    return std::pair{items[0].number(first), items[1].number(second)};
  };
  if (value.is_list()) {
    d.kind = Distribution::Kind::uniform;
    std::tie(d.a, d.b) = pair(value, range, range);
  } else {
    const YamlMap m = value.map();
    const std::string kind = m.only_one_of({"uniform", "normal", "choice"});
    if (kind.empty())
      value.fail("expected a number, [min, max], or a map with one of uniform, normal, choice");
    const YamlValue v = m.get(kind);
    if (kind == "uniform") {
      d.kind = Distribution::Kind::uniform;
      std::tie(d.a, d.b) = pair(v, range, range);
    } else if (kind == "normal") {
      d.kind = Distribution::Kind::normal;
      std::tie(d.a, d.b) = pair(v, Range::any(), Range::non_negative());
    } else {
      d.kind = Distribution::Kind::choice;
      for (const YamlValue& item : v.list()) d.values.push_back(item.number(range));
      if (d.values.empty()) v.fail("expected at least one value");
    }
  }
  if (d.kind == Distribution::Kind::uniform && d.b < d.a)
    value.fail("the range's upper end is below its lower end");
  return d;
}

}  // namespace

const char* input_key(EnsembleInput input) {
  return name_of(input).key;
}
const char* input_unit(EnsembleInput input) {
  return name_of(input).unit;
}

EnsembleConfig parse_ensemble(const std::string& ensemble_text, const std::string& file_name) {
  if (ensemble_text.find_first_not_of(" \n") == std::string::npos)
    throw_input_error(
        "{}: no `ensemble:` section at the top level; add one, e.g. `ensemble: {{members: 20, "
        "vary: {{log_length: [10, 30]}}}}` as a block (docs/case-format.md, \"ensemble\")",
        file_name);
  YamlDocument document(ensemble_text, file_name);
  const YamlValue section = document.root().get("ensemble");
  const YamlMap e = section.map();
  EnsembleConfig c;
  c.line = section.key_line();
  c.members = static_cast<int>(e.integer("members", c.members, Range::between(1, 1e6)));
  c.seed = static_cast<unsigned long>(e.integer("seed", 1, Range::between(0, 2147483647)));
  for (const auto& [key, value] : e.map("vary").entries()) {
    const EnsembleInput input = read_input_key(value, key);
    c.vary.push_back({input, read_distribution(value, name_of(input).range)});
  }
  std::sort(c.vary.begin(), c.vary.end(),
            [](const VariedInput& a, const VariedInput& b) { return a.input < b.input; });
  if (e.has("sweep")) {
    const YamlMap sweep = e.map("sweep");
    const YamlValue input = sweep.get("input", "the input to sweep, e.g. log_length");
    c.has_sweep = true;
    c.sweep_input = read_input_key(input, input.text());
    for (const VariedInput& v : c.vary)
      if (v.input == c.sweep_input)
        input.fail("this input is also under ensemble.vary; an input is either swept or varied");
    const YamlValue values = sweep.get("values", "a list of values");
    for (const YamlValue& v : values.list())
      c.sweep_values.push_back(v.number(name_of(c.sweep_input).range));
    if (c.sweep_values.empty()) values.fail("expected at least one value");
  }
  const YamlMap blocking = e.map("blocking");
  BlockingCriterion& b = c.blocking;
  b.fraction = blocking.number("fraction", b.fraction, {0.0, 1.0, true, false});
  b.sample_interval = blocking.number("sample_interval", b.sample_interval, Range::positive());
  b.duration = blocking.number("duration", b.duration, Range::non_negative());
  document.check_no_unknown_keys();
  return c;
}

}  // namespace flotsam
