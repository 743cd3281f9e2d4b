#include "core/io/medit_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>

#include "core/geometry/z_range.h"
#include "core/io/finish_mesh.h"
#include "core/io/surface_io.h"
#include "core/io/text_reader.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

constexpr long long kMaxInt = std::numeric_limits<int>::max();

std::string lower(std::string_view s) {
  std::string r(s);
  std::transform(r.begin(), r.end(), r.begin(), [](unsigned char c) { return std::tolower(c); });
  return r;
}

}  // namespace

void write_medit(const MeshData& data, const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw OutputError("cannot write '" + path + "': cannot create the file");
  std::fprintf(f, "MeshVersionFormatted 2\n\nDimension %d\n\n", data.dim);
  if (data.dim == 3) {
    const TetMesh& m = data.tet;
    std::fprintf(f, "Vertices\n%d\n", m.nb_vertices());
    for (int v = 0; v < m.nb_vertices(); ++v)
      std::fprintf(f, "%.17g %.17g %.17g 0\n", m.point(v)[0], m.point(v)[1], m.point(v)[2]);
    std::fprintf(f, "\nTriangles\n%d\n", m.nb_tris());
    for (int t = 0; t < m.nb_tris(); ++t)
      std::fprintf(f, "%d %d %d %d\n", m.tris[3 * t] + 1, m.tris[3 * t + 1] + 1,
                   m.tris[3 * t + 2] + 1, m.tri_surface[t]);
    // The Edges the input .mesh had (blocks with Medit references), as they were.
    long nb_edges = 0;
    for (const ElementBlock& b : m.model.extra) nb_edges += static_cast<long>(b.medit_refs.size());
    if (nb_edges) {
      std::fprintf(f, "\nEdges\n%ld\n", nb_edges);
      for (const ElementBlock& b : m.model.extra)
        for (std::size_t e = 0; e < b.medit_refs.size(); ++e)
          std::fprintf(f, "%d %d %d\n", b.nodes[2 * e] + 1, b.nodes[2 * e + 1] + 1,
                       b.medit_refs[e]);
    }
    long live = 0;
    for (int t = 0; t < m.nb_tets(); ++t) live += m.tets[4 * t] >= 0;
    std::fprintf(f, "\nTetrahedra\n%ld\n", live);
    for (int t = 0; t < m.nb_tets(); ++t)
      if (m.tets[4 * t] >= 0)
        std::fprintf(f, "%d %d %d %d %d\n", m.tets[4 * t] + 1, m.tets[4 * t + 1] + 1,
                     m.tets[4 * t + 2] + 1, m.tets[4 * t + 3] + 1, m.tet_region[t]);
  } else {
    const TriMesh2& m = data.tri;
    std::fprintf(f, "Vertices\n%d\n", m.nb_vertices());
    for (int v = 0; v < m.nb_vertices(); ++v)
      std::fprintf(f, "%.17g %.17g 0\n", m.point(v)[0], m.point(v)[1]);
    std::fprintf(f, "\nEdges\n%d\n", m.nb_edges());
    for (int e = 0; e < m.nb_edges(); ++e)
      std::fprintf(f, "%d %d %d\n", m.edges[2 * e] + 1, m.edges[2 * e + 1] + 1, m.edge_curve[e]);
    long live = 0;
    for (int t = 0; t < m.nb_tris(); ++t) live += m.tris[3 * t] >= 0;
    std::fprintf(f, "\nTriangles\n%ld\n", live);
    for (int t = 0; t < m.nb_tris(); ++t)
      if (m.tris[3 * t] >= 0)
        std::fprintf(f, "%d %d %d %d\n", m.tris[3 * t] + 1, m.tris[3 * t + 1] + 1,
                     m.tris[3 * t + 2] + 1, m.tri_region[t]);
  }
  std::fprintf(f, "\nEnd\n");
  const bool bad = std::ferror(f) != 0;
  if (std::fclose(f) != 0 || bad)
    throw OutputError("cannot write '" + path + "': write error (disk full?)");
}

MeshData read_medit(const std::string& path) {
  TextReader in(path);
  int dim = 0;
  long long nv = -1;
  std::vector<double> xyz;  // dim coordinates per vertex
  std::vector<int> edges, edge_ref, tris, tri_ref, tets, tet_ref;
  bool have_edges = false, have_tris = false, have_tets = false;
  // Sections we skip: keyword -> (integers, reals) per entry (reals are multiplied by dim).
  static const std::map<std::string, std::pair<int, int>> kSkip = {
      {"corners", {1, 0}},
      {"ridges", {1, 0}},
      {"requiredvertices", {1, 0}},
      {"requirededges", {1, 0}},
      {"requiredtriangles", {1, 0}},
      {"requiredtetrahedra", {1, 0}},
      {"normals", {0, 1}},
      {"tangents", {0, 1}},
      {"normalatvertices", {2, 0}},
      {"tangentatvertices", {2, 0}},
      {"normalattrianglevertices", {3, 0}}};
  static const char* kUnsupported[] = {"quadrilaterals", "hexahedra",        "prisms",
                                       "pyramids",       "edgesp2",          "trianglesp2",
                                       "tetrahedrap2",   "quadrilateralsq2", "hexahedraq2"};
  bool first = true;
  while (!in.at_end()) {
    const std::string kw = lower(in.token("a keyword"));
    if (first && kw != "meshversionformatted") {
      if (kw == "meshversionunformatted") in.fail("binary Medit files are not supported");
      in.fail("not a Medit .mesh file: expected 'MeshVersionFormatted', got '" + kw.substr(0, 40) +
              "'");
    }
    first = false;
    if (kw == "meshversionformatted") {
      in.integer("the mesh version", 1, 4);
    } else if (kw == "dimension") {
      if (dim) in.fail("'Dimension' given twice");
      dim = static_cast<int>(in.integer("the dimension", 2, 3));
    } else if (kw == "end") {
      break;
    } else if (kw == "vertices" || kw == "edges" || kw == "triangles" || kw == "tetrahedra") {
      if (!dim) in.fail("'" + kw + "' before 'Dimension'");
      const long long n = in.integer("the number of " + kw, 0, kMaxInt);
      if (kw == "vertices") {
        if (nv >= 0) in.fail("'Vertices' given twice");
        in.check_count(n, dim + 1, "vertices");
        nv = n;
        xyz.reserve(static_cast<std::size_t>(n) * dim);
        for (long long i = 0; i < n; ++i) {
          for (int k = 0; k < dim; ++k) xyz.push_back(in.real("a vertex coordinate"));
          in.integer("a vertex reference", -kMaxInt, kMaxInt);
        }
        continue;
      }
      const int npe = kw == "edges" ? 2 : kw == "triangles" ? 3 : 4;
      bool& have = kw == "edges" ? have_edges : kw == "triangles" ? have_tris : have_tets;
      if (have) in.fail("'" + kw + "' given twice");
      have = true;
      if (kw == "tetrahedra" && dim == 2) in.fail("tetrahedra in a 2D (Dimension 2) mesh");
      std::vector<int>& conn = kw == "edges" ? edges : kw == "triangles" ? tris : tets;
      std::vector<int>& ref = kw == "edges" ? edge_ref : kw == "triangles" ? tri_ref : tet_ref;
      in.check_count(n, npe + 1, kw);
      const long long hi = nv >= 0 ? nv : kMaxInt;
      for (long long i = 0; i < n; ++i) {
        for (int k = 0; k < npe; ++k)
          conn.push_back(static_cast<int>(in.integer("a vertex index", 1, hi) - 1));
        ref.push_back(static_cast<int>(in.integer("a reference", -kMaxInt, kMaxInt)));
      }
    } else if (auto it = kSkip.find(kw); it != kSkip.end()) {
      if (!dim) in.fail("'" + kw + "' before 'Dimension'");
      const long long n = in.integer("the number of entries", 0, kMaxInt);
      const int ni = it->second.first, nr = it->second.second * dim;
      in.check_count(n, ni + nr, kw);
      for (long long i = 0; i < n; ++i) {
        for (int k = 0; k < ni; ++k) in.integer("an index", -kMaxInt, kMaxInt);
        for (int k = 0; k < nr; ++k) in.real("a number", false);
      }
    } else {
      for (const char* u : kUnsupported)
        if (kw == u)
          in.fail("unsupported element type '" + kw +
                  "' (cvtmesh optimizes linear triangles and tetrahedra only)");
      in.fail("unknown keyword '" + kw.substr(0, 40) + "'");
    }
  }
  if (first) in.fail("not a Medit .mesh file");
  if (!dim) in.fail("no 'Dimension' in the file");
  if (nv < 0) in.fail("no 'Vertices' in the file");
  const std::string what = "'" + path + "'";
  // Element indices given before the vertices are checked by finish_mesh.
  MeshData data;
  const std::string name = std::filesystem::path(path).stem().string();
  std::vector<int> edges3, edge_ref3;  // 3D Edges: kept as line blocks after finish_mesh
  if (dim == 3 && !tets.empty()) {
    for (int v : edges)
      if (v >= nv)
        throw InputError(what + ": an edge refers to vertex " + std::to_string(v + 1) +
                         ", which does not exist (" + std::to_string(nv) + " vertices)");
    edges3 = std::move(edges);
    edge_ref3 = std::move(edge_ref);
    data.dim = 3;
    data.tet.xyz = std::move(xyz);
    data.tet.tets = std::move(tets);
    data.tet.tet_region = std::move(tet_ref);
    data.tet.tris = std::move(tris);
    data.tet.tri_surface = std::move(tri_ref);
    data.tet.model.name = name;
  } else {
    if (tris.empty()) throw InputError(what + " has no tetrahedra and no triangles (empty mesh)");
    data.dim = 2;
    TriMesh2& m = data.tri;
    if (dim == 3) {
      // A triangle mesh in space: accepted as 2D if it lies in a plane z = const.
      const ZRange zr = z_range(xyz, &tris);  // out-of-range ids are reported by finish_mesh
      const double zmin = zr.zmin;
      if (!zr.planar) {
        throw_surface_only(what, xyz, tris);
      }
      m.z0 = zmin;
      for (long long v = 0; v < nv; ++v) m.xy.insert(m.xy.end(), {xyz[3 * v], xyz[3 * v + 1]});
    } else {
      m.xy = std::move(xyz);
    }
    m.tris = std::move(tris);
    m.tri_region = std::move(tri_ref);
    m.edges = std::move(edges);
    m.edge_curve = std::move(edge_ref);
    m.model.name = name;
  }
  // The vertex ids finish_mesh gives: the vertices the tets use, in order.
  std::vector<int> renumber(edges3.empty() ? 0 : nv, -1);
  if (!edges3.empty()) {
    for (int v : data.tet.tets) renumber[v] = 0;
    int k = 0;
    for (int& r : renumber)
      if (r == 0) r = k++;
  }
  finish_mesh(data, what);
  if (!edges3.empty()) {
    // One line block per reference, on a curve entity of its own, kept unchanged (its vertices
    // are the tet mesh's: the boundary ones move only as the boundary does).
    ModelInfo& info = data.tet.model;
    int tag = 0;
    for (const ModelEntity& e : info.entities)
      if (e.dim == 1) tag = std::max(tag, e.tag);
    std::map<int, ElementBlock> by_ref;
    for (std::size_t e = 0; e < edge_ref3.size(); ++e) {
      ElementBlock& b = by_ref[edge_ref3[e]];
      for (int k = 0; k < 2; ++k) {
        const int v = renumber[edges3[2 * e + k]];
        if (v < 0)
          throw InputError(what + ": edge " + std::to_string(e + 1) + " uses vertex " +
                           std::to_string(edges3[2 * e + k] + 1) +
                           ", which no tetrahedron uses (cannot keep it)");
        b.nodes.push_back(v);
      }
      b.medit_refs.push_back(edge_ref3[e]);
      b.tags.push_back(0);
    }
    for (auto& [ref, b] : by_ref) {
      b.dim = 1;
      b.entity = ++tag;
      b.gmsh_type = 1;
      info.entities.push_back({1, tag, {}});
      info.extra.push_back(std::move(b));
    }
  }
  return data;
}

}  // namespace cvtmesh
