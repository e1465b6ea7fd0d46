#pragma once
// The output folder policy (docs/output-format.md): a run never mixes its files with an older
// run's, and --overwrite never deletes anything flotsam did not make.
//
//  * A missing folder is created (with its parents); an empty one (or one holding only the
//    marker below) is used as is.
//  * A non-empty folder is an error unless overwrite is set.
//  * With overwrite, a non-empty folder is emptied only if it holds the marker file
//    `.flotsam-output` that this function leaves in every folder it prepares; otherwise it is an
//    error (it was not made by flotsam: a typo such as --output src must not wipe the sources).
//  * Always refused: "/", the home folder, the working directory, any folder containing one of
//    those, a folder containing the case file or any file the case reads (mesh file, rasters,
//    vector files), and a path that exists but is not a folder.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace flotsam {

/// Name of the marker file left in every output folder.
inline constexpr const char* output_marker = ".flotsam-output";

/// A file the run reads: the key that names it ("mesh.file") and its path.
using ProtectedInput = std::pair<std::string, std::string>;

/// Applies the policy above and returns the folder's absolute path. `case_file` ("" when the
/// case was built in code) and `inputs` are protected from deletion. Throws InputError with the
/// reason and the way out. `shared_folder` (or ""): runs sharing files (io/shared_file.hpp) get
/// the marker as a link to one copy there (one file fewer to create per run).
std::filesystem::path prepare_output_directory(const std::string& directory, bool overwrite,
                                               const std::string& case_file = "",
                                               const std::vector<ProtectedInput>& inputs = {},
                                               const std::filesystem::path& shared_folder = {});

}  // namespace flotsam
