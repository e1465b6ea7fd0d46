#pragma once
// The structure of a Gmsh MSH file, checked before Gmsh reads it. Gmsh 4.8's parsers trust the
// counts a file declares: a node block longer than its section's count, or a node block header
// missing a number, writes past Gmsh's arrays and crashes the program (a damaged file kept in
// tests/fuzz/gmsh_crashes). flotsam therefore reads the file once itself and hands Gmsh only
// files whose structure it has verified; anything else is an InputError naming the file, the line
// (ASCII) or byte (binary) and what was expected there.
//
// Accepted: a name ending in .msh or .msh2 (Gmsh picks its reader by the name, then by the first
// line), $MeshFormat on the first line, MSH 2.2 and 4.1 (what flotsam writes and documents), ASCII
// or binary (little-endian, 8-byte size_t, as Gmsh writes on x86-64 and ARM), with the sections
// $MeshFormat (first), $PhysicalNames, $Entities (4.1, before $Nodes), $Nodes and $Elements (after
// $Nodes), each at most once and each closed by its $End line. Any other section ($Periodic,
// $NodeData, partitions, ...) is refused: flotsam does not use them and Gmsh's readers of them
// trust their counts too.
//
// Checked in every section: each number parses in full (an integer in its range, a finite real),
// the declared counts match the entries, tags are positive and unique, node blocks hold no
// parametric coordinates, every element block's entity exists and has the element type's
// dimension, an entity holds elements of one type only (Gmsh 4.8 corrupts its memory reading a
// surface of both 3- and 6-node triangles), every element's node tags exist, a 4.1 section's
// declared smallest and largest tags are its tags', and the element types are ones Gmsh 4.8 knows
// (points, lines, triangles, quadrangles, tetrahedra, hexahedra, prisms, pyramids of order 1 and
// 2). An ASCII element is one line (Gmsh reads its node tags with one fgets).
#include <cstddef>
#include <string>
#include <string_view>

namespace flotsam {

/// What the check counted, for the size estimate before a run.
struct MshCounts {
  std::string format;         // "4.1 ASCII", "2.2 binary", ...
  std::size_t nodes = 0;      // all nodes of the file
  std::size_t triangles = 0;  // 3- and 6-node triangles (Gmsh types 2 and 9)
  std::size_t lines = 0;      // 2- and 3-node lines (Gmsh types 1 and 8)
  std::size_t elements = 0;   // all elements, points included
};

/// Checks the MSH file at `path` (see above). Throws InputError naming the file when it cannot
/// be read or its structure is wrong.
MshCounts check_msh(const std::string& path);

/// The same check of a file's bytes, `path` naming it in messages.
MshCounts check_msh_bytes(const std::string& path, std::string_view bytes);

}  // namespace flotsam
