#include "ensemble/member_result.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"

namespace flotsam {

namespace {

constexpr const char* result_file = "member.txt";
constexpr const char* magic = "flotsam member 1";

/// The shortest text that reads back as the same double ("nan" for NaN).
std::string exact(double v) {
  return fmt::format("{}", v);
}

double read_double(std::istringstream& in) {
  std::string word;
  if (!(in >> word)) throw std::invalid_argument("member result: a number is missing");
  char* end = nullptr;
  const double v = std::strtod(word.c_str(), &end);
  if (end == word.c_str() || *end != '\0')
    throw std::invalid_argument("member result: not a number: " + word);
  return v;
}

long read_long(std::istringstream& in) {
  long v = 0;
  if (!(in >> v)) throw std::invalid_argument("member result: an integer is missing");
  return v;
}

EnsembleInput input_from_key(const std::string& key) {
  for (int k = 0; k < static_cast<int>(EnsembleInput::count); ++k)
    if (key == input_key(static_cast<EnsembleInput>(k))) return static_cast<EnsembleInput>(k);
  throw std::invalid_argument("member result: unknown input " + key);
}

}  // namespace

std::string serialize_member(const MemberResult& r) {
  std::string s = std::string(magic) + "\n";
  const MemberInputs& in = r.inputs;
  s += fmt::format("member {} sweep {} draw {}\n", in.member, in.sweep_index, in.draw);
  for (const auto& [input, v] : in.values)
    s += fmt::format("input {} {}\n", input_key(input), exact(v));
  for (long seed : in.release_seeds) s += fmt::format("seed {}\n", seed);
  s += fmt::format("status {}\n", r.failed ? "failed" : "ok");
  if (r.failed) {
    std::string message = r.message;
    for (char& c : message)
      if (c == '\n') c = ' ';
    s += "message " + message + "\n";
  }
  s += fmt::format("counts {} {} {} {} {} {}\n", r.released, r.passed, r.left, r.trapped,
                   r.stranded, r.floating);
  for (const BridgeOutcome& b : r.bridges)
    s += fmt::format("bridge {} {} {} {} {} {} {}\n", b.blocked ? 1 : 0, exact(b.blocking_time),
                     b.blocking_bodies, b.largest_jam, exact(b.max_blockage), exact(b.max_rise),
                     exact(b.max_opening_closed));
  for (std::size_t b = 0; b < r.gaps.size(); ++b)
    for (const GapOutcome& g : r.gaps[b])
      s += fmt::format("gap {} {} {} {} {}\n", b, g.blocked ? 1 : 0, exact(g.blocking_time),
                       exact(g.max_cover), exact(g.max_opening_closed));
  for (const BodyOutcome& b : r.bodies)
    s +=
        fmt::format("body {} {} {} {} {} {} {}\n", b.id, exact(b.start.x()), exact(b.start.y()),
                    exact(b.end.x()), exact(b.end.y()), static_cast<int>(b.fate), b.passed ? 1 : 0);
  s += fmt::format("wall {}\nend\n", exact(r.wall_seconds));
  return s;
}

MemberResult parse_member(const std::string& text) {
  std::istringstream lines(text);
  std::string line;
  if (!std::getline(lines, line) || line != magic)
    throw std::invalid_argument("member result: not a member result");
  MemberResult r;
  bool ended = false;
  while (std::getline(lines, line)) {
    std::istringstream in(line);
    std::string tag;
    in >> tag;
    if (tag == "member") {
      std::string word;  // "member M sweep S draw J": each label is followed by its number
      r.inputs.member = static_cast<int>(read_long(in));
      in >> word;
      r.inputs.sweep_index = static_cast<int>(read_long(in));
      in >> word;
      r.inputs.draw = static_cast<int>(read_long(in));
    } else if (tag == "input") {
      std::string key;
      in >> key;
      const EnsembleInput input = input_from_key(key);
      r.inputs.values.emplace_back(input, read_double(in));
    } else if (tag == "seed") {
      r.inputs.release_seeds.push_back(read_long(in));
    } else if (tag == "status") {
      std::string status;
      in >> status;
      r.failed = status == "failed";
    } else if (tag == "message") {
      r.message = line.size() > 8 ? line.substr(8) : "";
    } else if (tag == "counts") {
      int* counts[] = {&r.released, &r.passed, &r.left, &r.trapped, &r.stranded, &r.floating};
      for (int* c : counts) *c = static_cast<int>(read_long(in));
    } else if (tag == "bridge") {
      BridgeOutcome b;
      b.blocked = read_long(in) != 0;
      b.blocking_time = read_double(in);
      b.blocking_bodies = static_cast<int>(read_long(in));
      b.largest_jam = static_cast<int>(read_long(in));
      b.max_blockage = read_double(in);
      b.max_rise = read_double(in);
      b.max_opening_closed = read_double(in);
      r.bridges.push_back(b);
    } else if (tag == "gap") {
      const auto bridge = static_cast<std::size_t>(read_long(in));
      if (r.gaps.size() <= bridge) r.gaps.resize(bridge + 1);
      GapOutcome g;
      g.blocked = read_long(in) != 0;
      g.blocking_time = read_double(in);
      g.max_cover = read_double(in);
      g.max_opening_closed = read_double(in);
      r.gaps[bridge].push_back(g);
    } else if (tag == "body") {
      BodyOutcome b;
      b.id = read_long(in);
      const double x0 = read_double(in), y0 = read_double(in);
      const double x1 = read_double(in), y1 = read_double(in);
      b.start = {x0, y0};
      b.end = {x1, y1};
      b.fate = static_cast<BodyFate>(read_long(in));
      b.passed = read_long(in) != 0;
      r.bodies.push_back(b);
    } else if (tag == "wall") {
      r.wall_seconds = read_double(in);
    } else if (tag == "end") {
      ended = true;
      break;
    } else {
      throw std::invalid_argument("member result: unknown line: " + line);
    }
  }
  if (!ended) throw std::invalid_argument("member result: incomplete (no end line)");
  return r;
}

void write_member_result(const std::filesystem::path& folder, const MemberResult& result) {
  const std::filesystem::path path = folder / result_file, partial = folder / "member.txt.part";
  {
    std::ofstream out(partial, std::ios::binary);
    out << serialize_member(result);
    if (!out) throw_run_error("could not write '{}'", partial.string());
  }
  std::filesystem::rename(partial, path);
}

std::optional<MemberResult> read_member_result(const std::filesystem::path& folder) {
  std::ifstream in(folder / result_file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return parse_member(text.str());
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

}  // namespace flotsam
