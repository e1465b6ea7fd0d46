#pragma once
// The `ensemble:` section of a case file (docs/case-format.md, "ensemble"): how many members,
// which inputs vary and how, an optional sweep of one input over a list of values, and the
// blocking definition (docs/model.md, "Blocking"). The section sits at the top level of the case
// file, written as a block; `split_ensemble_text` (io/case_file.hpp) cuts it out, leaving the
// case text with the same line numbers, so that messages about either part name the right line.
#include <string>
#include <vector>

#include "io/case_file.hpp"

namespace flotsam {

/// An input an ensemble may vary, each applied to the member's case file (member_case.hpp).
enum class EnsembleInput {
  log_length,           // L [m] of every release (bodies.release[k].length)
  log_length_over_gap,  // L / w [-], w the widest gap of bridge_1 (channel meshes)
  log_diameter,         // l [m] of every release (bodies.release[k].width)
  log_density,          // rho_p [kg m^-3] of every release
  release_rate,         // [1/min] of every release given with a rate
  discharge_scale,      // [-] multiplies every discharge boundary's Q (number or table)
  restitution,          // e [-] (bodies.contact.restitution)
  contact_friction,     // mu_c [-] (bodies.contact.friction)
  bed_friction,         // mu_bed [-] (bodies.physics.bed_friction)
  release_shift_x,      // [m] added to the x of every release line's or zone's points
  release_shift_y,      // [m] added to the y of every release line's or zone's points
  count
};

/// The key of an input in the case file ("log_length"), and its unit for tables ("m").
const char* input_key(EnsembleInput input);
const char* input_unit(EnsembleInput input);

/// How one input is drawn for each member.
struct Distribution {
  enum class Kind { fixed, uniform, normal, choice } kind = Kind::fixed;
  double a = 0.0;              // fixed: the value; uniform: lower end; normal: mean
  double b = 0.0;              // uniform: upper end; normal: standard deviation
  std::vector<double> values;  // choice: drawn with equal probability
};

struct VariedInput {
  EnsembleInput input = EnsembleInput::log_length;
  Distribution distribution;
};

/// When a jam blocks a gap (docs/model.md, "Blocking").
struct BlockingCriterion {
  double fraction = 0.5;         // [-] share of the gap's width covered by jams at its bridge
  double duration = 60.0;        // [s] held at least this long without a break
  double sample_interval = 5.0;  // [s] statistics are taken at the first step past each multiple
};

struct EnsembleConfig {
  int members = 20;               // per sweep value (the whole ensemble without a sweep)
  unsigned long seed = 1;         // the ensemble's seed: member j's draws follow from (seed, j)
  std::vector<VariedInput> vary;  // in the order of EnsembleInput
  bool has_sweep = false;         // a sweep of one input over `sweep_values`
  EnsembleInput sweep_input = EnsembleInput::log_length;
  std::vector<double> sweep_values;  // in the input's unit, in the order given
  BlockingCriterion blocking;
  int line = 0;  // the line of the key `ensemble` in the case file

  /// Members in all: members per value times the sweep's values.
  int total_members() const {
    return members * (has_sweep ? static_cast<int>(sweep_values.size()) : 1);
  }
  int sweep_value_count() const { return has_sweep ? static_cast<int>(sweep_values.size()) : 1; }
};

/// Reads and checks the ensemble section (`ensemble_text` of split_ensemble_text); errors are
/// InputError "file:line: ensemble.key: what was expected". No section is an error telling what
/// to add.
EnsembleConfig parse_ensemble(const std::string& ensemble_text, const std::string& file_name);

}  // namespace flotsam
