// VTK XML writers (VTU pieces, PVTU, PVD collection) that know meshes and fields, no physics.
// Binary data goes in an appended raw section (encoding="raw"), which ParaView and VTK's
// vtkXMLUnstructuredGridReader read directly.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace crumple::output {

// Cells are given as 8-node hexahedra in LS-DYNA ordering, possibly degenerate
// (tetrahedron: n4=n5=n6=n7=n8; wedge/pentahedron: n5=n6 and n7=n8). The writer emits
// VTK_HEXAHEDRON, VTK_WEDGE or VTK_TETRA as the node pattern says, so ParaView draws them right.
// Shells (4 nodes, n3 == n4 a triangle) and beams or springs (2 nodes) are given in the same
// stride-8 array with their node count in `cell_sizes` (VTK_QUAD, VTK_TRIANGLE, VTK_LINE).
struct MeshView {
  std::size_t num_points = 0;
  const double* points = nullptr;  // packed xyz, 3*num_points (current coordinates)
  std::size_t num_cells = 0;
  const int32_t* hex_nodes = nullptr;   // 8*num_cells indices into points (stride 8)
  const uint8_t* cell_sizes = nullptr;  // nodes per cell (8, 4 or 2); nullptr: all 8
};

enum class Association { Point, Cell };

// A field of `components` values per point or cell, packed (component fastest).
struct FieldView {
  std::string name;
  Association where = Association::Point;
  int components = 1;
  const double* f64 = nullptr;  // exactly one of f64 / i64 is set
  const int64_t* i64 = nullptr;
};

// Writes one .vtu piece. Throws std::runtime_error naming the path on I/O failure.
void writeVtu(const std::filesystem::path& path, const MeshView& mesh,
              const std::vector<FieldView>& fields);

// Writes a .pvtu that refers to `pieces` (paths relative to the .pvtu's folder); the field
// names, associations, components and types are taken from `fields` (values unused).
void writePvtu(const std::filesystem::path& path, const std::vector<std::string>& pieces,
               const std::vector<FieldView>& fields);

// The results.pvd collection: one DataSet per plot state; rewritten after every state so an
// interrupted run still leaves a readable collection.
class PvdWriter {
 public:
  explicit PvdWriter(std::filesystem::path path);
  void addState(double time, const std::string& file_relative_to_pvd);
  // The states listed so far; restore() replaces them and rewrites the file (restart: the
  // states up to the dump, whatever the interrupted continuation had added).
  const std::vector<std::pair<double, std::string>>& states() const { return states_; }
  void restore(std::vector<std::pair<double, std::string>> states) {
    states_ = std::move(states);
    flush();
  }

 private:
  void flush() const;
  std::filesystem::path path_;
  std::vector<std::pair<double, std::string>> states_;
};

}  // namespace crumple::output
