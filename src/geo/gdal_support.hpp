#pragma once
// What the GDAL readers and writers of src/geo share: the drivers registered once, datasets
// closed by RAII, a coordinate system as WKT text.
#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <memory>
#include <string>

#include "core/error.hpp"

namespace flotsam::gdal {

/// GDAL's own messages go to the log at debug level, not to stderr: flotsam's errors name the
/// file and the key and quote GDAL's reason (CPLGetLastErrorMsg, which the handler leaves set),
/// so that a bare "ERROR 1: ..." naming no file never comes before them.
inline void log_gdal_message(CPLErr level, CPLErrorNum number, const char* message) {
  spdlog::debug("GDAL {} {}: {}", level >= CE_Failure ? "error" : "warning", number, message);
}

inline void register_drivers() {
  static const bool registered = [] {
    GDALAllRegister();
    CPLSetErrorHandler(log_gdal_message);
    return true;
  }();
  (void)registered;
}

struct DatasetCloser {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

/// Opens `path` read-only as a raster (GDAL_OF_RASTER) or vector (GDAL_OF_VECTOR) dataset, or
/// an InputError naming `origin` and the file: "the <kind> '<path>' does not exist", "'<path>'
/// is not a <kind> GDAL can read (<GDAL's reason>)".
inline Dataset open_dataset(const std::string& path, unsigned int flags, const std::string& origin,
                            const char* kind) {
  register_drivers();
  if (!std::filesystem::exists(path))
    throw_input_error("{}: the {} '{}' does not exist", origin, kind, path);
  CPLPushErrorHandler(CPLQuietErrorHandler);
  Dataset d(GDALDataset::Open(path.c_str(), flags | GDAL_OF_READONLY));
  CPLPopErrorHandler();
  if (!d)
    throw_input_error("{}: '{}' is not a {} GDAL can read ({})", origin, path, kind,
                      CPLGetLastErrorMsg());
  return d;
}

/// GeoPackage writes layers without a coordinate system as "Undefined geographic SRS" or
/// "Undefined Cartesian SRS": those count as none.
inline bool is_undefined(const OGRSpatialReference& srs) {
  const char* name = srs.GetName();
  return name && std::string(name).rfind("Undefined", 0) == 0;
}

inline std::string wkt_of(const OGRSpatialReference& srs) {
  char* wkt = nullptr;
  srs.exportToWkt(&wkt);
  std::string text = wkt ? wkt : "";
  CPLFree(wkt);
  return text;
}

}  // namespace flotsam::gdal
