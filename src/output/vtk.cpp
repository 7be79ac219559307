#include "output/vtk.hpp"

#include <array>
#include <bit>
#include <fstream>
#include <initializer_list>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>

#include <fmt/format.h>

namespace crumple::output {

namespace {

// VTK cell type codes (vtkCellType.h).
constexpr uint8_t kVtkTetra = 10;
constexpr uint8_t kVtkHexahedron = 12;
constexpr uint8_t kVtkWedge = 13;

// The readers honour byte_order, so the native order is always correct; it is little-endian
// on every machine we target.
constexpr const char* kByteOrder =
    std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";

std::string xmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
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

// Writes through a sibling temporary file renamed over `path` at the end, so a reader (or a
// run interrupted mid-write) never sees a half-written file under the final name.
template <typename WriteBody>
void writeAtomically(const std::filesystem::path& path, WriteBody&& body) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error(fmt::format("cannot open '{}' for writing", path.string()));
  bool written = false;
  try {
    body(out);
    out.close();
    written = static_cast<bool>(out);
  } catch (...) {
    out.close();
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  if (!written) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error(fmt::format("error while writing '{}'", path.string()));
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path.string(), ec.message()));
  }
}

// Checked before any file is opened, so a caller's mistake leaves no file behind.
void checkFields(const std::vector<FieldView>& fields) {
  for (const FieldView& field : fields) {
    if ((field.f64 == nullptr) == (field.i64 == nullptr)) {
      throw std::invalid_argument(
          fmt::format("field '{}' must have exactly one of f64 and i64 set", field.name));
    }
    if (field.components < 1) {
      throw std::invalid_argument(
          fmt::format("field '{}' has {} components", field.name, field.components));
    }
  }
}

const char* typeName(const FieldView& field) {
  return field.f64 != nullptr ? "Float64" : "Int64";
}

// One cell in VTK terms: its type and its 4, 6 or 8 node indices.
struct VtkCell {
  uint8_t type = kVtkHexahedron;
  int count = 8;
  std::array<int32_t, 8> nodes{};
};

// LS-DYNA stores tetrahedra and pentahedra as degenerate hexahedra: N1 N2 N3 N4 N4 N4 N4 N4
// and N1 N2 N3 N4 N5 N5 N6 N6. Collapsing the repeated slots of the hexahedron gives a tet
// with base (N1,N2,N3) whose right-hand normal points at N4 (VTK's tetra convention) and a
// wedge whose triangles are (N1,N2,N5) and (N4,N3,N6) with edges N1-N4, N2-N3, N5-N6. VTK
// wants the triangle (0,1,2) to point away from (3,4,5) for a positive volume (checked with
// vtkCellSizeFilter), which (N1,N2,N5),(N4,N3,N6) does for a positive hexahedron. No other
// collapse has a defined meaning in LS-DYNA, so it is passed on as the collapsed hexahedron it
// is and VTK draws it as such.
VtkCell classify(const int32_t* h) {
  VtkCell cell;
  auto distinct = [](std::initializer_list<int32_t> ids) {
    for (auto a = ids.begin(); a != ids.end(); ++a) {
      for (auto b = a + 1; b != ids.end(); ++b) {
        if (*a == *b) return false;
      }
    }
    return true;
  };
  if (h[3] == h[4] && h[3] == h[5] && h[3] == h[6] && h[3] == h[7] &&
      distinct({h[0], h[1], h[2], h[3]})) {
    cell.type = kVtkTetra;
    cell.count = 4;
    cell.nodes = {h[0], h[1], h[2], h[3]};
  } else if (h[4] == h[5] && h[6] == h[7] && distinct({h[0], h[1], h[2], h[3], h[4], h[6]})) {
    cell.type = kVtkWedge;
    cell.count = 6;
    cell.nodes = {h[0], h[1], h[4], h[3], h[2], h[6]};
  } else {
    for (int i = 0; i < 8; ++i) cell.nodes[i] = h[i];
  }
  return cell;
}

// Shells: a quadrilateral, or a triangle when n3 == n4 (LS-DYNA's degenerate shell); beams and
// springs: a line.
VtkCell classifySurfaceOrLine(const int32_t* h, int size) {
  constexpr uint8_t kVtkLine = 3, kVtkTriangle = 5, kVtkQuad = 9;
  VtkCell cell;
  if (size == 2) {
    cell.type = kVtkLine;
    cell.count = 2;
    cell.nodes = {h[0], h[1]};
  } else if (h[2] == h[3]) {
    cell.type = kVtkTriangle;
    cell.count = 3;
    cell.nodes = {h[0], h[1], h[2]};
  } else {
    cell.type = kVtkQuad;
    cell.count = 4;
    cell.nodes = {h[0], h[1], h[2], h[3]};
  }
  return cell;
}

// The appended section: each block is a UInt64 byte count followed by the bytes, and each
// DataArray names its block by the offset of that count from the first byte after '_'.
class AppendedData {
 public:
  struct Block {
    const void* data;
    uint64_t bytes;
  };
  uint64_t add(const void* data, uint64_t bytes) {
    uint64_t offset = next_offset_;
    blocks_.push_back({data, bytes});
    next_offset_ += sizeof(uint64_t) + bytes;
    return offset;
  }
  void write(std::ostream& out) const {
    out << "  <AppendedData encoding=\"raw\">\n   _";
    for (const Block& b : blocks_) {
      out.write(reinterpret_cast<const char*>(&b.bytes), sizeof b.bytes);
      if (b.bytes > 0)
        out.write(static_cast<const char*>(b.data), static_cast<std::streamsize>(b.bytes));
    }
    out << "\n  </AppendedData>\n";
  }

 private:
  std::vector<Block> blocks_;
  uint64_t next_offset_ = 0;
};

void writeFieldArrays(std::ostream& out, AppendedData& appended,
                      const std::vector<FieldView>& fields, Association where, std::size_t count) {
  for (const FieldView& f : fields) {
    if (f.where != where) continue;
    const char* type = typeName(f);
    const uint64_t values = static_cast<uint64_t>(count) * static_cast<uint64_t>(f.components);
    const void* data = f.f64 != nullptr ? static_cast<const void*>(f.f64) : f.i64;
    const uint64_t offset = appended.add(data, values * 8);
    out << fmt::format(
        "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" "
        "offset=\"{}\"/>\n",
        type, xmlEscape(f.name), f.components, offset);
  }
}

void writeFieldDeclarations(std::ostream& out, const std::vector<FieldView>& fields,
                            Association where) {
  for (const FieldView& f : fields) {
    if (f.where != where) continue;
    const char* type = typeName(f);
    out << fmt::format("      <PDataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"/>\n",
                       type, xmlEscape(f.name), f.components);
  }
}

std::string formatTime(double t) {
  return fmt::format("{}", t);
}

}  // namespace

void writeVtu(const std::filesystem::path& path, const MeshView& mesh,
              const std::vector<FieldView>& fields) {
  checkFields(fields);
  std::vector<int64_t> connectivity;
  std::vector<int64_t> offsets;
  std::vector<uint8_t> types;
  connectivity.reserve(8 * mesh.num_cells);
  offsets.reserve(mesh.num_cells);
  types.reserve(mesh.num_cells);
  for (std::size_t c = 0; c < mesh.num_cells; ++c) {
    const int32_t* h = mesh.hex_nodes + 8 * c;
    const int size = mesh.cell_sizes != nullptr ? mesh.cell_sizes[c] : 8;
    if (size != 8 && size != 4 && size != 2)
      throw std::invalid_argument(
          fmt::format("writing '{}': cell {} has {} nodes (8, 4 or 2)", path.string(), c, size));
    for (int i = 0; i < size; ++i) {
      if (h[i] < 0 || static_cast<std::size_t>(h[i]) >= mesh.num_points) {
        throw std::invalid_argument(
            fmt::format("writing '{}': cell {} refers to point {} but the mesh has {} points",
                        path.string(), c, h[i], mesh.num_points));
      }
    }
    const VtkCell cell = size == 8 ? classify(h) : classifySurfaceOrLine(h, size);
    connectivity.insert(connectivity.end(), cell.nodes.begin(), cell.nodes.begin() + cell.count);
    offsets.push_back(static_cast<int64_t>(connectivity.size()));
    types.push_back(cell.type);
  }

  writeAtomically(path, [&](std::ofstream& out) {
    AppendedData appended;
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"" << kByteOrder
        << "\" header_type=\"UInt64\">\n"
        << "  <UnstructuredGrid>\n"
        << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", mesh.num_points,
                       mesh.num_cells);
    out << "      <PointData>\n";
    writeFieldArrays(out, appended, fields, Association::Point, mesh.num_points);
    out << "      </PointData>\n      <CellData>\n";
    writeFieldArrays(out, appended, fields, Association::Cell, mesh.num_cells);
    out << "      </CellData>\n      <Points>\n";
    out << fmt::format(
        "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
        "format=\"appended\" offset=\"{}\"/>\n",
        appended.add(mesh.points, 3 * 8 * static_cast<uint64_t>(mesh.num_points)));
    out << "      </Points>\n      <Cells>\n";
    out << fmt::format(
        "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" "
        "offset=\"{}\"/>\n",
        appended.add(connectivity.data(), 8 * static_cast<uint64_t>(connectivity.size())));
    out << fmt::format(
        "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"{}\"/>\n",
        appended.add(offsets.data(), 8 * static_cast<uint64_t>(offsets.size())));
    out << fmt::format(
        "        <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"{}\"/>\n",
        appended.add(types.data(), types.size()));
    out << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
    appended.write(out);
    out << "</VTKFile>\n";
  });
}

void writePvtu(const std::filesystem::path& path, const std::vector<std::string>& pieces,
               const std::vector<FieldView>& fields) {
  checkFields(fields);
  writeAtomically(path, [&](std::ofstream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"" << kByteOrder
        << "\" header_type=\"UInt64\">\n"
        << "  <PUnstructuredGrid GhostLevel=\"0\">\n"
        << "    <PPointData>\n";
    writeFieldDeclarations(out, fields, Association::Point);
    out << "    </PPointData>\n    <PCellData>\n";
    writeFieldDeclarations(out, fields, Association::Cell);
    out << "    </PCellData>\n"
        << "    <PPoints>\n"
        << "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
        << "    </PPoints>\n";
    for (const std::string& piece : pieces) {
      out << "    <Piece Source=\"" << xmlEscape(piece) << "\"/>\n";
    }
    out << "  </PUnstructuredGrid>\n</VTKFile>\n";
  });
}

PvdWriter::PvdWriter(std::filesystem::path path) : path_(std::move(path)) {}

void PvdWriter::addState(double time, const std::string& file_relative_to_pvd) {
  states_.emplace_back(time, file_relative_to_pvd);
  flush();
}

void PvdWriter::flush() const {
  writeAtomically(path_, [&](std::ofstream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"" << kByteOrder << "\">\n"
        << "  <Collection>\n";
    for (const auto& [time, file] : states_) {
      out << "    <DataSet timestep=\"" << formatTime(time) << "\" group=\"\" part=\"0\" file=\""
          << xmlEscape(file) << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
  });
}

}  // namespace crumple::output
