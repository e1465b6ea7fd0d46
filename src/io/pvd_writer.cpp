#include "io/pvd_writer.hpp"

#include <fmt/format.h>

#include "io/vtk_xml.hpp"

namespace flotsam {

PvdWriter::PvdWriter(std::string path, Start start) : path_(std::move(path)) {
  if (start == Start::empty_now) write();
}

void PvdWriter::add(double time, const std::string& relative_file, int part) {
  entries_.push_back({time, relative_file, part});
  write();
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
