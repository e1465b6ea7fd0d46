// Geodata files named in a case (docs/case-format.md "Paths"): a path relative to the case
// file's folder, and a vector layer given as a path or as {file, layer}.
#include "core/error.hpp"
#include "io/case_sections.hpp"

namespace flotsam {

VectorLayer read_case_layer(const YamlValue& value, const std::filesystem::path& case_folder,
                            const std::string& value_field, const std::string& label_field) {
  std::string file, layer;
  if (value.is_map()) {
    const YamlMap m = value.map();
    file = m.get("file", "the vector file (GeoPackage, Shapefile, GeoJSON)")
               .input_path(case_folder.string());
    layer = m.text("layer", "");
  } else {
    file = value.input_path(case_folder.string());
  }
  return read_vector_layer(file, layer, value.origin(), value_field, label_field);
}

}  // namespace flotsam
