#include "io/vtk_xml.hpp"

#include <fmt/format.h>

#include <bit>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "core/error.hpp"

namespace flotsam {

// The files declare byte_order="LittleEndian" and the blocks are the host's bytes.
static_assert(std::endian::native == std::endian::little,
              "VTK output assumes a little-endian host");

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string AppendedData::add_block(std::string_view type, std::string_view name, int components,
                                    std::size_t tuples, const void* data, std::size_t size) {
  const std::uint64_t offset = bytes_.size();
  const std::uint64_t header = size;
  const auto* header_bytes = reinterpret_cast<const char*>(&header);
  bytes_.insert(bytes_.end(), header_bytes, header_bytes + sizeof header);
  const auto* data_bytes = static_cast<const char*>(data);
  bytes_.insert(bytes_.end(), data_bytes, data_bytes + size);
  std::string tag = fmt::format("<DataArray type=\"{}\"", type);
  if (!name.empty()) tag += fmt::format(" Name=\"{}\"", xml_escape(name));
  if (components != 1) tag += fmt::format(" NumberOfComponents=\"{}\"", components);
  tag += fmt::format(" NumberOfTuples=\"{}\" format=\"appended\" offset=\"{}\"/>", tuples, offset);
  return tag;
}

std::string AppendedData::add_float64(std::string_view name, int components,
                                      std::span<const double> values) {
  return add_block("Float64", name, components, values.size() / components, values.data(),
                   values.size_bytes());
}

std::string AppendedData::add_int64(std::string_view name, std::span<const std::int64_t> values) {
  return add_block("Int64", name, 1, values.size(), values.data(), values.size_bytes());
}

std::string AppendedData::add_int32(std::string_view name, std::span<const std::int32_t> values) {
  return add_block("Int32", name, 1, values.size(), values.data(), values.size_bytes());
}

std::string AppendedData::add_uint8(std::string_view name, std::span<const std::uint8_t> values) {
  return add_block("UInt8", name, 1, values.size(), values.data(), values.size_bytes());
}

std::string AppendedData::add_vec2_as_3d(std::string_view name, std::span<const Vec2> values) {
  std::vector<double> xyz;
  xyz.reserve(3 * values.size());
  for (const Vec2& v : values) xyz.insert(xyz.end(), {v.x(), v.y(), 0.0});
  return add_float64(name, 3, xyz);
}

std::string AppendedData::add_strings(std::string_view name, std::span<const std::string> values) {
  std::vector<char> chars;
  for (const std::string& s : values) {
    chars.insert(chars.end(), s.begin(), s.end());
    chars.push_back('\0');
  }
  return add_block("String", name, 1, values.size(), chars.data(), chars.size());
}

std::string AppendedData::field_data_time(double time) {
  const double value[] = {time};
  return "<FieldData>" + add_float64("TimeValue", 1, value) + "</FieldData>\n";
}

namespace {

std::filesystem::path part_path(const std::string& path) {
  return std::filesystem::path(path + ".part");
}

// A failed write (a full disk) leaves no .part file behind.
void finish(std::ofstream& out, const std::string& path) {
  out.close();
  std::error_code error;
  if (!out) {
    const int code = errno;
    std::filesystem::remove(part_path(path), error);
    throw_input_error("cannot write '{}': {}", path, std::strerror(code));
  }
  std::filesystem::rename(part_path(path), path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(part_path(path), ignored);
    throw_input_error("cannot write '{}': {}", path, error.message());
  }
}

std::ofstream open_part(const std::string& path) {
  std::ofstream out(part_path(path), std::ios::binary | std::ios::trunc);
  if (!out) throw_input_error("cannot write '{}': {}", path, std::strerror(errno));
  return out;
}

}  // namespace

void write_file_atomically(const std::string& path, std::string_view text) {
  std::ofstream out = open_part(path);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  finish(out, path);
}

void write_vtk_xml_file(const std::string& path, std::string_view file_type, std::string_view body,
                        const AppendedData& data) {
  std::ofstream out = open_part(path);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"" << file_type
      << "\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << body << "<AppendedData encoding=\"raw\">\n_";
  out.write(data.bytes().data(), static_cast<std::streamsize>(data.bytes().size()));
  out << "\n</AppendedData>\n</VTKFile>\n";
  finish(out, path);
}

}  // namespace flotsam
