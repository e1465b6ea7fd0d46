#include "io/binary_archive.hpp"

#include <cstdio>
#include <filesystem>

namespace flotsam {
namespace {
constexpr char magic[17] = "FLOTSAM-ARCHIVE\n";
constexpr std::uint32_t version = 1;
}  // namespace

ArchiveWriter::ArchiveWriter(const std::string& path)
    : path_(path), part_path_(path + ".part"), out_(part_path_, std::ios::binary) {
  if (!out_) throw_input_error("cannot write '{}'", path);
  out_.write(magic, 16);
  out_.write(reinterpret_cast<const char*>(&version), sizeof version);
}

void ArchiveWriter::write_raw(const std::string& name, std::uint32_t element_size,
                              std::uint64_t count, const void* data) {
  const auto length = static_cast<std::uint32_t>(name.size());
  out_.write(reinterpret_cast<const char*>(&length), sizeof length);
  out_.write(name.data(), static_cast<std::streamsize>(length));
  out_.write(reinterpret_cast<const char*>(&element_size), sizeof element_size);
  out_.write(reinterpret_cast<const char*>(&count), sizeof count);
  out_.write(static_cast<const char*>(data), static_cast<std::streamsize>(count * element_size));
}

void ArchiveWriter::close() {
  if (closed_) return;
  closed_ = true;
  out_.close();
  if (!out_) throw_input_error("cannot write '{}' (disk full?)", path_);
  std::filesystem::rename(part_path_, path_);
}

ArchiveWriter::~ArchiveWriter() {
  if (!closed_) {  // an exception left it unfinished: leave no partial file behind
    out_.close();
    std::error_code ignored;
    std::filesystem::remove(part_path_, ignored);
  }
}

ArchiveReader::ArchiveReader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
  if (!in_) throw_input_error("cannot read '{}': no such file or no permission", path);
  char head[16];
  std::uint32_t file_version = 0;
  in_.read(head, 16);
  in_.read(reinterpret_cast<char*>(&file_version), sizeof file_version);
  if (!in_ || std::memcmp(head, magic, 16) != 0)
    throw_input_error("'{}' is not a flotsam state file", path);
  if (file_version != version)
    throw_input_error("'{}' is a flotsam state file of version {}; this flotsam reads version {}",
                      path, file_version, version);
}

std::uint64_t ArchiveReader::next_record(const std::string& name, std::uint32_t element_size) {
  std::uint32_t length = 0, size = 0;
  std::uint64_t count = 0;
  in_.read(reinterpret_cast<char*>(&length), sizeof length);
  std::string found(in_ ? length : 0, '\0');
  in_.read(found.data(), static_cast<std::streamsize>(found.size()));
  in_.read(reinterpret_cast<char*>(&size), sizeof size);
  in_.read(reinterpret_cast<char*>(&count), sizeof count);
  if (!in_) throw_input_error("'{}' ends before record '{}': the file is truncated", path_, name);
  if (found != name || size != element_size)
    throw_input_error("'{}': expected record '{}' ({} bytes per value), found '{}' ({} bytes)",
                      path_, name, element_size, found, size);
  return count;
}

void ArchiveReader::read_bytes(void* data, std::uint64_t bytes, const std::string& name) {
  in_.read(static_cast<char*>(data), static_cast<std::streamsize>(bytes));
  if (!in_) throw_input_error("'{}' ends inside record '{}': the file is truncated", path_, name);
}

}  // namespace flotsam
