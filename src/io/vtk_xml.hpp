#pragma once
// The XML machinery shared by flotsam's VTK XML files (.vtu, .vtp): arrays in one binary APPENDED
// block, raw encoding, UInt64 block headers, little endian (docs/output-format.md).
//
// Layout of a file:
//
//   <?xml version="1.0"?>
//   <VTKFile type="..." version="1.0" byte_order="LittleEndian" header_type="UInt64">
//     ... <DataArray type="Float64" Name="h" format="appended" offset="K"/> ...
//     <AppendedData encoding="raw">
//   _[n0: UInt64][n0 bytes][n1: UInt64][n1 bytes]...
//     </AppendedData>
//   </VTKFile>
//
// where each offset K counts bytes from the one after '_' to the array's UInt64 size header.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec.hpp"

namespace flotsam {

/// The arrays of one VTK XML file, collected in order: each add_* call copies the values into the
/// appended block and returns the <DataArray .../> tag that refers to them.
class AppendedData {
 public:
  std::string add_float64(std::string_view name, int components, std::span<const double> values);
  std::string add_int64(std::string_view name, std::span<const std::int64_t> values);
  std::string add_int32(std::string_view name, std::span<const std::int32_t> values);
  std::string add_uint8(std::string_view name, std::span<const std::uint8_t> values);

  /// 2D vectors as 3-component Float64 tuples with z = 0 (what ParaView's glyphs expect).
  std::string add_vec2_as_3d(std::string_view name, std::span<const Vec2> values);

  /// Strings, each ended by a NUL byte (VTK's layout of a vtkStringArray).
  std::string add_strings(std::string_view name, std::span<const std::string> values);

  /// The "TimeValue" FieldData block that ParaView reads as the dataset's time [s].
  std::string field_data_time(double time);

  /// The bytes after '_': every block with its UInt64 size header.
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  std::string add_block(std::string_view type, std::string_view name, int components,
                        std::size_t tuples, const void* data, std::size_t size);
  std::vector<char> bytes_;
};

/// Writes `<VTKFile type=file_type ...>`, the XML `body`, the appended block and the closing tag
/// to path. The file is written beside under a temporary name and renamed at the end, so a
/// reader (ParaView watching the folder, an interrupted run) never sees half a file. Throws
/// InputError naming the path when it cannot be written.
void write_vtk_xml_file(const std::string& path, std::string_view file_type, std::string_view body,
                        const AppendedData& data);

/// Writes `text` to path through a temporary file and a rename (see write_vtk_xml_file).
void write_file_atomically(const std::string& path, std::string_view text);

/// `text` with XML's five special characters escaped, for attribute values.
std::string xml_escape(std::string_view text);

}  // namespace flotsam
