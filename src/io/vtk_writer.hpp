#pragma once
// ParaView output (docs/output-format.md), one header for the callers:
//   write_vtu           flow fields on the P2 mesh (.vtu, quadratic triangles)
//   write_boundary_vtp  the boundary edges with their group (.vtp)
//   write_bodies_vtp    the bodies as rectangles with their state (.vtp)
//   PvdWriter           the time-series index ParaView opens (.pvd)
// All binary (appended raw, see io/vtk_xml.hpp), written through a temporary file and a rename.
#include "io/pvd_writer.hpp"
#include "io/vtp_writer.hpp"
#include "io/vtu_writer.hpp"
