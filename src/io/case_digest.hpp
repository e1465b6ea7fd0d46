#pragma once
// What a restart checks (docs/output-format.md "Restarting a run"): every value of the case
// file, as settings "key path = canonical value", plus the checksum of every file the case reads.
// A checkpoint stores the settings of the run that wrote it; a restart compares them with the
// case it is given and names each key that changed.
//
// Three kinds of keys:
//   free     time.end, output.directory, output.overwrite: a restart may always change them
//            (a later end time is what a restart is for; the folder is given on the command line)
//   output   output.interval, output.probe_interval, output.rasters, output.wet_depth: what is
//            written, not what is computed; changed only with --accept-output-changes
//   run      everything else (physics, numerics, boundaries, bodies, releases and their seeds,
//            the mesh, the name, the probes, backwater): never, the result would belong to no
//            case
// A key given with its default value counts as a change from a key left out.
#include <string>
#include <string_view>
#include <vector>

#include "io/case.hpp"

namespace YAML {
class Node;
}

namespace flotsam {

enum class SettingKind { free, output, run };
SettingKind setting_kind(std::string_view key);

/// The suffix of the setting that holds an input file's checksum: "bed.raster (file contents)".
inline constexpr std::string_view file_contents_suffix = " (file contents)";

/// Every value under `root`, in document order (numbers in their shortest exact form), then for
/// each of `input_files` its checksum; free keys are left out.
std::vector<CaseSetting> case_settings(const YAML::Node& root,
                                       const std::vector<InputFile>& input_files);

/// One line "key<TAB>value" per setting (tabs, newlines and backslashes escaped), and back.
std::string format_settings(const std::vector<CaseSetting>& settings);
std::vector<CaseSetting> parse_settings(const std::string& text);

/// A key whose value differs: `before` or `after` is empty when the key was added or removed.
struct SettingChange {
  std::string key;
  std::string before, after;
  SettingKind kind = SettingKind::run;
};
std::vector<SettingChange> compare_settings(const std::vector<CaseSetting>& before,
                                            const std::vector<CaseSetting>& after);

/// "flow.viscosity: 0.01 then, 0.02 now" per change, one per line, at most `shown` of them.
std::string describe_changes(const std::vector<SettingChange>& changes, std::size_t shown = 8);

}  // namespace flotsam
