#pragma once
// The bodies: rigid rectangles in plan view (spec 2), stored as a structure of arrays so that a
// loop over 100,000 bodies touches only the arrays it needs. Bodies are reached by index; `id`
// is the user's name for a body and survives removal of others.
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/vec.hpp"

namespace flotsam {

enum class Shape : std::uint8_t { log, box };
enum class BodyState : std::uint8_t { floating, grounded, gone };

/// What the user gives for one body (spec 2); everything else is derived.
struct BodySpec {
  Shape shape = Shape::log;
  double length = 20.0;           // L [m], long side
  double width = 1.0;             // l [m], short side (a log's diameter)
  double height = 1.0;            // b [m], vertical size (= l for a log)
  double density = 600.0;         // rho_p [kg m^-3]
  Vec2 position = Vec2::Zero();   // x_G [m]
  double angle = 0.0;             // theta [rad], long axis from the x axis
  Vec2 velocity = Vec2::Zero();   // u_p [m/s]
  double angular_velocity = 0.0;  // omega [rad/s]
  long id = -1;                   // user's id; -1: the next free one
  bool anchored = false;          // held in place (a post, a pile, a stuck jam): feels the flow and
                                  // acts on it and on other bodies, but does not move
};

struct BodySet {
  double water_density = 1000.0;  // rho [kg m^-3], for the draft

  // Geometry and mass (cold: set once).
  std::vector<Shape> shape;
  std::vector<double> length;   // L [m]
  std::vector<double> width;    // l [m]
  std::vector<double> height;   // b [m]
  std::vector<double> density;  // rho_p [kg m^-3]
  std::vector<double> mass;     // m_p [kg]
  std::vector<double> inertia;  // I_p [kg m^2], yaw, about G
  std::vector<double> draft;    // d [m], floating draft (the full height if it cannot float)
  std::vector<long> id;
  long next_id = 0;  // the id the next body without one gets

  // Derived shape factors for the drag laws (cold: set once by add()).
  std::vector<double> equal_volume_diameter;  // d_v [m], sphere of the body's volume (P-18)
  std::vector<double> sphericity;             // Theta [-], sphere surface / body surface (P-18)
  std::vector<double> ganser_K2;              // K2 [-], Newton-regime shape factor (P-18)
  std::vector<double> ganser_K1_term;         // 2 / (3 sqrt(Theta)) [-], the constant of K1
  std::vector<double> pressure_reach;         // 0.1 L (1 - exp(3 (1 - L/l))) [m], (M-7) at 0

  // State (hot).
  std::vector<double> wetted_height;     // d_w [m]: the height the water acts on in (M-6) and
                                         // (M-8), the draft, or its jam's thickness (M-J1)
  std::vector<Vec2> position;            // x_G [m]
  std::vector<double> angle;             // theta [rad]
  std::vector<Vec2> velocity;            // u_p [m/s]
  std::vector<double> angular_velocity;  // omega [rad/s]
  std::vector<BodyState> state;
  std::vector<std::uint8_t> anchored;  // 1: does not move (BodySpec::anchored)
  std::vector<int> element_hint;       // last element found for G (point location), -1 unknown
  std::vector<double> step_size;       // RKF45 step proposed for the next sub-step [s], 0: unknown

  // Forces at the start of each body's last accepted sub-step (output, two-way coupling).
  std::vector<Vec2> drag_force;          // F_drag [N] (M-6), summed over drag points
  std::vector<Vec2> bed_force;           // F_bed + F_slope [N] (spec 3.4), zero when floating
  std::vector<Vec2> reaction_force;      // F_x = F_drag + C_a m_f (Du_f/Dt - du_p/dt) [N] (spec 5)
  std::vector<double> torque;            // T_drag + T_rot + T_bed [N m] (M-5)
  std::vector<double> drag_rate;         // K [kg/s]: F_drag = K (u_f - u_p) (M-6)
  std::vector<double> added_mass;        // C_a m_f [kg] (M-5)
  std::vector<Vec2> fluid_acceleration;  // Du_f/Dt at G [m/s^2]
  std::vector<Vec2> flow_velocity;       // u_f at G [m/s]

  // Two-way coupling (spec 5; model.md "Two-way coupling").
  std::vector<Vec2> mean_acceleration;  // (u_p(t1) - u_p(t0)) / (t1 - t0), contacts included,
                                        // over the last coupling step [m/s^2]
  std::vector<Vec2> water_force;        // the force the water exchanged with the body over the last
                                        // flow step, as the flow applied it [N] (on the body)

  long outflow_count = 0;  // bodies that left through an outflow boundary (spec 5)

  int size() const { return static_cast<int>(position.size()); }

  /// Appends a body with its mass, inertia and draft (spec 2); returns its index.
  int add(const BodySpec& spec);

  /// Unit vector along the long axis, and the body's half extents (L/2, l/2) [m].
  Vec2 axis(int i) const { return {std::cos(angle[i]), std::sin(angle[i])}; }
  Vec2 half_extents(int i) const { return {0.5 * length[i], 0.5 * width[i]}; }

  /// Volume under water at immersion `depth` (clamped to [0, b]) [m^3] (spec 2).
  double submerged_volume(int i, double depth) const;

  /// Calls f(name, array) for every per-body array, in a fixed order: a checkpoint keeps them
  /// all, so that a restarted run continues bit for bit. A new array must be listed here.
  template <class F>
  void for_each_array(F&& f) {
    visit_arrays(*this, f);
  }
  template <class F>
  void for_each_array(F&& f) const {
    visit_arrays(*this, f);
  }

 private:
  template <class Self, class F>
  static void visit_arrays(Self& b, F& f) {
    f("shape", b.shape), f("length", b.length), f("width", b.width), f("height", b.height);
    f("density", b.density), f("mass", b.mass), f("inertia", b.inertia), f("draft", b.draft);
    f("id", b.id), f("equal_volume_diameter", b.equal_volume_diameter);
    f("sphericity", b.sphericity), f("ganser_K2", b.ganser_K2);
    f("ganser_K1_term", b.ganser_K1_term), f("pressure_reach", b.pressure_reach);
    f("wetted_height", b.wetted_height);
    f("position", b.position), f("angle", b.angle), f("velocity", b.velocity);
    f("angular_velocity", b.angular_velocity), f("state", b.state), f("anchored", b.anchored);
    f("element_hint", b.element_hint), f("step_size", b.step_size);
    f("drag_force", b.drag_force), f("bed_force", b.bed_force);
    f("reaction_force", b.reaction_force), f("torque", b.torque);
    f("drag_rate", b.drag_rate), f("added_mass", b.added_mass);
    f("fluid_acceleration", b.fluid_acceleration), f("flow_velocity", b.flow_velocity);
    f("mean_acceleration", b.mean_acceleration);
    f("water_force", b.water_force);
  }
};

/// Submerged cross-section of a log of diameter l at immersion depth d (circle segment) [m^2].
double log_segment_area(double diameter, double depth);

/// Floating draft from Archimedes, rho V_sub(d) = m_p (spec 2) [m]. A body denser than water
/// gets its full height.
double floating_draft(Shape shape, double width, double height, double density,
                      double water_density);

/// Surface area of the whole body (a log's mantle and two end discs, a box's six faces) [m^2].
double body_surface(Shape shape, double length, double width, double height);

}  // namespace flotsam
