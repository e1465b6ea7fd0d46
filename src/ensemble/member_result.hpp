#pragma once
// What one member of an ensemble leaves: its inputs, whether it ran, and its statistics (per
// bridge, per gap, per body; docs/model.md "Blocking"). A member's folder holds it as
// member.txt, written last (so a member with a member.txt is complete, and one without is run
// again on resume); MPI ranks send the same text to rank 0.
//
// The text is one record per line, numbers in their shortest exact form, so that reading it
// back gives the same doubles bit for bit (the ensemble's summary does not depend on whether a
// member was run now, read back from its folder, or received from another rank).
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "ensemble/member_case.hpp"

namespace flotsam {

/// One bridge line in one member (docs/model.md "Blocking").
struct BridgeOutcome {
  bool blocked = false;  // at least one of its gaps blocked
  double blocking_time = std::numeric_limits<double>::quiet_NaN();  // [s] earliest gap's onset
  int blocking_bodies = 0;    // bodies in the jams at the bridge when the blocking was confirmed
  int largest_jam = 0;        // most bodies in one jam at the bridge, over the samples
  double max_blockage = 0.0;  // [-] largest blockage ratio of the bridge over the samples
  double max_rise = std::numeric_limits<double>::quiet_NaN();  // [m] largest backwater rise
                                                               // (NaN: no reference flow)
  double max_opening_closed = 0.0;  // [-] largest closed share of its openings' area (samples)
};

struct GapOutcome {
  bool blocked = false;
  double blocking_time = std::numeric_limits<double>::quiet_NaN();  // [s] start of the blocking
  double max_cover = 0.0;           // [-] largest covered share of the gap over the samples
  double max_opening_closed = 0.0;  // [-] largest closed share of the gap's opening area
};

enum class BodyFate : int { floating = 0, trapped = 1, stranded = 2, left = 3 };

struct BodyOutcome {
  long id = 0;
  Vec2 start = Vec2::Zero();  // [m] G when the body first appeared (end of its release step)
  Vec2 end = Vec2::Zero();    // [m] G at the end (where it left, for a body gone)
  BodyFate fate = BodyFate::floating;
  bool passed = false;  // beyond the last bridge and not in a jam (JamStatistics::passed)
  double travel() const { return (end - start).norm(); }  // [m] straight-line distance
};

struct MemberResult {
  MemberInputs inputs;
  bool failed = false;
  std::string message;  // why it failed (one line)
  int released = 0, passed = 0, left = 0, trapped = 0, stranded = 0, floating = 0;
  std::vector<BridgeOutcome> bridges;         // per JamGeometry::bridges
  std::vector<std::vector<GapOutcome>> gaps;  // per bridge, per gap
  std::vector<BodyOutcome> bodies;
  double wall_seconds = 0.0;  // [s] the member's run (not in the summary)
  double step_seconds = 0.0;  // [s] of which in its steps (flow, bodies with their contacts,
                              // reaction, diagnostics; not the outputs they write) and in the
                              // blocking monitor's samples; the rest is set-up and output. Not
                              // in member.txt.
};

/// The text form, and back; a malformed text is std::invalid_argument (a half-written file).
std::string serialize_member(const MemberResult& result);
MemberResult parse_member(const std::string& text);

/// Writes `<folder>/member.txt` through a temporary file and a rename (all or nothing).
void write_member_result(const std::filesystem::path& folder, const MemberResult& result);
/// The result in `<folder>/member.txt`, or nothing when it is missing or incomplete.
std::optional<MemberResult> read_member_result(const std::filesystem::path& folder);

}  // namespace flotsam
