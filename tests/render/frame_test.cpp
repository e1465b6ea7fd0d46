// Verifies that a drawn frame has the requested size, that every pixel over the mesh shows the
// colour map's colour of the field's exact value at the pixel's centre (P1 and P2 fields), that
// bodies, piers and arrows appear where they stand, and that bad scenes and unwritable files are
// reported by name.
#include "render/frame.hpp"

#include <cairo.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "../mesh/holey_mesh.hpp"
#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "mesh/structured_mesh.hpp"
#include "render/body_layer.hpp"
#include "render/cairo_draw.hpp"
#include "render/frame_layout.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// Cairo keeps its font faces (and their fontconfig patterns) in static caches; release them at
// the end (release_font_caches) so that the sanitizer build's leak check sees only leaks of our
// own.
class CairoStaticData : public ::testing::Environment {
 public:
  void TearDown() override { release_font_caches(); }
};
const auto* const cairo_static_data =
    ::testing::AddGlobalTestEnvironment(new CairoStaticData);  // gtest owns it

// The channel [0, 4] x [0, 2] m in 4 x 2 cells, f = x at its vertices (P1), range [0, 4].
struct RampScene {
  Mesh mesh = make_rectangle_mesh({.length = 4.0, .width = 2.0, .nx = 4, .ny = 2});
  Scene scene;  // points at `mesh`: not copyable
  RampScene(const RampScene&) = delete;
  RampScene() {
    scene.mesh = &mesh;
    scene.field.name = "f";
    scene.field.unit = "m";
    for (int v = 0; v < mesh.vertex_count; ++v) scene.field.values.push_back(mesh.nodes[v].x());
    scene.width = 480;
    scene.height = 300;
    scene.title = "ramp";
    scene.time = 3725.0;
  }
};

/// The pixel whose square holds world point p, and the world point at that pixel's centre.
std::pair<int, int> pixel_of(const FrameLayout& layout, const Vec2& p) {
  const Vec2 q = layout.to_pixel(p);
  return {static_cast<int>(std::floor(q.x())), static_cast<int>(std::floor(q.y()))};
}
Vec2 centre_of(const FrameLayout& layout, std::pair<int, int> pixel) {
  return layout.to_world({pixel.first + 0.5, pixel.second + 0.5});
}

void expect_near(const Colour& got, const Colour& want, int tolerance, const std::string& where) {
  EXPECT_NEAR(got.r, want.r, tolerance) << where;
  EXPECT_NEAR(got.g, want.g, tolerance) << where;
  EXPECT_NEAR(got.b, want.b, tolerance) << where;
}

TEST(Frame, PngHasTheRequestedSizeAndMoreThanOneColour) {
  RampScene ramp;
  const fs::path path = test::scratch_path("flotsam_render_frame_test.png");
  render_png(ramp.scene, path.string());
  cairo_surface_t* png = cairo_image_surface_create_from_png(path.c_str());
  ASSERT_EQ(cairo_surface_status(png), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(png), 480);
  EXPECT_EQ(cairo_image_surface_get_height(png), 300);
  // The file holds the same pixels as the in-memory picture.
  const Image image = render_image(ramp.scene);
  cairo_surface_flush(png);
  const unsigned char* data = cairo_image_surface_get_data(png);
  const int stride = cairo_image_surface_get_stride(png);
  std::set<std::uint32_t> colours;
  int differing = 0;
  for (int y = 0; y < 300; ++y) {
    for (int x = 0; x < 480; ++x) {
      const auto p =
          *reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x) | 0xff000000u;
      colours.insert(p);
      differing += p != image.argb[y * 480 + x];
    }
  }
  cairo_surface_destroy(png);
  fs::remove(path);
  EXPECT_EQ(differing, 0);
  EXPECT_GT(colours.size(), 50u);  // a ramp over hundreds of pixel columns
}

TEST(Frame, PixelsShowTheColourOfTheP1FieldAtTheirCentre) {
  RampScene ramp;
  const FrameLayout layout = frame_layout(ramp.scene);
  const Image image = render_image(ramp.scene);
  // Points away from the boundary lines; f = x over [0, 4].
  double previous_t = -1.0;
  for (const double x : {0.3, 0.9, 1.5, 2.0, 2.6, 3.1, 3.7}) {
    for (const double y : {0.4, 1.0, 1.7}) {
      const auto pixel = pixel_of(layout, {x, y});
      const double t = centre_of(layout, pixel).x() / 4.0;
      expect_near(image.at(pixel.first, pixel.second), colour_at(ColourMapName::viridis, t), 1,
                  fmt::format("at ({}, {})", x, y));
      if (y == 1.0) {
        EXPECT_GT(t, previous_t);  // further right, higher value
        previous_t = t;
      }
    }
  }
}

TEST(Frame, PixelsShowTheP2FieldItselfNotALinearBlend) {
  // f = (x - 2)^2 is exactly P2 on the mesh; a linear blend of colours of the vertex values
  // would be wrong inside each element. Range [0, 4].
  RampScene ramp;
  ramp.scene.field.values.clear();
  for (const Vec2& p : ramp.mesh.nodes)
    ramp.scene.field.values.push_back((p.x() - 2) * (p.x() - 2));
  const FrameLayout layout = frame_layout(ramp.scene);
  const Image image = render_image(ramp.scene);
  for (const double x : {0.25, 0.5, 1.3, 1.9, 2.45, 3.5}) {
    const auto pixel = pixel_of(layout, {x, 0.77});
    const Vec2 c = centre_of(layout, pixel);
    const double t = (c.x() - 2) * (c.x() - 2) / 4.0;
    expect_near(image.at(pixel.first, pixel.second), colour_at(ColourMapName::viridis, t), 1,
                fmt::format("at x = {}", x));
  }
}

TEST(Frame, SymmetricRangeCentresZeroOnTheMiddleColour) {
  RampScene ramp;
  for (double& f : ramp.scene.field.values) f -= 1.0;  // f = x - 1 in [-1, 3]: range [-3, 3]
  ramp.scene.colour_map = ColourMapName::blue_white_red;
  ramp.scene.range.kind = ColourRange::Kind::symmetric;
  const FrameLayout layout = frame_layout(ramp.scene);
  const Image image = render_image(ramp.scene);
  const auto pixel = pixel_of(layout, {3.2, 1.3});
  const double t = (centre_of(layout, pixel).x() - 1.0 + 3.0) / 6.0;
  expect_near(image.at(pixel.first, pixel.second), colour_at(ColourMapName::blue_white_red, t), 1,
              "at (3.2, 1.3)");
}

TEST(Frame, BodyIsDrawnInItsCategoryColourWhereItStands) {
  RampScene ramp;
  ramp.scene.bodies.add({1.0, 1.0}, 0.3, 0.8, 0.4, BodyCategory::jammed);
  ramp.scene.bodies.add({3.0, 1.0}, 1.2, 0.8, 0.4, BodyCategory::grounded);
  const FrameLayout layout = frame_layout(ramp.scene);
  const Image before = render_image(RampScene().scene);
  const Image image = render_image(ramp.scene);
  const auto jammed = pixel_of(layout, {1.0, 1.0});
  const auto grounded = pixel_of(layout, {3.0, 1.0});
  EXPECT_EQ(image.at(jammed.first, jammed.second), body_colour(BodyCategory::jammed));
  EXPECT_EQ(image.at(grounded.first, grounded.second), body_colour(BodyCategory::grounded));
  EXPECT_NE(before.at(jammed.first, jammed.second), body_colour(BodyCategory::jammed));
  // Beyond the rotated body's far end (0.8 m long, turned 0.3 rad): the field again.
  const auto outside = pixel_of(layout, {1.0 + 0.6 * std::cos(0.3), 1.0 + 0.6 * std::sin(0.3)});
  EXPECT_EQ(image.at(outside.first, outside.second), before.at(outside.first, outside.second));
}

TEST(Frame, CategoriesHaveDistinctColours) {
  std::set<std::tuple<int, int, int>> colours;
  for (const auto c :
       {BodyCategory::floating, BodyCategory::grounded, BodyCategory::jammed, BodyCategory::gone}) {
    const Colour k = body_colour(c);
    colours.insert({k.r, k.g, k.b});
  }
  EXPECT_EQ(colours.size(), 4u);
}

TEST(Frame, HoleIsFilledPierGreyAndOutsideIsLand) {
  const Mesh mesh = build_mesh(fixtures::make_holey_raw(2));
  Scene scene;
  scene.mesh = &mesh;
  scene.field = {"f", "m", std::vector<double>(mesh.vertex_count, 1.0)};
  scene.width = 600;
  scene.height = 440;
  const FrameLayout layout = frame_layout(scene);
  const Image image = render_image(scene);
  const auto in_hole = pixel_of(layout, {3.0, 3.5});  // centre of the square hole [2,4] x [2,5]
  EXPECT_EQ(image.at(in_hole.first, in_hole.second), pier_colour);
  const auto beyond = pixel_of(layout, {-0.2, 4.0});  // in the 3% margin left of the mesh
  EXPECT_EQ(image.at(beyond.first, beyond.second), land);
  const auto water = pixel_of(layout, {6.0, 7.0});  // constant field: the middle of the map
  EXPECT_EQ(image.at(water.first, water.second), colour_at(ColourMapName::viridis, 0.5));
}

TEST(Frame, DryGroundIsDrawnAsLand) {
  // Nodes at x > 2.5 m dry: the sub-triangles dry at all three corners (x >= 3 m) stay land,
  // the wet ones show the field.
  RampScene ramp;
  for (const Vec2& p : ramp.mesh.nodes) ramp.scene.wet.push_back(p.x() > 2.5 ? 0 : 1);
  const FrameLayout layout = frame_layout(ramp.scene);
  const Image image = render_image(ramp.scene);
  for (const double y : {0.4, 1.0, 1.7}) {
    const auto dry = pixel_of(layout, {3.6, y});
    EXPECT_EQ(image.at(dry.first, dry.second), land) << "y = " << y;
    const auto wet = pixel_of(layout, {1.2, y});
    expect_near(image.at(wet.first, wet.second),
                colour_at(ColourMapName::viridis, centre_of(layout, wet).x() / 4.0), 1,
                fmt::format("wet at y = {}", y));
  }
  ramp.scene.wet.pop_back();
  EXPECT_THROW(render_image(ramp.scene), InputError);  // one flag per node
}

TEST(Frame, ArrowSitsOnEverySamplePointOfAUniformFlow) {
  RampScene ramp;
  ramp.scene.u_x.assign(ramp.mesh.node_count(), 1.0);  // [m/s] along +x
  ramp.scene.u_y.assign(ramp.mesh.node_count(), 0.0);
  ramp.scene.arrow_spacing = 40.0;
  const FrameLayout layout = frame_layout(ramp.scene);
  const Image image = render_image(ramp.scene);
  const Image plain = render_image(RampScene().scene);
  // The first sample: half a spacing in from the plot's corner, at a pixel centre; the shaft
  // (1 px wide, dark ink) runs through it. Behind the arrow's tail the field is untouched.
  const int x = static_cast<int>(std::floor(layout.plot.x0 + 20.0));
  const int y = static_cast<int>(std::floor(layout.plot.y0 + 20.0));
  const Vec2 world = layout.to_world({x + 0.5, y + 0.5});
  ASSERT_TRUE(world.y() > 0.05 && world.y() < 1.95 && world.x() > 0.05);  // inside the mesh
  EXPECT_EQ(image.at(x, y), ink);
  EXPECT_EQ(image.at(x - 19, y), plain.at(x - 19, y));  // the shaft spans 0.9 * 40 = 36 px
}

TEST(Frame, ViewWindowKeepsOneScaleAndHoldsTheWindowAsked) {
  RampScene ramp;
  ramp.scene.view = ViewWindow{1.0, 2.0, 0.5, 1.5};
  const FrameLayout layout = frame_layout(ramp.scene);
  EXPECT_LE(layout.window.x_min, 1.0 + 1e-9);
  EXPECT_GE(layout.window.x_max, 2.0 - 1e-9);
  EXPECT_LE(layout.window.y_min, 0.5 + 1e-9);
  EXPECT_GE(layout.window.y_max, 1.5 - 1e-9);
  const double sx = layout.plot.width() / (layout.window.x_max - layout.window.x_min);
  const double sy = layout.plot.height() / (layout.window.y_max - layout.window.y_min);
  EXPECT_NEAR(sx, layout.pixels_per_metre, 1e-9);
  EXPECT_NEAR(sy, layout.pixels_per_metre, 1e-9);
  // Window 1 x 1 m in a wider room: the plot box is square.
  EXPECT_DOUBLE_EQ(layout.plot.width(), layout.plot.height());
}

TEST(Frame, UnwritablePathIsNamed) {
  RampScene ramp;
  const std::string path = "/nonexistent_flotsam_folder/frame.png";
  try {
    render_png(ramp.scene, path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'/nonexistent_flotsam_folder/frame.png'"));
  }
}

// A picture is written under <path>.part and renamed when whole: no .part is left, and a write
// that cannot finish (its .part cannot be created: a folder holds the name) leaves the previous
// picture as it was.
TEST(Frame, PngIsReplacedWholeOrNotAtAll) {
  RampScene ramp;
  const fs::path path = test::scratch_path("flotsam_render_frame_whole.png");
  fs::remove_all(path.string() + ".part");
  render_png(ramp.scene, path.string());
  EXPECT_FALSE(fs::exists(path.string() + ".part"));
  const auto size = fs::file_size(path);
  fs::create_directories(path.string() + ".part");
  ramp.scene.width = 240;  // a different picture
  EXPECT_THROW(render_png(ramp.scene, path.string()), InputError);
  EXPECT_EQ(fs::file_size(path), size);
  cairo_surface_t* png = cairo_image_surface_create_from_png(path.c_str());
  EXPECT_EQ(cairo_image_surface_get_width(png), 480);
  cairo_surface_destroy(png);
  fs::remove_all(path.string() + ".part");
  fs::remove(path);
}

TEST(Frame, FieldOfTheWrongLengthIsNamed) {
  RampScene ramp;
  ramp.scene.field.values.resize(7);
  try {
    render_image(ramp.scene);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("picture 'ramp', field 'f': 7 values, expected 15 (P1, one "
                                    "per vertex) or 45 (P2, one per node)"));
  }
}

TEST(Frame, TooSmallImageIsNamed) {
  RampScene ramp;
  ramp.scene.width = 64;
  ramp.scene.height = 48;
  EXPECT_THROW(render_image(ramp.scene), InputError);
}

}  // namespace
}  // namespace flotsam
