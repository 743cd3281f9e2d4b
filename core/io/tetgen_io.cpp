#include "core/io/tetgen_io.h"

#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "core/io/finish_mesh.h"
#include "core/io/read_mesh.h"
#include "core/io/text_reader.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

constexpr long long kMaxInt = std::numeric_limits<int>::max();

// An output file written with stdio; every write is checked when the file is closed.
class OutFile {
 public:
  explicit OutFile(const std::string& path) : path_(path), f_(std::fopen(path.c_str(), "w")) {
    if (!f_) throw OutputError("cannot write '" + path + "': cannot create the file");
  }
  ~OutFile() {
    if (f_) std::fclose(f_);
  }
  std::FILE* get() { return f_; }
  void close() {
    const bool bad = std::ferror(f_) != 0;
    const int rc = std::fclose(f_);
    f_ = nullptr;
    if (bad || rc != 0) throw OutputError("cannot write '" + path_ + "': write error (disk full?)");
  }

 private:
  std::string path_;
  std::FILE* f_;
};

bool exists(const std::string& p) {
  struct stat st;
  return stat(p.c_str(), &st) == 0;
}

// Region tag from a TetGen attribute (a double that must hold an integer).
int region_from_attribute(TextReader& in, double a) {
  if (a != std::floor(a) || std::fabs(a) > 2e9)
    in.fail("the region attribute " + std::to_string(a) + " is not an integer tag");
  return static_cast<int>(a);
}

// The index of record i (from 0) of a .node or .ele list: the first sets the numbering's base
// (0 or 1), each next one must follow it. `what` names the records ("point", "element"),
// `an_index` the value read ("a point index").
void read_record_index(TextReader& in, const std::string& what, const std::string& an_index,
                       long long i, long long& base) {
  const long long idx = in.integer(an_index, 0, kMaxInt);
  if (i == 0) {
    if (idx > 1) in.fail("the first " + what + " index must be 0 or 1, got " + std::to_string(idx));
    base = idx;
  } else if (idx != base + i) {
    in.fail(what + " index " + std::to_string(idx) + " out of sequence (expected " +
            std::to_string(base + i) + ")");
  }
}

}  // namespace

TetgenFiles tetgen_files(const std::string& path, int dim) {
  const std::string ext = file_extension(path);
  std::string base = path;
  if (ext == ".node" || ext == ".ele" || ext == ".face" || ext == ".edge")
    base = path.substr(0, path.size() - ext.size());
  return {base + ".node", base + ".ele", base + (dim == 2 ? ".edge" : ".face")};
}

void write_tetgen(const MeshData& data, const TetgenFiles& files,
                  const std::vector<ElementField>& fields) {
  const int dim = data.dim;
  const int nv = dim == 3 ? data.tet.nb_vertices() : data.tri.nb_vertices();
  {
    OutFile f(files.node);
    std::fprintf(f.get(), "# written by cvtmesh: <#points> <dimension> <#attributes> <#markers>\n");
    std::fprintf(f.get(), "%d %d 0 0\n", nv, dim);
    for (int v = 0; v < nv; ++v) {
      if (dim == 3) {
        const double* p = data.tet.point(v);
        std::fprintf(f.get(), "%d %.17g %.17g %.17g\n", v + 1, p[0], p[1], p[2]);
      } else {
        const double* p = data.tri.point(v);
        std::fprintf(f.get(), "%d %.17g %.17g\n", v + 1, p[0], p[1]);
      }
    }
    f.close();
  }
  const std::vector<int>& cells = dim == 3 ? data.tet.tets : data.tri.tris;
  const std::vector<int>& region = dim == 3 ? data.tet.tet_region : data.tri.tri_region;
  const int npe = dim + 1;
  long nb_live = 0;
  for (std::size_t e = 0; e < region.size(); ++e) nb_live += cells[npe * e] >= 0;
  for (const auto& fld : fields)
    if (static_cast<long>(fld.values.size()) != nb_live)
      throw InvariantError("write_tetgen: field '" + fld.name + "' has " +
                           std::to_string(fld.values.size()) + " values for " +
                           std::to_string(nb_live) + " elements");
  {
    OutFile f(files.ele);
    std::fprintf(f.get(), "# written by cvtmesh: <#elements> <nodes per element> <#attributes>\n");
    std::fprintf(f.get(), "# attribute 1: region");
    for (std::size_t k = 0; k < fields.size(); ++k)
      std::fprintf(f.get(), ", %zu: %s", k + 2, fields[k].name.c_str());
    std::fprintf(f.get(), "\n%ld %d %zu\n", nb_live, npe, fields.size() + 1);
    long i = 0;
    for (std::size_t e = 0; e < region.size(); ++e) {
      if (cells[npe * e] < 0) continue;
      std::fprintf(f.get(), "%ld", i + 1);
      for (int k = 0; k < npe; ++k) std::fprintf(f.get(), " %d", cells[npe * e + k] + 1);
      std::fprintf(f.get(), " %d", region[e]);
      for (const auto& fld : fields) std::fprintf(f.get(), " %.17g", fld.values[i]);
      std::fprintf(f.get(), "\n");
      ++i;
    }
    f.close();
  }
  {
    OutFile f(files.facets);
    const std::vector<int>& facets = dim == 3 ? data.tet.tris : data.tri.edges;
    const std::vector<int>& tags = dim == 3 ? data.tet.tri_surface : data.tri.edge_curve;
    std::fprintf(f.get(), "# written by cvtmesh: <#%s> <#markers>\n", dim == 3 ? "faces" : "edges");
    std::fprintf(f.get(), "%zu 1\n", tags.size());
    for (std::size_t e = 0; e < tags.size(); ++e) {
      std::fprintf(f.get(), "%zu", e + 1);
      for (int k = 0; k < dim; ++k) std::fprintf(f.get(), " %d", facets[dim * e + k] + 1);
      std::fprintf(f.get(), " %d\n", tags[e]);
    }
    f.close();
  }
}

MeshData read_tetgen(const std::string& path) {
  const TetgenFiles guess = tetgen_files(path, 3);
  if (!exists(guess.node))
    throw InputError("cannot read '" + path + "': a TetGen mesh needs '" + guess.node +
                     "', which does not exist");
  if (!exists(guess.ele))
    throw InputError("cannot read '" + path + "': a TetGen mesh needs '" + guess.ele +
                     "', which does not exist");
  MeshData data;
  // .node: <#points> <dimension> <#attributes> <#boundary markers>, then
  //        <index> <x> <y> [<z>] [attributes] [marker]
  TextReader node(guess.node);
  const long long nv = node.integer("the number of points", 0, kMaxInt);
  if (nv == 0)
    node.fail("the number of points is 0 (a .node file that refers to a .poly is not supported)");
  const int dim = static_cast<int>(node.integer("the dimension", 2, 3));
  const long long nattr = node.integer("the number of point attributes", 0, 1000);
  const long long nmark = node.integer("the number of boundary markers", 0, 1);
  node.check_count(nv, 1 + dim + static_cast<int>(nattr + nmark), "points");
  data.dim = dim;
  std::vector<double> coords;
  coords.reserve(static_cast<std::size_t>(nv) * dim);
  long long base = 0;
  for (long long i = 0; i < nv; ++i) {
    read_record_index(node, "point", "a point index", i, base);
    for (int k = 0; k < dim; ++k) coords.push_back(node.real("a coordinate"));
    for (long long k = 0; k < nattr + nmark; ++k) node.real("a point attribute or marker", false);
  }
  if (!node.at_end()) node.fail("unexpected data after the " + std::to_string(nv) + " points");

  // .ele: <#elements> <nodes per element> <#attributes>, then <index> <nodes> [attributes]
  TextReader ele(guess.ele);
  const long long ne = ele.integer("the number of elements", 0, kMaxInt);
  const long long npe = ele.integer("the number of nodes per element", 1, 100);
  const int want = dim + 1;
  if (npe != want) {
    if ((dim == 3 && npe == 10) || (dim == 2 && npe == 6))
      ele.fail("second-order elements are not supported (cvtmesh optimizes linear simplices)");
    ele.fail(std::to_string(npe) + " nodes per element; a " + std::to_string(dim) +
             "D mesh needs " + std::to_string(want));
  }
  const long long eattr = ele.integer("the number of element attributes", 0, 1000);
  ele.check_count(ne, 1 + want + static_cast<int>(eattr), "elements");
  std::vector<int> cells, region;
  cells.reserve(static_cast<std::size_t>(ne) * want);
  long long ebase = 0;
  for (long long i = 0; i < ne; ++i) {
    read_record_index(ele, "element", "an element index", i, ebase);
    for (int k = 0; k < want; ++k)
      cells.push_back(static_cast<int>(ele.integer("a point index", base, base + nv - 1) - base));
    int r = 1;
    for (long long k = 0; k < eattr; ++k) {
      const double a = ele.real("an element attribute", k == 0);
      if (k == 0) r = region_from_attribute(ele, a);
    }
    region.push_back(r);
  }
  if (!ele.at_end()) ele.fail("unexpected data after the " + std::to_string(ne) + " elements");

  // .face / .edge (optional): <#facets> <#markers>, then <index> <nodes> [marker]
  const TetgenFiles files = tetgen_files(path, dim);
  std::vector<int> facets, marker;
  if (exists(files.facets)) {
    TextReader fac(files.facets);
    const long long nf = fac.integer("the number of facets", 0, kMaxInt);
    const long long fmark = fac.integer("the number of boundary markers", 0, 1);
    fac.check_count(nf, 1 + dim + static_cast<int>(fmark), "facets");
    for (long long i = 0; i < nf; ++i) {
      fac.integer("a facet index", 0, kMaxInt);
      for (int k = 0; k < dim; ++k)
        facets.push_back(
            static_cast<int>(fac.integer("a point index", base, base + nv - 1) - base));
      marker.push_back(fmark ? static_cast<int>(fac.integer("a boundary marker", -kMaxInt, kMaxInt))
                             : 0);
      // TetGen may append the two adjacent tetrahedra (-nn); skip anything to the end of line.
      fac.rest_of_line();
    }
    if (!fac.at_end()) fac.fail("unexpected data after the " + std::to_string(nf) + " facets");
  }

  if (dim == 3) {
    data.tet.xyz = std::move(coords);
    data.tet.tets = std::move(cells);
    data.tet.tet_region = std::move(region);
    data.tet.tris = std::move(facets);
    data.tet.tri_surface = std::move(marker);
  } else {
    data.tri.xy = std::move(coords);
    data.tri.tris = std::move(cells);
    data.tri.tri_region = std::move(region);
    data.tri.edges = std::move(facets);
    data.tri.edge_curve = std::move(marker);
  }
  data.model().name = std::filesystem::path(guess.node).stem().string();
  finish_mesh(data, "'" + path + "'");
  return data;
}

}  // namespace cvtmesh
