#include "io/run_state.hpp"

#include "io/binary_archive.hpp"

namespace flotsam {

template <>
struct archive_fields<BoundaryEdge> {
  static constexpr auto fields =
      std::make_tuple(&BoundaryEdge::element, &BoundaryEdge::local_edge, &BoundaryEdge::group);
};

namespace {

std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& line : lines) text += line + "\n";
  return text;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    lines.push_back(text.substr(start, end - start));
  return lines;
}

}  // namespace

void write_run_description(const std::string& path, const RunDescription& run) {
  const Mesh& m = run.mesh;
  ArchiveWriter w(path);
  w.write_text("name", run.name);
  w.write_text("mesh.source", m.source);
  w.write_value("mesh.vertex_count", m.vertex_count);
  w.write("mesh.nodes", m.nodes);
  w.write("mesh.elements", m.elements);
  w.write("mesh.neighbours", m.neighbours);
  w.write("mesh.area", m.area);
  w.write("mesh.boundary", m.boundary);
  w.write_text("mesh.group_names", join_lines(m.group_names));
  w.write("mesh.node_tags", m.node_tags);
  w.write("mesh.element_tags", m.element_tags);
  w.write("open_group", run.open_group);
  if (!run.decks.empty()) w.write("decks", run.decks);
  w.close();
}

RunDescription read_run_description(const std::string& path) {
  ArchiveReader r(path);
  RunDescription run;
  run.name = r.read_text("name");
  Mesh& m = run.mesh;
  m.source = r.read_text("mesh.source");
  m.vertex_count = r.read_value<int>("mesh.vertex_count");
  m.nodes = r.read<Vec2>("mesh.nodes");
  m.elements = r.read<std::array<int, 6>>("mesh.elements");
  m.neighbours = r.read<std::array<int, 3>>("mesh.neighbours");
  m.area = r.read<double>("mesh.area");
  m.boundary = r.read<BoundaryEdge>("mesh.boundary");
  m.group_names = split_lines(r.read_text("mesh.group_names"));
  m.node_tags = r.read<long>("mesh.node_tags");
  m.element_tags = r.read<long>("mesh.element_tags");
  run.open_group = r.read<std::uint8_t>("open_group");
  if (r.next_is("decks")) run.decks = r.read<std::array<Vec2, 4>>("decks");
  r.finish();
  return run;
}

void write_run_snapshot(const std::string& path, double time, const std::vector<double>& eta,
                        const std::vector<double>& u, const std::vector<double>& v,
                        const std::vector<std::uint8_t>& wet, const BodySet& bodies,
                        const std::vector<std::uint8_t>& jammed) {
  ArchiveWriter w(path);
  w.write_value("time", time);
  w.write("eta", eta);
  w.write("u", u);
  w.write("v", v);
  w.write("wet", wet);
  w.write("bodies.id", bodies.id);
  w.write("bodies.position", bodies.position);
  w.write("bodies.angle", bodies.angle);
  w.write("bodies.length", bodies.length);
  w.write("bodies.width", bodies.width);
  w.write("bodies.state", bodies.state);
  w.write("bodies.jammed", jammed);
  w.close();
}

RunSnapshot read_run_snapshot(const std::string& path) {
  ArchiveReader r(path);
  RunSnapshot s;
  s.time = r.read_value<double>("time");
  s.eta = r.read<double>("eta");
  s.u = r.read<double>("u");
  s.v = r.read<double>("v");
  s.wet = r.read<std::uint8_t>("wet");
  s.id = r.read<long>("bodies.id");
  s.position = r.read<Vec2>("bodies.position");
  s.angle = r.read<double>("bodies.angle");
  s.length = r.read<double>("bodies.length");
  s.width = r.read<double>("bodies.width");
  s.state = r.read<BodyState>("bodies.state");
  s.jammed = r.read<std::uint8_t>("bodies.jammed");
  r.finish();
  return s;
}

}  // namespace flotsam
