// The case file's `flow` section (docs/case-format.md, spec 1).
#include <fmt/format.h>

#include <string_view>

#include "io/case_sections.hpp"
#include "mesh/simple_polygon.hpp"

namespace flotsam {

namespace {

// nu from the key `viscosity`, or from `reynolds` via nu = U_ref L_ref / Re (spec 1.2).
double read_viscosity(const YamlMap& m, double fallback) {
  const std::string given = m.only_one_of({"viscosity", "reynolds"});
  if (given == "viscosity")
    return m.get("viscosity").number(Range::between(0.0, 1000.0));  // [m^2/s]
  if (given.empty()) return fallback;
  const YamlMap re = m.get("reynolds").map();
  const double number = re.get("number", "Re [-]").number(Range::positive());
  const double U = re.get("reference_velocity", "U_ref [m/s]").number(Range::positive());
  const double L = re.get("reference_length", "L_ref [m]").number(Range::positive());
  return U * L / number;  // spec 1.2
}

void read_turbulence(const YamlMap& m, FlowConfig& flow) {
  flow.turbulence =
      m.get("model").choice<TurbulenceModel>({{"none", TurbulenceModel::none},
                                              {"smagorinsky", TurbulenceModel::smagorinsky},
                                              {"mixing-length", TurbulenceModel::mixing_length}});
  if (flow.turbulence == TurbulenceModel::smagorinsky) {
    flow.smagorinsky_constant =
        m.number("smagorinsky_constant", flow.smagorinsky_constant, Range::positive());
  } else {
    m.forbid("smagorinsky_constant", "only used with model 'smagorinsky'");
  }
}

// The finite-volume engine's numerical choices (src/flow/fv).
FiniteVolumeConfig read_finite_volume(const YamlMap& m) {
  FiniteVolumeConfig fv;
  fv.order = static_cast<int>(m.integer("order", fv.order, Range::between(1, 2)));
  fv.courant = m.number("courant", fv.courant, {0.0, 1.0, true, false});
  if (m.has("cells"))
    fv.cells = m.get("cells").choice<FvCells>(
        {{"elements", FvCells::elements}, {"split", FvCells::split}});
  fv.velocity_depth = m.number("velocity_depth", fv.velocity_depth, Range::positive());
  if (const auto levels = m.find("time_levels"))  // 1..8, or auto (0)
    fv.time_levels = levels->is_number() ? static_cast<int>(levels->integer(Range::between(1, 8)))
                                         : levels->choice<int>({{"auto", 0}});
  fv.pier_drag = m.number("pier_drag", fv.pier_drag, Range::between(0.0, 10.0));
  return fv;
}

// Rain: an intensity i [mm/h] (a number or a hyetograph [[t, i], ...]), an optional raster of
// weights multiplying it, and an optional infiltration f [mm/h], both >= 0. The raster's values
// are checked under the cells when the run starts (flow/fv/rain_source.hpp).
RainConfig read_rain(const YamlValue& value, const std::filesystem::path& case_folder,
                     std::vector<GeodataCrs>& geodata) {
  const YamlMap m = value.map();
  RainConfig rain;
  rain.enabled = true;
  rain.line = value.key_line();
  rain.intensity = m.get("intensity", "i [mm/h], a number or a hyetograph [[t, i], ...]")
                       .series("t", Range::non_negative());
  rain.infiltration = m.number("infiltration", rain.infiltration, Range::non_negative());
  if (const auto raster = m.find("raster")) {
    rain.raster_origin = raster->origin();
    rain.raster = std::make_shared<const Raster>(
        Raster::read(raster->input_path(case_folder.string()), rain.raster_origin));
    if (!rain.raster->grid().crs_wkt.empty())
      geodata.push_back(
          {rain.raster->grid().crs_wkt, fmt::format("the rain raster '{}'", rain.raster->path())});
  }
  return rain;
}

// Sources: a list of {name?, point: [x, y] | polygon: [[x, y], ...], discharge: Q or [[t, Q], ...]}
// with Q >= 0 [m^3/s]. Where they fall on the cells is checked when the run starts
// (flow/fv/flow_sources.hpp).
std::vector<FlowSource> read_sources(const YamlValue& value) {
  std::vector<FlowSource> sources;
  const std::vector<YamlValue> items = value.list();
  if (items.empty()) value.fail("expected a list of sources {point: [x, y] or polygon, discharge}");
  for (const YamlValue& item : items) {
    const YamlMap m = item.map();
    FlowSource s;
    s.name = m.text("name", fmt::format("flow.sources[{}]", sources.size()));
    s.origin = m.has("name") ? fmt::format("{} ({})", item.origin(), s.name) : item.origin();
    const std::string kind = m.only_one_of({"point", "polygon"});
    if (kind.empty()) item.fail("expected 'point: [x, y]' or 'polygon: [[x, y], ...]' [m]");
    if (kind == "point") {
      s.point = m.get("point").vec2();
    } else {
      const YamlValue polygon = m.get("polygon");
      for (const YamlValue& corner : polygon.list()) s.polygon.push_back(corner.vec2());
      if (const std::string defect = polygon_defect(s.polygon); !defect.empty())
        polygon.fail(defect);
    }
    s.discharge = m.get("discharge", "Q [m^3/s] >= 0, a number or a hydrograph [[t, Q], ...]")
                      .series("t", Range::non_negative());
    sources.push_back(std::move(s));
  }
  return sources;
}

// A velocity component of the initial state: a number or a formula, both kept as a formula;
// absent: empty (at rest).
Expression read_initial_velocity(const YamlMap& m, std::string_view key) {
  const auto value = m.find(key);
  return value ? value->expression() : Expression();
}

// Still water with eta linear in x between two values (spec 8.2), or flat, or a formula in x, y;
// u and v are zero unless given.
void read_initial(const YamlMap& m, FlowConfig& flow) {
  const std::string given = m.only_one_of({"eta", "eta_start"});
  if (given.empty()) m.fail("expected 'eta' [m], or 'eta_start' and 'eta_end' [m]");
  flow.initial_u = read_initial_velocity(m, "u");
  flow.initial_v = read_initial_velocity(m, "v");
  if (given == "eta") {
    const YamlValue eta = m.get("eta");
    if (eta.is_number()) {
      m.forbid("eta_end", "with 'eta' the surface is flat; use eta_start and eta_end for a slope");
      flow.initial_eta_start = flow.initial_eta_end = eta.number();
    } else {
      m.forbid("eta_end", "with 'eta' as a formula the surface is the formula's");
      flow.initial_eta = eta.expression();
    }
    return;
  }
  flow.initial_eta_start = m.get("eta_start").number();
  flow.initial_eta_end = m.get("eta_end", "eta at the largest x [m]").number();
}

BoundaryCondition read_boundary(const std::string& group, const YamlValue& value) {
  using Kind = BoundaryCondition::Kind;
  const YamlMap m = value.map();
  BoundaryCondition bc;
  bc.group = group;
  bc.line = value.key_line();
  bc.kind = m.get("type").choice<Kind>({{"elevation", Kind::elevation},
                                        {"discharge", Kind::discharge},
                                        {"velocity", Kind::velocity},
                                        {"wall", Kind::wall},
                                        {"noslip", Kind::noslip},
                                        {"free", Kind::free}});
  switch (bc.kind) {
    case Kind::elevation:
    case Kind::discharge: {
      const bool is_eta = bc.kind == Kind::elevation;
      m.forbid("u", "only a velocity condition takes u and v");
      m.forbid("v", "only a velocity condition takes u and v");
      bc.value = m.get("value", is_eta ? "eta_b [m], a number or a table [[t, eta_b], ...]"
                                       : "Q [m^3/s], a number or a table [[t, Q], ...]")
                     .series("t");
      break;
    }
    case Kind::velocity:
      m.forbid("value", "a velocity condition takes u and v [m/s]");
      bc.value = m.get("u", "u_b [m/s], a number or a table [[t, u], ...]").series("t");
      bc.value_y = m.get("v", "v_b [m/s], a number or a table [[t, v], ...]").series("t");
      break;
    case Kind::wall:
    case Kind::noslip:
      for (const char* key : {"value", "u", "v"}) m.forbid(key, "a wall takes no value");
      break;
    case Kind::free:
      for (const char* key : {"value", "u", "v"})
        m.forbid(key, "a free boundary takes no value: what reaches it leaves");
      break;
  }
  return bc;
}

}  // namespace

FlowConfig read_flow(const YamlMap& m, const std::filesystem::path& case_folder,
                     std::vector<GeodataCrs>& geodata) {
  FlowConfig flow;
  if (const auto engine = m.find("engine"))
    flow.engine =
        engine->choice<FlowEngineKind>({{"fem", FlowEngineKind::fem}, {"fv", FlowEngineKind::fv}});
  if (flow.engine == FlowEngineKind::fv)
    flow.fv = read_finite_volume(m.map("fv"));
  else
    m.forbid("fv", "flow.fv only applies to 'engine: fv' (the engine is fem)");
  if (const auto scheme = m.find("scheme")) {
    if (flow.engine == FlowEngineKind::fv)
      scheme->fail("flow.scheme only applies to 'engine: fem' (the engine is fv)");
    flow.scheme = scheme->choice<FlowScheme>(
        {{"coupled", FlowScheme::coupled}, {"segregated", FlowScheme::segregated}});
  }
  flow.gravity = m.number("gravity", flow.gravity, Range::up_to(100.0));  // [m s^-2]
  // [kg m^-3] fresh, salt and muddy water
  flow.water_density = m.number("density", flow.water_density, Range::between(500.0, 2500.0));
  flow.viscosity = read_viscosity(m, flow.viscosity);
  if (m.has("friction")) read_friction(m.get("friction").map(), case_folder, flow, geodata);
  if (flow.engine == FlowEngineKind::fv)
    m.forbid("turbulence",
             "flow.turbulence only applies to 'engine: fem' (the finite-volume engine has no eddy "
             "viscosity)");
  else if (m.has("turbulence"))
    read_turbulence(m.get("turbulence").map(), flow);
  if (m.has("coriolis")) {
    flow.coriolis = true;
    flow.latitude_deg = m.get("coriolis")
                            .map()
                            .get("latitude_deg", "phi [deg]")
                            .number(Range::between(-90.0, 90.0));
  }
  if (m.has("wind")) flow.wind = m.get("wind").map().get("velocity", "W [m/s] as [x, y]").vec2();
  if (m.has("rain")) flow.rain = read_rain(m.get("rain"), case_folder, geodata);
  if (const auto sources = m.find("sources")) {
    if (flow.engine == FlowEngineKind::fem)
      sources->fail(
          "flow.sources are taken by 'engine: fv' only (the FEM engine has no sources: let the "
          "water in through a discharge boundary, or use the finite-volume engine)");
    flow.sources = read_sources(*sources);
  }
  flow.min_depth = m.number("min_depth", flow.min_depth, Range::positive());
  if (const auto dry = m.find("dry_depth")) flow.dry_depth = dry->number(Range::positive());
  read_initial(m.get("initial", "the initial water surface").map(), flow);

  const YamlValue boundaries =
      m.get("boundaries", "a condition for every boundary group of the mesh");
  for (const auto& [group, value] : boundaries.map().entries())
    flow.boundaries.push_back(read_boundary(group, value));
  if (flow.boundaries.empty())
    boundaries.fail("expected a map of boundary group -> {type: ..., value: ...}");
  return flow;
}

}  // namespace flotsam
