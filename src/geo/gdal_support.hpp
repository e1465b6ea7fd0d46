#pragma once
// What the GDAL readers and writers of src/geo share: the drivers registered once, datasets
// closed by RAII, a coordinate system as WKT text.
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <memory>
#include <string>

namespace flotsam::gdal {

inline void register_drivers() {
  static const bool registered = [] {
    GDALAllRegister();
    return true;
  }();
  (void)registered;
}

struct DatasetCloser {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

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
