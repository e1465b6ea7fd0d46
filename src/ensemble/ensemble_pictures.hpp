#pragma once
// The pictures of an ensemble (Cairo, in the style of `flotsam render`), into its folder:
//
//   blocking_probability.png   the blocking probability of each bridge against the swept input,
//                              with its 95% Wilson interval as bars (one point without a sweep)
//   jam_size.png               histogram of the largest jam per member [bodies]
//   backwater_rise.png         histogram of the largest backwater rise per member [m] (when the
//                              members have a reference flow: two-way with output.backwater)
//   stopping_points.png        where the bodies stopped (trapped or stranded) across all members,
//                              as a density over the mesh, with the piers and banks drawn
#include <string>
#include <vector>

#include "ensemble/ensemble_config.hpp"
#include "ensemble/ensemble_statistics.hpp"
#include "ensemble/member_result.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

/// Draws the pictures above into `directory`; returns the files written.
std::vector<std::string> draw_ensemble_pictures(const std::string& directory,
                                                const std::vector<MemberResult>& results,
                                                const EnsembleStatistics& statistics,
                                                const EnsembleConfig& config, const Mesh& mesh);

}  // namespace flotsam
