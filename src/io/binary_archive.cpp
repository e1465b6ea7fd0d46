#include "io/binary_archive.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "io/checksum.hpp"

namespace flotsam {
namespace {
constexpr char magic[17] = "FLOTSAM-ARCHIVE\n";
constexpr std::uint32_t longest_name = 1024;  // [bytes] of a record's name
constexpr const char* end_record = "end";     // closes every archive
}  // namespace

std::string Checksum::hex() const {
  return fmt::format("{:016x}", hash_);
}

std::string file_checksum(const std::string& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_input_error("{}: cannot read '{}'", what, path);
  Checksum sum;
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    sum.add(buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw_input_error("{}: cannot read '{}'", what, path);
  return sum.hex();
}

ArchiveWriter::ArchiveWriter(const std::string& path)
    : path_(path),
      part_path_(path + ".part"),
      out_(part_path_, std::ios::binary),
      checksum_(record_checksum_for(archive_version)) {
  if (!out_) {
    abandon();
    throw_input_error("cannot write '{}'", path);
  }
  out_.write(magic, 16);
  out_.write(reinterpret_cast<const char*>(&archive_version), sizeof archive_version);
}

void ArchiveWriter::write_raw(const std::string& name, std::uint32_t element_size,
                              std::uint64_t count, const void* data) {
  RecordChecksum& sum = *checksum_;
  sum.reset();
  auto put = [&](const void* bytes, std::size_t size) {
    sum.add(bytes, size);
    out_.write(static_cast<const char*>(bytes), static_cast<std::streamsize>(size));
  };
  const auto length = static_cast<std::uint32_t>(name.size());
  put(&length, sizeof length);
  put(name.data(), length);
  put(&element_size, sizeof element_size);
  put(&count, sizeof count);
  put(data, count * element_size);
  const std::uint64_t check = sum.value();
  out_.write(reinterpret_cast<const char*>(&check), sizeof check);
}

void ArchiveWriter::close() {
  if (closed_) return;
  write_raw(end_record, 1, 0, nullptr);
  out_.close();
  if (!out_) {
    abandon();
    throw_input_error("cannot write '{}' (disk full?)", path_);
  }
  closed_ = true;
  std::error_code error;
  std::filesystem::rename(part_path_, path_, error);
  if (error) {
    abandon();
    throw_input_error("cannot write '{}': {}", path_, error.message());
  }
}

void ArchiveWriter::abandon() {
  closed_ = true;
  out_.close();
  std::error_code ignored;
  std::filesystem::remove(part_path_, ignored);
}

ArchiveWriter::~ArchiveWriter() {
  if (!closed_) abandon();  // an exception left it unfinished: leave no partial file behind
}

ArchiveReader::ArchiveReader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
  if (!in_) throw_input_error("cannot read '{}': no such file or no permission", path);
  std::error_code error;
  file_size_ = std::filesystem::file_size(path, error);
  char head[16];
  std::uint32_t file_version = 0;
  in_.read(head, 16);
  in_.read(reinterpret_cast<char*>(&file_version), sizeof file_version);
  if (!in_ || error || std::memcmp(head, magic, 16) != 0)
    throw_input_error("'{}' is not a flotsam state file", path);
  checksum_ = record_checksum_for(file_version);
  if (!checksum_)
    throw_input_error(
        "'{}' is a flotsam state file of version {}; this flotsam reads versions 2 to {}", path,
        file_version, archive_version);
}

bool ArchiveReader::next_is(const std::string& name) {
  const auto start = in_.tellg();
  std::uint32_t length = 0;
  in_.read(reinterpret_cast<char*>(&length), sizeof length);
  std::string found(in_ && length == name.size() ? length : 0, '\0');
  in_.read(found.data(), static_cast<std::streamsize>(found.size()));
  const bool same = in_ && length == name.size() && found == name;
  in_.clear();
  in_.seekg(start);
  return same;
}

std::uint64_t ArchiveReader::next_record(const std::string& name, std::uint32_t element_size) {
  checksum_->reset();
  auto get = [&](void* bytes, std::size_t size) {
    in_.read(static_cast<char*>(bytes), static_cast<std::streamsize>(size));
    if (in_) checksum_->add(bytes, size);
  };
  std::uint32_t length = 0, size = 0;
  std::uint64_t count = 0;
  get(&length, sizeof length);
  if (in_ && length > longest_name)
    throw_input_error("'{}' is damaged before record '{}' (a name of {} bytes)", path_, name,
                      length);
  std::string found(in_ ? length : 0, '\0');
  get(found.data(), found.size());
  get(&size, sizeof size);
  get(&count, sizeof count);
  if (!in_) throw_input_error("'{}' ends before record '{}': the file is truncated", path_, name);
  if (found != name || size != element_size)
    throw_input_error("'{}': expected record '{}' ({} bytes per value), found '{}' ({} bytes)",
                      path_, name, element_size, found, size);
  const auto position = static_cast<std::uint64_t>(in_.tellg());
  const std::uint64_t left = file_size_ > position ? file_size_ - position : 0;
  if (size > 0 && count > left / size)
    throw_input_error(
        "'{}': record '{}' claims {} values of {} bytes but the file has {} bytes left: the file "
        "is truncated or damaged",
        path_, name, count, size, left);
  return count;
}

void ArchiveReader::read_bytes(void* data, std::uint64_t bytes, const std::string& name) {
  in_.read(static_cast<char*>(data), static_cast<std::streamsize>(bytes));
  std::uint64_t stored = 0;
  in_.read(reinterpret_cast<char*>(&stored), sizeof stored);
  if (!in_) throw_input_error("'{}' ends inside record '{}': the file is truncated", path_, name);
  checksum_->add(data, bytes);
  if (stored != checksum_->value())
    throw_input_error(
        "'{}': record '{}' is damaged (its checksum does not match its contents): the file was "
        "altered after it was written",
        path_, name);
}

void ArchiveReader::finish() {
  next_record(end_record, 1);
  read_bytes(nullptr, 0, end_record);
  const auto position = static_cast<std::uint64_t>(in_.tellg());
  if (position != file_size_)
    throw_input_error(
        "'{}' has {} bytes after its last record: the file was appended to or damaged", path_,
        file_size_ - position);
}

}  // namespace flotsam
