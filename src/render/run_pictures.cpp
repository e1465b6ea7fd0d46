#include "render/run_pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "core/error.hpp"
#include "io/run_state.hpp"
#include "render/derived_fields.hpp"
#include "render/frame.hpp"
#include "render/scene.hpp"

namespace flotsam {
namespace fs = std::filesystem;
namespace {

std::vector<fs::path> snapshot_files(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("state_") && entry.path().extension() == ".bin")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// The piers' region widened by one channel width along x, across the whole channel; the whole
/// mesh when there is no group named pier_*.
std::optional<ViewWindow> pier_window(const Mesh& mesh) {
  const ViewWindow all = bounding_box(mesh);
  double x_min = INFINITY, x_max = -INFINITY;
  for (const BoundaryEdge& edge : mesh.boundary) {
    if (!mesh.group_names[edge.group].starts_with("pier")) continue;
    for (int n : mesh.edge_nodes(edge.element, edge.local_edge)) {
      x_min = std::min(x_min, mesh.nodes[n].x());
      x_max = std::max(x_max, mesh.nodes[n].x());
    }
  }
  if (!(x_min < x_max)) return std::nullopt;
  const double margin = 0.6 * (all.y_max - all.y_min);
  return ViewWindow{std::max(all.x_min, x_min - margin), std::min(all.x_max, x_max + margin),
                    all.y_min, all.y_max};
}

SceneBodies bodies_of(const RunSnapshot& s) {
  SceneBodies bodies;
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    BodyCategory category = s.state[i] == BodyState::gone       ? BodyCategory::gone
                            : !s.jammed.empty() && s.jammed[i]  ? BodyCategory::jammed
                            : s.state[i] == BodyState::grounded ? BodyCategory::grounded
                                                                : BodyCategory::floating;
    if (category == BodyCategory::gone) continue;
    bodies.add(s.position[i], s.angle[i], s.length[i], s.width[i], category);
  }
  return bodies;
}

Scene base_scene(const RunDescription& run, const RunSnapshot& s, const PictureOptions& o) {
  Scene scene;
  scene.mesh = &run.mesh;
  scene.width = o.width;
  scene.height = o.height;
  scene.time = s.time;
  scene.bodies = bodies_of(s);
  scene.wet = s.wet;
  for (std::uint8_t open : run.open_group)
    scene.boundary_kinds.push_back(open ? BoundaryKind::open : BoundaryKind::wall);
  scene.decks = run.decks;
  return scene;
}

}  // namespace

std::vector<std::string> render_run(const std::string& run_directory, const PictureOptions& options,
                                    const std::function<void(const std::string&)>& report) {
  const fs::path dir(run_directory);
  if (!fs::exists(dir / "run.bin"))
    throw_input_error(
        "'{}' is not a flotsam run folder (no run.bin in it); give the folder that `flotsam "
        "run` wrote, e.g. out/bridge_piers",
        run_directory);
  const RunDescription run = read_run_description((dir / "run.bin").string());
  const std::vector<fs::path> states = snapshot_files(dir);
  if (states.empty())
    throw_input_error("'{}' holds no state_*.bin: the run wrote no output yet", run_directory);
  std::vector<std::string> written;
  auto save = [&](const Scene& scene, const fs::path& path) {
    render_png(scene, path.string());
    written.push_back(path.string());
    if (report) report(path.string());
  };

  std::vector<RunSnapshot> snapshots;
  for (const auto& file : states) {
    snapshots.push_back(read_run_snapshot(file.string()));
    const RunSnapshot& s = snapshots.back();
    const auto nodes = static_cast<std::size_t>(run.mesh.node_count());
    const auto vertices = static_cast<std::size_t>(run.mesh.vertex_count);
    if (s.eta.size() != vertices || s.u.size() != nodes || s.v.size() != nodes ||
        (!s.wet.empty() && s.wet.size() != nodes))
      throw_input_error(
          "'{}' does not belong to the run in '{}': it holds {} surface values and {} velocities, "
          "the run's mesh {} vertices and {} nodes (a state file copied from another run?)",
          file.string(), run_directory, s.eta.size(), s.u.size(), vertices, nodes);
  }
  const RunSnapshot& last = snapshots.back();
  const std::optional<ViewWindow> zoom = pier_window(run.mesh);

  // Figures 15 and 16 at the last output; Fig. 17 at the output with the most bodies among the
  // piers (the latest of equals), since by the end they may all have left.
  const RunSnapshot* busiest = &last;
  int most = -1;
  for (const RunSnapshot& snapshot : snapshots) {
    int among = 0;
    for (std::size_t i = 0; i < snapshot.position.size(); ++i) {
      const Vec2& p = snapshot.position[i];
      among += snapshot.state[i] != BodyState::gone &&
               (!zoom || (p.x() >= zoom->x_min && p.x() <= zoom->x_max));
    }
    if (among >= most) most = among, busiest = &snapshot;
  }
  {
    Scene scene = base_scene(run, last, options);
    scene.field = {"eta", "m", last.eta};
    scene.title = fmt::format("{}: water surface elevation", run.name);
    save(scene, dir / "water_surface.png");
  }
  {
    Scene scene = base_scene(run, last, options);
    scene.field = {"|u|", "m/s", speed_field(last.u, last.v)};
    scene.u_x = last.u;
    scene.u_y = last.v;
    scene.view = zoom;
    scene.bodies = {};
    scene.title = fmt::format("{}: velocity magnitude through the bridges", run.name);
    save(scene, dir / "velocity.png");
  }
  {
    Scene scene = base_scene(run, *busiest, options);
    scene.field = {"|u|", "m/s", speed_field(busiest->u, busiest->v)};
    scene.view = zoom;
    if (zoom)  // widened along x to every body still in the water
      for (int i = 0; i < scene.bodies.size(); ++i) {
        const double reach = 0.5 * scene.bodies.length[i] + 10.0;  // [m]
        scene.view->x_min = std::min(scene.view->x_min, scene.bodies.position[i].x() - reach);
        scene.view->x_max = std::max(scene.view->x_max, scene.bodies.position[i].x() + reach);
      }
    scene.title = fmt::format("{}: bodies among the piers", run.name);
    save(scene, dir / "bodies.png");
  }

  if (options.frames) {
    // One colour scale for the whole series: the largest speed of all outputs.
    double top = 0.0;
    for (const RunSnapshot& snapshot : snapshots)
      for (double speed : speed_field(snapshot.u, snapshot.v)) top = std::max(top, speed);
    fs::create_directories(dir / "frames");
    for (std::size_t k = 0; k < snapshots.size(); ++k) {
      Scene scene = base_scene(run, snapshots[k], options);
      scene.field = {"|u|", "m/s", speed_field(snapshots[k].u, snapshots[k].v)};
      scene.range = {ColourRange::Kind::fixed, 0.0, top > 0 ? top : 1.0};
      scene.title = run.name;
      save(scene, dir / "frames" / fmt::format("frame_{:06d}.png", k));
    }
    if (options.movie && snapshots.size() > 1 && std::system("command -v ffmpeg >/dev/null") == 0) {
      const fs::path movie = dir / "movie.mp4";
      const std::string command = fmt::format(
          "ffmpeg -y -loglevel error -framerate 8 -i '{}' -vf "
          "'scale=trunc(iw/2)*2:trunc(ih/2)*2' -pix_fmt yuv420p '{}'",
          (dir / "frames" / "frame_%06d.png").string(), movie.string());
      if (std::system(command.c_str()) != 0)
        throw_run_error("ffmpeg could not make '{}' from the frames", movie.string());
      written.push_back(movie.string());
      if (report) report(movie.string());
    }
  }
  return written;
}

}  // namespace flotsam
