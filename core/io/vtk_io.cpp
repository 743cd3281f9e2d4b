#include "core/mesh/check_surface_mesh.h"
#include "core/io/vtk_io.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>

#include <pugixml.hpp>

#include "core/geometry/z_range.h"
#include "core/io/finish_mesh.h"
#include "core/io/surface_io.h"
#include "core/io/text_reader.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

constexpr long long kMaxInt = std::numeric_limits<int>::max();
constexpr int kVtkVertex = 1, kVtkLine = 3, kVtkTriangle = 5, kVtkTetra = 10;

// ---------------------------------------------------------------------------------------------
// Writing

struct Cells {
  int nv = 0, npe = 0, type = 0;
  std::vector<double> xyz;  // 3 per vertex
  std::vector<int> conn;    // npe per live element
  std::vector<int> region;  // per live element
};

Cells cells_of(const MeshData& data, const std::vector<ElementField>& fields) {
  Cells c;
  if (data.dim == 3 && is_surface_mesh(data.tet)) {
    // A surface mesh in space: its triangles, the surface tag as the region.
    const TetMesh& m = data.tet;
    c.nv = m.nb_vertices();
    c.npe = 3;
    c.type = kVtkTriangle;
    c.xyz = m.xyz;
    for (int f = 0; f < m.nb_tris(); ++f)
      if (m.tris[3 * f] >= 0) {
        c.conn.insert(c.conn.end(), &m.tris[3 * f], &m.tris[3 * f] + 3);
        c.region.push_back(m.tri_surface[f]);
      }
  } else if (data.dim == 3) {
    const TetMesh& m = data.tet;
    c.nv = m.nb_vertices();
    c.npe = 4;
    c.type = kVtkTetra;
    c.xyz = m.xyz;
    for (int t = 0; t < m.nb_tets(); ++t)
      if (m.tets[4 * t] >= 0) {
        c.conn.insert(c.conn.end(), &m.tets[4 * t], &m.tets[4 * t] + 4);
        c.region.push_back(m.tet_region[t]);
      }
  } else {
    const TriMesh2& m = data.tri;
    c.nv = m.nb_vertices();
    c.npe = 3;
    c.type = kVtkTriangle;
    for (int v = 0; v < c.nv; ++v) c.xyz.insert(c.xyz.end(), {m.point(v)[0], m.point(v)[1], m.z0});
    for (int t = 0; t < m.nb_tris(); ++t)
      if (m.tris[3 * t] >= 0) {
        c.conn.insert(c.conn.end(), &m.tris[3 * t], &m.tris[3 * t] + 3);
        c.region.push_back(m.tri_region[t]);
      }
  }
  for (const auto& f : fields)
    if (f.values.size() != c.region.size())
      throw InvariantError("VTK writer: field '" + f.name + "' has " +
                           std::to_string(f.values.size()) + " values for " +
                           std::to_string(c.region.size()) + " elements");
  return c;
}

void close_checked(std::FILE* f, const std::string& path) {
  const bool bad = std::ferror(f) != 0;
  if (std::fclose(f) != 0 || bad)
    throw OutputError("cannot write '" + path + "': write error (disk full?)");
}

std::string legacy_name(const std::string& name) {
  std::string r = name.empty() ? "field" : name;
  for (char& ch : r)
    if (std::isspace(static_cast<unsigned char>(ch)) || ch < 33 || ch > 126) ch = '_';
  return r;
}

std::string xml_escape(const std::string& s) {
  std::string r;
  for (char ch : s) {
    switch (ch) {
      case '&':
        r += "&amp;";
        break;
      case '<':
        r += "&lt;";
        break;
      case '>':
        r += "&gt;";
        break;
      case '"':
        r += "&quot;";
        break;
      default:
        r += ch;
    }
  }
  return r;
}

// ---------------------------------------------------------------------------------------------
// Reading: both formats fill a Grid, then grid_to_mesh builds the MeshData.

struct Grid {
  std::vector<double> xyz;
  std::vector<long long> offsets;  // #cells + 1
  std::vector<long long> conn;
  std::vector<long long> types;
  std::vector<std::pair<std::string, std::vector<double>>> cell_arrays;  // one component
};

const char* cell_type_name(long long t) {
  switch (t) {
    case 7:
      return "polygon";
    case 8:
      return "pixel";
    case 9:
      return "quad";
    case 11:
      return "voxel";
    case 12:
      return "hexahedron";
    case 13:
      return "wedge (prism)";
    case 14:
      return "pyramid";
    case 21:
      return "quadratic edge";
    case 22:
      return "quadratic triangle";
    case 24:
      return "quadratic tetrahedron";
    case 42:
      return "polyhedron";
    default:
      return "unknown";
  }
}

int nodes_of(long long type) {
  switch (type) {
    case kVtkVertex:
      return 1;
    case kVtkLine:
      return 2;
    case kVtkTriangle:
      return 3;
    case kVtkTetra:
      return 4;
    default:
      return 0;
  }
}

MeshData grid_to_mesh(const Grid& g, const std::string& path, std::vector<ElementField>* fields) {
  const std::string what = "'" + path + "'";
  const long long nc = static_cast<long long>(g.types.size());
  const long long nv = static_cast<long long>(g.xyz.size() / 3);
  if (static_cast<long long>(g.offsets.size()) != nc + 1)
    throw InputError(what + ": the number of cell types differs from the number of cells");
  const std::vector<double>* region = nullptr;
  for (const auto& [name, values] : g.cell_arrays) {
    if (static_cast<long long>(values.size()) != nc)
      throw InputError(what + ": cell array '" + name + "' has " + std::to_string(values.size()) +
                       " values for " + std::to_string(nc) + " cells");
    if (name == "region") region = &values;
  }
  bool has_tets = false;
  for (long long c = 0; c < nc; ++c) {
    const long long t = g.types[c];
    const int n = nodes_of(t);
    if (!n)
      throw InputError(what + ": unsupported cell type " + std::to_string(t) + " (" +
                       cell_type_name(t) + ") in cell " + std::to_string(c + 1) +
                       "; cvtmesh optimizes linear triangles and tetrahedra only");
    if (g.offsets[c + 1] - g.offsets[c] != n)
      throw InputError(what + ": cell " + std::to_string(c + 1) + " of type " + std::to_string(t) +
                       " has " + std::to_string(g.offsets[c + 1] - g.offsets[c]) +
                       " points instead of " + std::to_string(n));
    has_tets |= t == kVtkTetra;
  }
  for (long long v : g.conn)
    if (v < 0 || v >= nv)
      throw InputError(what + ": a cell refers to point " + std::to_string(v) +
                       ", which does not exist (" + std::to_string(nv) + " points, 0-based)");
  auto tag_of = [&](long long c) {
    if (!region) return 0;
    const double r = (*region)[c];
    if (r != std::floor(r) || std::fabs(r) > 2e9)
      throw InputError(what + ": region value " + std::to_string(r) + " of cell " +
                       std::to_string(c + 1) + " is not an integer tag");
    return static_cast<int>(r);
  };
  const int dim = has_tets ? 3 : 2;
  const long long main_type = has_tets ? kVtkTetra : kVtkTriangle;
  const long long facet_type = has_tets ? kVtkTriangle : kVtkLine;
  std::vector<int> cells, cell_tag, facets, facet_tag;
  std::vector<long long> main_index;
  for (long long c = 0; c < nc; ++c) {
    const long long t = g.types[c];
    if (t == main_type) {
      for (long long k = g.offsets[c]; k < g.offsets[c + 1]; ++k)
        cells.push_back(static_cast<int>(g.conn[k]));
      const int tag = tag_of(c);
      cell_tag.push_back(region ? tag : 1);
      main_index.push_back(c);
    } else if (t == facet_type) {
      for (long long k = g.offsets[c]; k < g.offsets[c + 1]; ++k)
        facets.push_back(static_cast<int>(g.conn[k]));
      facet_tag.push_back(tag_of(c));
    }
  }
  if (cells.empty()) throw InputError(what + " has no tetrahedra and no triangles (empty mesh)");
  MeshData data;
  data.dim = dim;
  const std::string name = std::filesystem::path(path).stem().string();
  if (dim == 3) {
    data.tet.xyz = g.xyz;
    data.tet.tets = std::move(cells);
    data.tet.tet_region = std::move(cell_tag);
    data.tet.tris = std::move(facets);
    data.tet.tri_surface = std::move(facet_tag);
    data.tet.model.name = name;
  } else {
    const ZRange zr = z_range(g.xyz, &cells);
    const double zmin = zr.zmin;
    if (!zr.planar) {
      throw_surface_only(what, g.xyz, cells);
    }
    TriMesh2& m = data.tri;
    m.z0 = zmin;
    for (long long v = 0; v < nv; ++v) m.xy.insert(m.xy.end(), {g.xyz[3 * v], g.xyz[3 * v + 1]});
    m.tris = std::move(cells);
    m.tri_region = std::move(cell_tag);
    m.edges = std::move(facets);
    m.edge_curve = std::move(facet_tag);
    m.model.name = name;
  }
  finish_mesh(data, what);
  if (fields) {
    fields->clear();
    for (const auto& [aname, values] : g.cell_arrays) {
      if (aname == "region") continue;
      ElementField f{aname, {}};
      for (long long c : main_index) f.values.push_back(values[c]);
      fields->push_back(std::move(f));
    }
  }
  return data;
}

std::string upper(std::string_view s) {
  std::string r(s);
  std::transform(r.begin(), r.end(), r.begin(), [](unsigned char c) { return std::toupper(c); });
  return r;
}

// Legacy: the values of one dataset attribute (n tuples of ncomp numbers).
std::vector<double> read_values(TextReader& in, long long n, long long ncomp) {
  in.check_count(n * ncomp, 1, "values");
  std::vector<double> v;
  v.reserve(static_cast<std::size_t>(n * ncomp));
  for (long long i = 0; i < n * ncomp; ++i) v.push_back(in.real("a data value", false));
  return v;
}

// Legacy: the attribute sections after CELL_DATA n / POINT_DATA n. Returns the next keyword (or
// "" at the end of the file); keeps one-component arrays if `keep`.
std::string read_attributes(TextReader& in, long long n, Grid& g, bool keep) {
  while (!in.at_end()) {
    const std::string kw = upper(in.token("a keyword"));
    if (kw == "SCALARS") {
      const std::string name(in.token("an array name"));
      in.token("a data type");
      long long ncomp = 1;
      std::string next = upper(in.token("LOOKUP_TABLE"));
      if (next != "LOOKUP_TABLE") {
        const auto [p, ec] = std::from_chars(next.data(), next.data() + next.size(), ncomp);
        if (ec != std::errc() || p != next.data() + next.size() || ncomp < 1 || ncomp > 4)
          in.fail("expected the number of components (1 to 4) or LOOKUP_TABLE, got '" +
                  next.substr(0, 40) + "'");
        next = upper(in.token("LOOKUP_TABLE"));
      }
      if (next != "LOOKUP_TABLE")
        in.fail("expected LOOKUP_TABLE, got '" + next.substr(0, 40) + "'");
      in.token("a lookup table name");
      auto v = read_values(in, n, ncomp);
      if (keep && ncomp == 1) g.cell_arrays.emplace_back(name, std::move(v));
    } else if (kw == "FIELD") {
      in.token("a field name");
      const long long na = in.integer("the number of arrays", 0, 100000);
      for (long long a = 0; a < na; ++a) {
        const std::string name(in.token("an array name"));
        const long long ncomp = in.integer("the number of components", 1, 1000);
        const long long nt = in.integer("the number of tuples", 0, kMaxInt);
        in.token("a data type");
        if (nt != n)
          in.fail("array '" + name + "' has " + std::to_string(nt) + " tuples, expected " +
                  std::to_string(n));
        auto v = read_values(in, nt, ncomp);
        if (keep && ncomp == 1) g.cell_arrays.emplace_back(name, std::move(v));
      }
    } else if (kw == "VECTORS" || kw == "NORMALS") {
      in.token("an array name");
      in.token("a data type");
      read_values(in, n, 3);
    } else if (kw == "TENSORS") {
      in.token("an array name");
      in.token("a data type");
      read_values(in, n, 9);
    } else if (kw == "TEXTURE_COORDINATES") {
      in.token("an array name");
      const long long d = in.integer("a dimension", 1, 3);
      in.token("a data type");
      read_values(in, n, d);
    } else if (kw == "COLOR_SCALARS") {
      in.token("an array name");
      read_values(in, n, in.integer("the number of values", 1, 4));
    } else if (kw == "LOOKUP_TABLE") {
      in.token("a table name");
      read_values(in, in.integer("the table size", 0, kMaxInt), 4);
    } else if (kw == "METADATA") {
      // Information keys written by VTK 9: skipped up to the next blank line.
      in.rest_of_line();
      while (!in.at_end()) {
        const std::string l = in.rest_of_line();
        if (l.find_first_not_of(" \t\r") == std::string::npos) break;
      }
    } else {
      return kw;
    }
  }
  return "";
}

}  // namespace

void write_vtk(const MeshData& data, const std::string& path,
               const std::vector<ElementField>& fields) {
  const Cells c = cells_of(data, fields);
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw OutputError("cannot write '" + path + "': cannot create the file");
  const std::size_t ne = c.region.size();
  std::fprintf(f, "# vtk DataFile Version 3.0\ncvtmesh %s\nASCII\nDATASET UNSTRUCTURED_GRID\n",
               legacy_name(data.model().name).c_str());
  std::fprintf(f, "POINTS %d double\n", c.nv);
  for (int v = 0; v < c.nv; ++v)
    std::fprintf(f, "%.17g %.17g %.17g\n", c.xyz[3 * v], c.xyz[3 * v + 1], c.xyz[3 * v + 2]);
  std::fprintf(f, "CELLS %zu %zu\n", ne, ne * (c.npe + 1));
  for (std::size_t e = 0; e < ne; ++e) {
    std::fprintf(f, "%d", c.npe);
    for (int k = 0; k < c.npe; ++k) std::fprintf(f, " %d", c.conn[c.npe * e + k]);
    std::fprintf(f, "\n");
  }
  std::fprintf(f, "CELL_TYPES %zu\n", ne);
  for (std::size_t e = 0; e < ne; ++e) std::fprintf(f, "%d\n", c.type);
  std::fprintf(f, "CELL_DATA %zu\nSCALARS region int 1\nLOOKUP_TABLE default\n", ne);
  for (int r : c.region) std::fprintf(f, "%d\n", r);
  for (const auto& fld : fields) {
    std::fprintf(f, "SCALARS %s double 1\nLOOKUP_TABLE default\n", legacy_name(fld.name).c_str());
    for (double v : fld.values) std::fprintf(f, "%.17g\n", v);
  }
  close_checked(f, path);
}

void write_vtu(const MeshData& data, const std::string& path,
               const std::vector<ElementField>& fields) {
  const Cells c = cells_of(data, fields);
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw OutputError("cannot write '" + path + "': cannot create the file");
  const std::size_t ne = c.region.size();
  std::fprintf(f,
               "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "  <UnstructuredGrid>\n"
               "    <Piece NumberOfPoints=\"%d\" NumberOfCells=\"%zu\">\n"
               "      <Points>\n"
               "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
               c.nv, ne);
  for (int v = 0; v < c.nv; ++v)
    std::fprintf(f, "%.17g %.17g %.17g\n", c.xyz[3 * v], c.xyz[3 * v + 1], c.xyz[3 * v + 2]);
  std::fprintf(f,
               "        </DataArray>\n      </Points>\n      <Cells>\n"
               "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (std::size_t e = 0; e < ne; ++e) {
    for (int k = 0; k < c.npe; ++k) std::fprintf(f, "%s%d", k ? " " : "", c.conn[c.npe * e + k]);
    std::fprintf(f, "\n");
  }
  std::fprintf(f,
               "        </DataArray>\n"
               "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (std::size_t e = 0; e < ne; ++e) std::fprintf(f, "%zu\n", (e + 1) * c.npe);
  std::fprintf(f,
               "        </DataArray>\n"
               "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (std::size_t e = 0; e < ne; ++e) std::fprintf(f, "%d\n", c.type);
  std::fprintf(f,
               "        </DataArray>\n      </Cells>\n      <CellData Scalars=\"region\">\n"
               "        <DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">\n");
  for (int r : c.region) std::fprintf(f, "%d\n", r);
  std::fprintf(f, "        </DataArray>\n");
  for (const auto& fld : fields) {
    std::fprintf(f, "        <DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n",
                 xml_escape(fld.name).c_str());
    for (double v : fld.values) std::fprintf(f, "%.17g\n", v);
    std::fprintf(f, "        </DataArray>\n");
  }
  std::fprintf(f, "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  close_checked(f, path);
}

MeshData read_vtk(const std::string& path, std::vector<ElementField>* fields) {
  TextReader in(path, false);
  const std::string head = in.rest_of_line();
  if (head.rfind("# vtk DataFile Version", 0) != 0)
    in.fail("not a legacy VTK file (expected '# vtk DataFile Version ...')");
  const bool v5 = head.find("Version 5") != std::string::npos;
  in.rest_of_line();  // title
  const std::string format = upper(in.token("ASCII or BINARY"));
  if (format == "BINARY") in.fail("binary legacy VTK files are not supported (write ASCII)");
  if (format != "ASCII") in.fail("expected ASCII, got '" + format.substr(0, 40) + "'");
  if (upper(in.token("DATASET")) != "DATASET") in.fail("expected DATASET");
  const std::string type = upper(in.token("a dataset type"));
  if (type != "UNSTRUCTURED_GRID")
    in.fail("dataset type '" + type.substr(0, 40) + "' is not supported (only UNSTRUCTURED_GRID)");
  Grid g;
  bool have_points = false, have_cells = false, have_types = false;
  std::string kw = in.at_end() ? "" : upper(in.token("a keyword"));
  while (!kw.empty()) {
    if (kw == "POINTS") {
      if (have_points) in.fail("POINTS given twice");
      have_points = true;
      const long long n = in.integer("the number of points", 0, kMaxInt);
      in.token("a data type");
      in.check_count(n, 3, "points");
      for (long long i = 0; i < 3 * n; ++i) g.xyz.push_back(in.real("a point coordinate"));
    } else if (kw == "CELLS") {
      if (have_cells) in.fail("CELLS given twice");
      have_cells = true;
      const long long n = in.integer("the number of cells", 0, kMaxInt);
      const long long size = in.integer("the size of the cell list", 0, kMaxInt);
      if (v5) {
        // VTK 5.1 layout: CELLS <#offsets> <#connectivity>, OFFSETS <type>, CONNECTIVITY <type>.
        if (upper(in.token("OFFSETS")) != "OFFSETS") in.fail("expected OFFSETS");
        in.token("a data type");
        in.check_count(n, 1, "offsets");
        if (n < 1) in.fail("at least one offset is needed");
        for (long long i = 0; i < n; ++i) {
          g.offsets.push_back(in.integer("an offset", 0, size));
          if (i && g.offsets[i] < g.offsets[i - 1]) in.fail("offsets must not decrease");
        }
        if (g.offsets.front() != 0 || g.offsets.back() != size)
          in.fail("offsets must run from 0 to the connectivity size");
        if (upper(in.token("CONNECTIVITY")) != "CONNECTIVITY") in.fail("expected CONNECTIVITY");
        in.token("a data type");
        in.check_count(size, 1, "connectivity entries");
        for (long long i = 0; i < size; ++i)
          g.conn.push_back(in.integer("a point index", 0, kMaxInt));
      } else {
        in.check_count(size, 1, "cell list entries");
        if (size < n) in.fail("the cell list is shorter than the number of cells");
        g.offsets.push_back(0);
        long long used = 0;
        for (long long i = 0; i < n; ++i) {
          const long long k = in.integer("the number of points of a cell", 1, 1000);
          used += k + 1;
          if (used > size)
            in.fail("the cells need more entries than the declared size " + std::to_string(size));
          for (long long j = 0; j < k; ++j)
            g.conn.push_back(in.integer("a point index", 0, kMaxInt));
          g.offsets.push_back(g.offsets.back() + k);
        }
        if (used != size)
          in.fail("the cells use " + std::to_string(used) + " entries, declared " +
                  std::to_string(size));
      }
    } else if (kw == "CELL_TYPES") {
      if (have_types) in.fail("CELL_TYPES given twice");
      have_types = true;
      const long long n = in.integer("the number of cell types", 0, kMaxInt);
      in.check_count(n, 1, "cell types");
      for (long long i = 0; i < n; ++i) g.types.push_back(in.integer("a cell type", 0, 1000));
    } else if (kw == "CELL_DATA" || kw == "POINT_DATA") {
      const long long n = in.integer("the number of tuples", 0, kMaxInt);
      const long long want = kw == "CELL_DATA" ? static_cast<long long>(g.types.size())
                                               : static_cast<long long>(g.xyz.size() / 3);
      if (n != want)
        in.fail(kw + " " + std::to_string(n) + " differs from the number of " +
                (kw == "CELL_DATA" ? "cells " : "points ") + std::to_string(want));
      kw = read_attributes(in, n, g, kw == "CELL_DATA");
      continue;
    } else if (kw == "METADATA") {
      read_attributes(in, 0, g, false);  // not reached in practice: METADATA follows arrays
    } else {
      in.fail("unexpected keyword '" + kw.substr(0, 40) + "'");
    }
    kw = in.at_end() ? "" : upper(in.token("a keyword"));
  }
  if (!have_points) in.fail("no POINTS section");
  if (!have_cells) in.fail("no CELLS section");
  if (!have_types) in.fail("no CELL_TYPES section");
  return grid_to_mesh(g, path, fields);
}

// ---------------------------------------------------------------------------------------------
// .vtu: the XML parsed by pugixml; the VTK structure (one <Piece> of an UnstructuredGrid, ASCII
// DataArrays) checked here, every refusal naming the file and the line.

namespace {

class VtuDocument {
 public:
  explicit VtuDocument(const std::string& path) : path_(path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError("cannot read '" + path + "': cannot open the file");
    std::ostringstream ss;
    ss << in.rdbuf();
    text_ = ss.str();
    if (text_.empty()) throw InputError("cannot read '" + path + "': the file is empty");
    const pugi::xml_parse_result r = doc_.load_buffer(text_.data(), text_.size());
    if (r.status == pugi::status_no_document_element) fail(0, "not a VTK XML file (no <VTKFile>)");
    if (!r) {
      std::string why = r.description();  // "Start-end tags mismatch", ...
      if (!why.empty())
        why[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(why[0])));
      // pugixml stops at the end of the text when an element or a tag is still open.
      const std::size_t at = static_cast<std::size_t>(std::max<std::ptrdiff_t>(r.offset, 0));
      if (text_.find_first_not_of(" \t\r\n", std::min(at + 1, text_.size())) == std::string::npos)
        fail(at, "the file ends inside an XML element (truncated file?): " + why);
      fail(at, "malformed XML: " + why);
    }
  }
  pugi::xml_node root() const { return doc_.document_element(); }
  [[noreturn]] void fail(std::size_t at, const std::string& msg) const {
    const long line =
        1 + std::count(text_.begin(), text_.begin() + std::min(at, text_.size()), '\n');
    throw InputError("'" + path_ + "' line " + std::to_string(line) + ": " + msg);
  }
  [[noreturn]] void fail(const pugi::xml_node& n, const std::string& msg) const {
    fail(static_cast<std::size_t>(std::max<std::ptrdiff_t>(n.offset_debug(), 0)), msg);
  }
  // The numbers of a <DataArray>, whitespace-separated in its text; `take` says whether a value
  // is acceptable.
  template <class F>
  void numbers(const pugi::xml_node& array, const std::string& what, F&& take) const {
    for (pugi::xml_node t = array.first_child(); t; t = t.next_sibling()) {
      if (t.type() != pugi::node_pcdata && t.type() != pugi::node_cdata) continue;
      const char* const text = t.value();
      long line = 0;  // newlines since the start of the text (parse_eol keeps one per line)
      for (const char* p = text; *p;) {
        if (std::isspace(static_cast<unsigned char>(*p))) {
          line += *p++ == '\n';
          continue;
        }
        const char* q = p;
        while (*q && !std::isspace(static_cast<unsigned char>(*q))) ++q;
        char* end = nullptr;
        const double v = std::strtod(p, &end);
        const std::string tok(p, std::min<std::size_t>(q - p, 40));
        if (end != q) fail_in(t, line, "expected " + what + " (a number), got '" + tok + "'");
        if (!take(v)) fail_in(t, line, "bad " + what + " '" + tok + "'");
        p = q;
      }
    }
  }

 private:
  [[noreturn]] void fail_in(const pugi::xml_node& text, long newlines,
                            const std::string& msg) const {
    const std::size_t at =
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(text.offset_debug(), 0));
    const long line =
        1 + newlines + std::count(text_.begin(), text_.begin() + std::min(at, text_.size()), '\n');
    throw InputError("'" + path_ + "' line " + std::to_string(line) + ": " + msg);
  }

  std::string path_, text_;
  pugi::xml_document doc_;
};

bool integral(double v) {
  return v == std::floor(v) && std::fabs(v) < 9e15;
}

// A count attribute of <Piece>: a decimal integer in [0, INT_MAX], or -1.
long long count_attribute(const pugi::xml_node& piece, const char* name) {
  const std::string s = piece.attribute(name).value();
  char* e = nullptr;
  const long long n = std::strtoll(s.c_str(), &e, 10);
  return s.empty() || *e || n < 0 || n > kMaxInt ? -1 : n;
}

}  // namespace

MeshData read_vtu(const std::string& path, std::vector<ElementField>* fields) {
  const VtuDocument doc(path);
  const pugi::xml_node root = doc.root();
  if (std::strcmp(root.name(), "VTKFile") != 0) doc.fail(root, "not a VTK XML file (no <VTKFile>)");
  const std::string type = root.attribute("type").value();
  if (type != "UnstructuredGrid")
    doc.fail(root,
             "VTK XML type '" + type.substr(0, 40) + "' is not supported (only UnstructuredGrid)");
  if (root.attribute("compressor"))
    doc.fail(root, "compressed .vtu files are not supported (write ASCII)");
  if (const pugi::xml_node a = root.child("AppendedData"))
    doc.fail(a, "appended (binary) .vtu data is not supported (write ASCII)");
  const pugi::xml_node grid = root.child("UnstructuredGrid");
  const pugi::xml_node piece = grid.child("Piece");
  if (!piece) doc.fail(root, "no <Piece>");
  if (const pugi::xml_node second = piece.next_sibling("Piece"))
    doc.fail(second, "more than one <Piece> is not supported");
  const long long np = count_attribute(piece, "NumberOfPoints");
  if (np < 0) doc.fail(piece, "bad NumberOfPoints");
  const long long nc = count_attribute(piece, "NumberOfCells");
  if (nc < 0) doc.fail(piece, "bad NumberOfCells");

  Grid g;
  bool have_points = false, have_conn = false, have_offsets = false, have_types = false;
  std::vector<pugi::xml_node> arrays;  // every <DataArray> in the piece, in document order
  const std::function<void(pugi::xml_node)> collect = [&](pugi::xml_node n) {
    for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
      if (c.type() == pugi::node_element) {
        if (std::strcmp(c.name(), "DataArray") == 0)
          arrays.push_back(c);
        else
          collect(c);
      }
  };
  collect(piece);
  for (const pugi::xml_node& a : arrays) {
    // The section: Points, Cells, CellData or PointData (another parent: none).
    std::string section = a.parent().name();
    if (section != "Points" && section != "Cells" && section != "CellData" &&
        section != "PointData")
      section.clear();
    const std::string fmt = a.attribute("format") ? a.attribute("format").value() : "ascii";
    if (fmt != "ascii")
      doc.fail(a, "DataArray format '" + fmt.substr(0, 40) + "' is not supported (only ascii)");
    const std::string name = a.attribute("Name").value();
    const std::string ncs =
        a.attribute("NumberOfComponents") ? a.attribute("NumberOfComponents").value() : "1";
    const long long ncomp = std::atoll(ncs.c_str());
    if (ncomp < 1 || ncomp > 1000)
      doc.fail(a, "bad NumberOfComponents '" + ncs.substr(0, 40) + "'");
    if (section == "Points") {
      if (have_points) doc.fail(a, "two point arrays");
      have_points = true;
      if (ncomp != 3) doc.fail(a, "points need 3 components");
      doc.numbers(a, "a point coordinate", [&](double v) {
        g.xyz.push_back(v);
        return std::isfinite(v);
      });
      if (static_cast<long long>(g.xyz.size()) != 3 * np)
        doc.fail(a, "the points array has " + std::to_string(g.xyz.size()) + " values, expected " +
                        std::to_string(3 * np));
    } else if (section == "Cells" &&
               (name == "connectivity" || name == "offsets" || name == "types")) {
      std::vector<long long> vals;
      doc.numbers(a, "an integer", [&](double v) {
        vals.push_back(static_cast<long long>(v));
        return integral(v) && v >= 0;
      });
      if (name == "connectivity") {
        have_conn = true;
        g.conn = std::move(vals);
      } else if (name == "offsets") {
        have_offsets = true;
        if (static_cast<long long>(vals.size()) != nc)
          doc.fail(a, "offsets has " + std::to_string(vals.size()) + " values for " +
                          std::to_string(nc) + " cells");
        g.offsets = {0};
        for (long long o : vals) {
          if (o < g.offsets.back()) doc.fail(a, "offsets must not decrease");
          g.offsets.push_back(o);
        }
      } else {
        have_types = true;
        if (static_cast<long long>(vals.size()) != nc)
          doc.fail(a, "types has " + std::to_string(vals.size()) + " values for " +
                          std::to_string(nc) + " cells");
        g.types = std::move(vals);
      }
    } else {
      std::vector<double> vals;
      doc.numbers(a, "a data value", [&](double v) {
        vals.push_back(v);
        return true;
      });
      const long long n = section == "CellData" ? nc : np;
      if (static_cast<long long>(vals.size()) != n * ncomp)
        doc.fail(a, "array '" + name.substr(0, 40) + "' has " + std::to_string(vals.size()) +
                        " values, expected " + std::to_string(n * ncomp));
      if (section == "CellData" && ncomp == 1) g.cell_arrays.emplace_back(name, std::move(vals));
    }
  }
  if (!have_points) doc.fail(piece, "no points array");
  if (!have_conn || !have_offsets || !have_types) doc.fail(piece, "incomplete <Cells>");
  if (!g.offsets.empty() && g.offsets.back() != static_cast<long long>(g.conn.size()))
    doc.fail(piece.child("Cells"), "the last offset differs from the connectivity size");
  return grid_to_mesh(g, path, fields);
}

}  // namespace cvtmesh
