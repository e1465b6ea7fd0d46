#pragma once
// A small self-describing binary file of named arrays, for checkpoints (restart) and the states
// `flotsam render` draws. Layout (little endian, as the machine writes it):
//
//   "FLOTSAM-ARCHIVE\n" (16 bytes), uint32 version,
//   then records: uint32 name length, name bytes, uint32 element size, uint64 count, raw data.
//
// Arrays of trivially copyable values only; the reader checks every name and element size, so a
// file of another version or another program is an InputError naming the file and the record,
// never a silent misread.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "core/vec.hpp"

namespace flotsam {

/// Values stored as their bytes: trivially copyable types, and Vec2 (two doubles, no padding).
/// Plain structs whose members are such values (Eigen's fixed-size vectors are not trivially
/// copyable by the type trait, but are plain arrays of doubles) opt in by specialising
/// is_plain_struct.
template <class T>
struct is_plain_struct : std::false_type {};
template <class T>
constexpr bool is_archivable =
    std::is_trivially_copyable_v<T> || std::is_same_v<T, Vec2> || is_plain_struct<T>::value;
static_assert(sizeof(Vec2) == 2 * sizeof(double));

class ArchiveWriter {
 public:
  explicit ArchiveWriter(const std::string& path);
  /// Closes the file under a temporary name and renames it (no half-written archive is seen).
  void close();
  ~ArchiveWriter();

  template <class T>
  void write(const std::string& name, const std::vector<T>& values) {
    static_assert(is_archivable<T>);
    write_raw(name, sizeof(T), values.size(), values.data());
  }
  template <class T>
  void write_value(const std::string& name, const T& value) {
    static_assert(is_archivable<T>);
    write_raw(name, sizeof(T), 1, &value);
  }
  void write_text(const std::string& name, const std::string& text) {
    write_raw(name, 1, text.size(), text.data());
  }

 private:
  void write_raw(const std::string& name, std::uint32_t element_size, std::uint64_t count,
                 const void* data);
  std::string path_, part_path_;
  std::ofstream out_;
  bool closed_ = false;
};

class ArchiveReader {
 public:
  explicit ArchiveReader(const std::string& path);

  template <class T>
  std::vector<T> read(const std::string& name) {
    static_assert(is_archivable<T>);
    const std::uint64_t count = next_record(name, sizeof(T));
    std::vector<T> values(count);
    read_bytes(values.data(), count * sizeof(T), name);
    return values;
  }
  template <class T>
  T read_value(const std::string& name) {
    auto v = read<T>(name);
    if (v.size() != 1)
      throw_input_error("{}: record '{}' holds {} values, expected 1", path_, name, v.size());
    return v.front();
  }
  std::string read_text(const std::string& name) {
    auto bytes = read<char>(name);
    return std::string(bytes.begin(), bytes.end());
  }
  const std::string& path() const { return path_; }

 private:
  std::uint64_t next_record(const std::string& name, std::uint32_t element_size);
  void read_bytes(void* data, std::uint64_t bytes, const std::string& name);
  std::string path_;
  std::ifstream in_;
};

}  // namespace flotsam
