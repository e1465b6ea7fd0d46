#pragma once
// A small self-describing binary file of named arrays, for checkpoints (restart) and the states
// `flotsam render` draws. Layout (little endian, as the machine writes it):
//
//   "FLOTSAM-ARCHIVE\n" (16 bytes), uint32 version (3),
//   then records: uint32 name length, name bytes, uint32 element size, uint64 count, the values,
//                 uint64 checksum (of the record's bytes before it: XXH3-64 in version 3,
//                 FNV-1a in version 2; io/record_checksum.hpp),
//   then the record "end" (no values), and nothing after it.
//
// Versions: archives are written in version 3; archives of version 2 (the same layout with
// FNV-1a checksums) are read as well, any other version is refused naming it.
//
// Integrity: the reader checks every record's name, element size, length (never more than the
// bytes left in the file) and checksum, and finish() that the file ends right after "end"; a
// truncated, damaged or appended-to file, or one of another version or program, is an
// InputError naming the file and the record, never a silent misread.
//
// Determinism: an archive is a function of the values alone. Arrays of numbers, enums, Vec2,
// Mat2 and std::arrays of those hold no padding and are stored as their bytes; a struct is
// stored field by field (archive_fields below), so its padding bytes (uninitialised memory) are
// never written.
#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "core/vec.hpp"
#include "io/record_checksum.hpp"

namespace flotsam {

/// The version archives are written in (the layout above).
inline constexpr std::uint32_t archive_version = 3;

/// A struct in an archive: specialise with its data members in a fixed order,
///   template <> struct archive_fields<Foo> {
///     static constexpr auto fields = std::make_tuple(&Foo::a, &Foo::b);
///   };
/// Each member must itself be archivable. Every member that shapes the state must be listed.
template <class T>
struct archive_fields;

namespace archive_detail {

template <class T>
struct is_std_array : std::false_type {};
template <class T, std::size_t N>
struct is_std_array<std::array<T, N>> : std::true_type {};

template <class T>
concept Scalar = std::is_arithmetic_v<T> || std::is_enum_v<T>;
template <class T>
concept FixedMatrix =  // Eigen's fixed-size vectors and matrices of doubles (Vec2, Mat2)
    requires {
  typename T::Scalar;
}
&&std::is_same_v<typename T::Scalar, double> && (T::SizeAtCompileTime > 0) &&
    sizeof(T) == T::SizeAtCompileTime * sizeof(double);
template <class T>
concept Described = requires {
  archive_fields<T>::fields;
};

/// Values stored as their bytes: no padding anywhere in them.
template <class T>
constexpr bool is_dense() {
  if constexpr (Scalar<T> || FixedMatrix<T>)
    return true;
  else if constexpr (is_std_array<T>::value)
    return is_dense<typename T::value_type>() &&
           sizeof(T) == std::tuple_size_v<T> * sizeof(typename T::value_type);
  else
    return false;
}

template <class T>
constexpr std::size_t packed_size() {
  if constexpr (is_dense<T>()) {
    return sizeof(T);
  } else if constexpr (is_std_array<T>::value) {
    return std::tuple_size_v<T> * packed_size<typename T::value_type>();
  } else {
    static_assert(Described<T>, "not archivable: specialise archive_fields<T>");
    return std::apply(
        [](auto... member) {
          return (packed_size<std::remove_cvref_t<decltype(std::declval<T>().*member)>>() + ... +
                  0);
        },
        archive_fields<T>::fields);
  }
}

template <class T>
void pack(const T& value, char*& out) {
  if constexpr (is_dense<T>()) {
    std::memcpy(out, &value, sizeof(T));
    out += sizeof(T);
  } else if constexpr (is_std_array<T>::value) {
    for (const auto& item : value) pack(item, out);
  } else {
    std::apply([&](auto... member) { (pack(value.*member, out), ...); }, archive_fields<T>::fields);
  }
}

template <class T>
void unpack(T& value, const char*& in) {
  if constexpr (FixedMatrix<T>) {
    std::memcpy(value.data(), in, sizeof(T));
    in += sizeof(T);
  } else if constexpr (is_dense<T>()) {
    std::memcpy(static_cast<void*>(&value), in, sizeof(T));
    in += sizeof(T);
  } else if constexpr (is_std_array<T>::value) {
    for (auto& item : value) unpack(item, in);
  } else {
    std::apply([&](auto... member) { (unpack(value.*member, in), ...); },
               archive_fields<T>::fields);
  }
}

}  // namespace archive_detail

class ArchiveWriter {
 public:
  explicit ArchiveWriter(const std::string& path);
  /// Ends the archive, closes it under a temporary name (<path>.part) and renames it (no
  /// half-written archive is seen). A failed write (disk full) removes the temporary file and
  /// is an InputError naming the file.
  void close();
  ~ArchiveWriter();
  ArchiveWriter(const ArchiveWriter&) = delete;
  ArchiveWriter& operator=(const ArchiveWriter&) = delete;

  template <class T>
  void write(const std::string& name, const std::vector<T>& values) {
    if constexpr (archive_detail::is_dense<T>()) {
      write_raw(name, sizeof(T), values.size(), values.data());
    } else {
      constexpr std::size_t size = archive_detail::packed_size<T>();
      std::vector<char> bytes(values.size() * size);
      char* out = bytes.data();
      for (const T& value : values) archive_detail::pack(value, out);
      write_raw(name, size, values.size(), bytes.data());
    }
  }
  template <class T>
  void write_value(const std::string& name, const T& value) {
    write(name, std::vector<T>{value});
  }
  void write_text(const std::string& name, const std::string& text) {
    write_raw(name, 1, text.size(), text.data());
  }

 private:
  void write_raw(const std::string& name, std::uint32_t element_size, std::uint64_t count,
                 const void* data);
  void abandon();  // closes and removes the temporary file
  std::string path_, part_path_;
  std::ofstream out_;
  std::unique_ptr<RecordChecksum> checksum_;  // of the record being written
  bool closed_ = false;
};

class ArchiveReader {
 public:
  explicit ArchiveReader(const std::string& path);

  template <class T>
  std::vector<T> read(const std::string& name) {
    constexpr std::size_t size = archive_detail::packed_size<T>();
    const std::uint64_t count = next_record(name, size);
    std::vector<T> values(count);
    if constexpr (archive_detail::is_dense<T>()) {
      read_bytes(values.data(), count * size, name);
    } else {
      std::vector<char> bytes(count * size);
      read_bytes(bytes.data(), bytes.size(), name);
      const char* in = bytes.data();
      for (T& value : values) archive_detail::unpack(value, in);
    }
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
  /// Whether the next record is called `name` (nothing is read): for a record that files of
  /// older versions do not have.
  bool next_is(const std::string& name);
  /// Reads the closing record and checks that nothing follows it: call after the last record.
  void finish();
  const std::string& path() const { return path_; }

 private:
  std::uint64_t next_record(const std::string& name, std::uint32_t element_size);
  /// The record's values, then its checksum, which must match.
  void read_bytes(void* data, std::uint64_t bytes, const std::string& name);
  std::string path_;
  std::ifstream in_;
  std::uint64_t file_size_ = 0;               // [bytes]
  std::unique_ptr<RecordChecksum> checksum_;  // of the record being read (the file's version)
};

}  // namespace flotsam
