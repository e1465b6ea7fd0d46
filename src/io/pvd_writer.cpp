#include "io/pvd_writer.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "io/vtk_xml.hpp"

namespace flotsam {

PvdWriter::PvdWriter(std::string path, Start start) : path_(std::move(path)), start_(start) {
  if (start == Start::empty_now) write();
}

PvdWriter::~PvdWriter() {
  try {
    close();
  } catch (const std::exception&) {  // a destructor cannot report it; close() does
  }
}

void PvdWriter::add(double time, const std::string& relative_file, int part) {
  if (closed_) throw std::logic_error("PvdWriter::add after close: " + path_);
  entries_.push_back({time, relative_file, part});
  if (start_ != Start::when_closed) write();
}

void PvdWriter::close() {
  if (closed_ || path_.empty()) return;
  closed_ = true;
  if (start_ == Start::when_closed && !entries_.empty()) write();
}

void PvdWriter::write() const {
  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "<Collection>\n";
  for (const Entry& entry : entries_)  // {:.17g}: the time round-trips exactly
    text += fmt::format("  <DataSet timestep=\"{:.17g}\" group=\"\" part=\"{}\" file=\"{}\"/>\n",
                        entry.time, entry.part, xml_escape(entry.file));
  text += "</Collection>\n</VTKFile>\n";
  write_file_atomically(path_, text);
}

}  // namespace flotsam
