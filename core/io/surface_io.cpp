#include "core/mesh/check_surface_mesh.h"
#include "core/io/surface_io.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cmath>
#include <exception>
#include <sstream>

#include "core/io/read_mesh.h"
#include "core/io/read_surface_coordinates.h"
#include "core/mesh/build_adjacency.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

struct Traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OMesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;

// Redirects OpenMesh's error and log streams (std::cerr by default: core/ never prints) into a
// string for the duration of a read or write.
class OpenMeshMessages {
 public:
  OpenMeshMessages() {
    err_was_ = omerr().is_enabled();
    log_was_ = omlog().is_enabled();
    out_was_ = omout().is_enabled();
    omerr().disconnect(std::cerr);
    omerr().connect(buf_);
    omlog().disable();
    omout().disable();
  }
  ~OpenMeshMessages() {
    omerr().flush();
    omerr().disconnect(buf_);
    omerr().connect(std::cerr);
    if (!err_was_) omerr().disable();
    if (log_was_) omlog().enable();
    if (out_was_) omout().enable();
  }
  std::string text() {
    omerr().flush();
    std::string s = buf_.str();
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    for (char& c : s)
      if (c == '\n') c = ';';
    return s;
  }

 private:
  std::ostringstream buf_;
  bool err_was_ = true, log_was_ = true, out_was_ = true;
};

}  // namespace

SurfaceMesh used_surface(const std::vector<double>& xyz, const std::vector<int>& tris) {
  SurfaceMesh s;
  std::vector<int> id(xyz.size() / 3, -1);
  for (int v : tris) {
    if (id[v] < 0) {
      id[v] = static_cast<int>(s.xyz.size() / 3);
      s.xyz.insert(s.xyz.end(), &xyz[3 * v], &xyz[3 * v] + 3);
    }
    s.tris.push_back(id[v]);
  }
  return s;
}

void throw_surface_only(const std::string& what, const std::vector<double>& xyz,
                        const std::vector<int>& tris) {
  const long long nv = static_cast<long long>(xyz.size() / 3);
  for (int v : tris)
    if (v < 0 || v >= nv)
      throw InputError(what + ": a triangle refers to vertex " + std::to_string(v + 1) +
                       ", which does not exist (" + std::to_string(nv) + " vertices)");
  throw SurfaceOnlyInput(what +
                             " has no tetrahedra and its triangles are not in a plane z = const "
                             "(a surface mesh that bounds no volume cannot be optimized as 2D or "
                             "3D)",
                         used_surface(xyz, tris));
}

SurfaceMesh boundary_surface(const MeshData& data) {
  SurfaceMesh s;
  std::vector<int> faces;
  std::vector<double> coords;
  int nv = 0;
  if (data.dim == 3 && is_surface_mesh(data.tet)) {
    // A surface mesh in space: its triangles as they turn.
    const TetMesh& m = data.tet;
    for (int f = 0; f < m.nb_tris(); ++f)
      if (m.tris[3 * f] >= 0) faces.insert(faces.end(), &m.tris[3 * f], &m.tris[3 * f] + 3);
    coords = m.xyz;
    nv = m.nb_vertices();
  } else if (data.dim == 3) {
    const TetMesh* m = &data.tet;
    TetMesh copy;
    if (m->adj.size() != m->tets.size()) {
      copy = *m;
      build_adjacency(copy);
      m = &copy;
    }
    for (int t = 0; t < m->nb_tets(); ++t) {
      if (m->tets[4 * t] < 0) continue;
      for (int f = 0; f < 4; ++f)
        if (m->adj[4 * t + f] < 0)
          for (int k = 0; k < 3; ++k) faces.push_back(m->tets[4 * t + kTetFace[f][k]]);
    }
    coords = m->xyz;
    nv = m->nb_vertices();
  } else {
    const TriMesh2& m = data.tri;
    for (int t = 0; t < m.nb_tris(); ++t)
      if (m.tris[3 * t] >= 0) faces.insert(faces.end(), &m.tris[3 * t], &m.tris[3 * t] + 3);
    nv = m.nb_vertices();
    for (int v = 0; v < nv; ++v) coords.insert(coords.end(), {m.point(v)[0], m.point(v)[1], m.z0});
  }
  std::vector<int> map(nv, -1);
  for (int& v : faces) {
    if (map[v] < 0) {
      map[v] = static_cast<int>(s.xyz.size() / 3);
      s.xyz.insert(s.xyz.end(), &coords[3 * v], &coords[3 * v] + 3);
    }
    v = map[v];
  }
  s.tris = std::move(faces);
  return s;
}

void write_surface(const MeshData& data, const std::string& path) {
  const SurfaceMesh s = boundary_surface(data);
  OpenMeshMessages messages;
  OMesh mesh;
  std::vector<OMesh::VertexHandle> vh;
  for (std::size_t v = 0; v < s.xyz.size() / 3; ++v)
    vh.push_back(mesh.add_vertex(OMesh::Point(s.xyz[3 * v], s.xyz[3 * v + 1], s.xyz[3 * v + 2])));
  for (std::size_t f = 0; f < s.tris.size() / 3; ++f) {
    const auto fh = mesh.add_face(vh[s.tris[3 * f]], vh[s.tris[3 * f + 1]], vh[s.tris[3 * f + 2]]);
    if (!fh.is_valid())
      throw InputError("cannot write '" + path +
                       "': the boundary surface is non-manifold (an edge or vertex is shared by "
                       "separate sheets), which " +
                       "this surface format cannot hold");
  }
  // STL: binary (OpenMesh's ASCII STL has blank lines that Gmsh's reader miscounts), with face
  // normals. The other formats: ASCII. (OpenMesh 9 writes single-precision coordinates.)
  OpenMesh::IO::Options opt;
  if (file_extension(path) == ".stl") {
    mesh.request_face_normals();
    mesh.update_face_normals();
    opt = OpenMesh::IO::Options(OpenMesh::IO::Options::Binary | OpenMesh::IO::Options::FaceNormal);
  }
  bool ok = false;
  try {
    ok = OpenMesh::IO::write_mesh(mesh, path, opt, 17);
  } catch (const std::exception& e) {
    throw OutputError("cannot write '" + path + "': " + e.what());
  }
  if (!ok) {
    const std::string why = messages.text();
    throw OutputError("cannot write '" + path + "'" + (why.empty() ? "" : ": " + why));
  }
}

SurfaceMesh read_surface(const std::string& path, bool require_closed) {
  const std::string what = "'" + path + "'";
  OpenMeshMessages messages;
  OMesh mesh;
  mesh.request_vertex_status();
  mesh.request_edge_status();
  mesh.request_face_status();
  bool ok = false;
  try {
    OpenMesh::IO::Options opt;
    ok = OpenMesh::IO::read_mesh(mesh, path, opt);
  } catch (const std::exception& e) {
    throw InputError("cannot read " + what + ": " + e.what());
  }
  const std::string why = messages.text();
  if (!ok)
    throw InputError("cannot read " + what + ": not a readable surface file" +
                     (why.empty() ? "" : " (" + why + ")"));
  if (why.find("invalid vertex index") != std::string::npos ||
      why.find("equal vertices") != std::string::npos)
    throw InputError("cannot read " + what +
                     ": a face refers to a missing vertex or repeats one (" + why + ")");
  if (mesh.n_faces() == 0) throw InputError(what + " contains no triangles");
  long nonmanifold = 0;
  for (const auto f : mesh.faces()) nonmanifold += mesh.status(f).fixed_nonmanifold();
  if (nonmanifold)
    throw InputError(what + ": the surface is non-manifold or inconsistently oriented (" +
                     std::to_string(nonmanifold) +
                     " triangles would share an edge with more than one other triangle on the "
                     "same side); cannot mesh its interior");
  if (require_closed) {
    long open = 0;
    for (const auto e : mesh.edges()) open += mesh.is_boundary(e);
    if (open)
      throw InputError(what + ": the surface is not closed (" + std::to_string(open) +
                       " boundary edges); a volume mesh needs a closed, watertight surface");
  }
  SurfaceMesh s;
  std::vector<int> map(mesh.n_vertices(), -1);
  // Double-precision coordinates where we can read them (ASCII .off / .obj), if they agree with
  // OpenMesh's single-precision ones vertex by vertex.
  std::vector<double> exact = read_surface_coordinates(path);
  if (exact.size() == 3 * mesh.n_vertices()) {
    for (const auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      for (int k = 0; k < 3; ++k) {
        const double e = exact[3 * v.idx() + k];
        if (!(std::abs(e - p[k]) <= 1e-6 * (1 + std::abs(e)))) exact.clear();
      }
      if (exact.empty()) break;
    }
  } else {
    exact.clear();
  }
  for (const auto f : mesh.faces()) {
    for (const auto v : mesh.fv_range(f)) {
      int& id = map[v.idx()];
      if (id < 0) {
        OMesh::Point p = mesh.point(v);
        if (!exact.empty())
          for (int k = 0; k < 3; ++k) p[k] = exact[3 * v.idx() + k];
        for (int k = 0; k < 3; ++k)
          if (!std::isfinite(p[k]))
            throw InputError(what + ": vertex " + std::to_string(v.idx() + 1) +
                             " has a NaN or infinite coordinate");
        id = static_cast<int>(s.xyz.size() / 3);
        s.xyz.insert(s.xyz.end(), {p[0], p[1], p[2]});
      }
      s.tris.push_back(id);
    }
  }
  return s;
}

}  // namespace cvtmesh
