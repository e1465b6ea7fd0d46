#pragma once
// Case files: YAML in, a checked Case out (docs/case-format.md lists every key with its unit,
// default and range). Bad input is an InputError "file:line: key.path: what was expected".
#include <string>
#include <vector>

#include "io/case.hpp"

namespace flotsam {

/// The text of the case file at `path`: an InputError naming it when it cannot be opened or is
/// not a file (a named pipe, a device).
std::string read_case_text(const std::string& path);

/// Reads and checks the case file at `path`. Relative paths inside it (mesh.file) are resolved
/// against the case file's folder.
Case read_case(const std::string& path);

/// A case file's text cut in two with the line numbers kept: `case_text` has the ensemble
/// section's lines emptied, `ensemble_text` has every other line emptied.
struct SplitCaseText {
  std::string case_text;
  std::string ensemble_text;  // blank lines only when the file has no top-level `ensemble:`
};
SplitCaseText split_ensemble_text(const std::string& text);

/// Parses the text of a case file (its `ensemble:` section, flotsam ensemble's, left aside
/// with a word in the log); `file_name` is used in messages, for the default name (its
/// stem) and to resolve relative paths (its folder).
Case parse_case(const std::string& text, const std::string& file_name);

/// Checks that the case's boundary conditions and the mesh's boundary groups match one to one:
/// a condition on a group the mesh does not have, or a mesh group without a condition, is an
/// InputError naming the case file, the group, and the mesh's groups.
void check_case_against_mesh(const Case& c, const std::vector<std::string>& mesh_groups);

}  // namespace flotsam
