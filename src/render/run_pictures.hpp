#pragma once
// The pictures of a finished (or running) run, drawn from the files it left (io/run_state.hpp):
//
//   water_surface.png    the water surface elevation eta at the last output (paper Fig. 15)
//   velocity.png         the velocity magnitude through the bridges, with arrows (Fig. 16)
//   bodies.png           the bodies among the piers, coloured by state (Fig. 17)
//   frames/frame_NNNNNN.png   |u| and the bodies at every output, one colour scale for all
//   movie.mp4            the frames as a video, when ffmpeg is installed
//
// Figures 16 and 17 zoom on the piers (the boundary groups named pier_*) when the mesh has any.
#include <functional>
#include <string>
#include <vector>

namespace flotsam {

struct PictureOptions {
  int width = 1600;    // [px]
  int height = 600;    // [px]
  bool frames = true;  // one frame per output time
  bool movie = true;   // an MP4 of the frames, when ffmpeg is on the PATH
};

/// Draws the pictures of the run in `run_directory` into that folder; returns the files
/// written. `report` (optional) is told about each file as it is written.
std::vector<std::string> render_run(const std::string& run_directory, const PictureOptions& options,
                                    const std::function<void(const std::string&)>& report = {});

}  // namespace flotsam
