#include "ensemble/member_case.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"

namespace flotsam {

// ---- draws --------------------------------------------------------------------------------

namespace {

std::uint64_t splitmix64(std::uint64_t& x) {
  // Steele, Lea & Flood (2014), the generator of java.util.SplittableRandom.
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

constexpr std::uint64_t release_seed_key = 1000;  // keys of release seeds: 1000 + k

}  // namespace

KeyedStream::KeyedStream(std::initializer_list<std::uint64_t> key) : state_(0x243f6a8885a308d3ULL) {
  for (std::uint64_t k : key) {
    state_ ^= k;
    state_ = splitmix64(state_);
  }
}

std::uint64_t KeyedStream::next() {
  return splitmix64(state_);
}

double KeyedStream::uniform() {
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

double KeyedStream::normal() {
  const double u1 = 1.0 - uniform();  // in (0, 1]
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

double draw_value(const Distribution& d, KeyedStream& stream) {
  switch (d.kind) {
    case Distribution::Kind::fixed:
      return d.a;
    case Distribution::Kind::uniform:
      return d.a + (d.b - d.a) * stream.uniform();
    case Distribution::Kind::normal:
      return d.a + d.b * stream.normal();
    case Distribution::Kind::choice: {
      const auto k = static_cast<std::size_t>(stream.next() % d.values.size());
      return d.values[k];
    }
  }
  return d.a;
}

double MemberInputs::value(EnsembleInput input) const {
  for (const auto& [which, v] : values)
    if (which == input) return v;
  return std::numeric_limits<double>::quiet_NaN();
}

MemberInputs draw_member_inputs(const EnsembleConfig& config, int member, int release_count) {
  MemberInputs m;
  m.member = member;
  m.sweep_index = member / config.members;
  m.draw = member % config.members;
  const auto j = static_cast<std::uint64_t>(m.draw);
  for (const VariedInput& v : config.vary) {
    KeyedStream stream{config.seed, j, static_cast<std::uint64_t>(v.input)};
    m.values.emplace_back(v.input, draw_value(v.distribution, stream));
  }
  if (config.has_sweep) {
    m.values.emplace_back(config.sweep_input, config.sweep_values.at(m.sweep_index));
    std::sort(m.values.begin(), m.values.end());
  }
  for (int k = 0; k < release_count; ++k) {
    KeyedStream stream{config.seed, j, release_seed_key + static_cast<std::uint64_t>(k)};
    m.release_seeds.push_back(static_cast<long>(stream.next() >> 33));  // in [0, 2^31)
  }
  return m;
}

std::string member_name(int member) {
  return fmt::format("member_{:04d}", member);
}

// ---- the member's case file --------------------------------------------------------------

namespace {

/// A number as the case reader reads it back exactly (the shortest text that round-trips).
YAML::Node number_node(double v) {
  return YAML::Node(fmt::format("{}", v));
}

double node_number(const YAML::Node& node) {
  return std::stod(node.Scalar());
}

/// Relative paths of files next to the case become absolute (the member's case lives elsewhere).
void make_paths_absolute(YAML::Node node, const std::filesystem::path& folder) {
  if (node.IsMap() || node.IsSequence()) {
    for (auto it = node.begin(); it != node.end(); ++it)
      make_paths_absolute(node.IsMap() ? it->second : *it, folder);
    return;
  }
  if (!node.IsScalar() || node.Scalar().empty()) return;
  const std::filesystem::path p(node.Scalar());
  std::error_code error;
  if (p.is_relative() && std::filesystem::is_regular_file(folder / p, error))
    node = std::filesystem::absolute(folder / p).lexically_normal().string();
}

void shift_points(YAML::Node points, double dx, double dy) {
  for (YAML::Node p : points) {
    p[0] = number_node(node_number(p[0]) + dx);
    p[1] = number_node(node_number(p[1]) + dy);
  }
}

}  // namespace

std::string member_case_text(const YAML::Node& base, const MemberInputs& inputs,
                             const MemberCaseContext& context) {
  YAML::Node root = YAML::Clone(base);
  make_paths_absolute(root, context.case_folder);
  YAML::Node releases = root["bodies"]["release"];
  auto fail = [&](EnsembleInput input, const char* why) {
    throw_input_error("{}: ensemble: input {}: {}", context.source, input_key(input), why);
  };
  for (const auto& [input, v] : inputs.values) {
    const bool per_release = input <= EnsembleInput::release_rate ||
                             input == EnsembleInput::release_shift_x ||
                             input == EnsembleInput::release_shift_y;
    if (per_release && (!releases.IsSequence() || releases.size() == 0))
      fail(input, "the case has no bodies.release to apply it to");
    switch (input) {
      case EnsembleInput::log_length:
        for (YAML::Node r : releases) r["length"] = number_node(v);
        break;
      case EnsembleInput::log_length_over_gap:
        if (context.gap_width <= 0.0) fail(input, "the mesh has no bridge (a channel with piers)");
        for (YAML::Node r : releases) r["length"] = number_node(v * context.gap_width);
        break;
      case EnsembleInput::log_diameter:
        for (YAML::Node r : releases) r["width"] = number_node(v);
        break;
      case EnsembleInput::log_density:
        for (YAML::Node r : releases) r["density"] = number_node(v);
        break;
      case EnsembleInput::release_rate:
        for (YAML::Node r : releases) {
          if (r["count"]) fail(input, "a release given with a count has no rate");
          r["rate"] = number_node(v);
        }
        break;
      case EnsembleInput::discharge_scale: {
        int scaled = 0;
        for (auto entry : root["flow"]["boundaries"]) {
          YAML::Node bc = entry.second;
          if (!bc["type"] || bc["type"].Scalar() != "discharge") continue;
          YAML::Node value = bc["value"];
          if (value.IsSequence())
            for (YAML::Node row : value) row[1] = number_node(v * node_number(row[1]));
          else
            bc["value"] = number_node(v * node_number(value));
          ++scaled;
        }
        if (scaled == 0) fail(input, "the case has no discharge boundary to scale");
        break;
      }
      case EnsembleInput::restitution:
        root["bodies"]["contact"]["restitution"] = number_node(v);
        break;
      case EnsembleInput::contact_friction:
        root["bodies"]["contact"]["friction"] = number_node(v);
        break;
      case EnsembleInput::bed_friction:
        root["bodies"]["physics"]["bed_friction"] = number_node(v);
        break;
      case EnsembleInput::release_shift_x:
      case EnsembleInput::release_shift_y: {
        const double dx = input == EnsembleInput::release_shift_x ? v : 0.0;
        for (YAML::Node r : releases) shift_points(r[r["zone"] ? "zone" : "line"], dx, v - dx);
        break;
      }
      case EnsembleInput::count:
        break;
    }
  }
  for (std::size_t k = 0; releases.IsSequence() && k < releases.size(); ++k)
    releases[k]["seed"] = inputs.release_seeds.at(k);
  const std::string name = member_name(inputs.member);
  root["name"] = name;
  root["output"]["directory"] = context.directory.string();

  YAML::Emitter out;
  out << root;
  std::string header = fmt::format("# Member {} of the ensemble of {} (draw {}", inputs.member,
                                   context.source, inputs.draw);
  for (const auto& [input, v] : inputs.values)
    header += fmt::format(", {} = {} {}", input_key(input), v, input_unit(input));
  header += fmt::format(").\n# Rerun it alone:\n#   flotsam run {}.yaml -o {} --overwrite\n",
                        (context.directory / name).string(), (context.directory / name).string());
  return header + out.c_str() + "\n";
}

}  // namespace flotsam
