#include "core/io/gmsh_surface.h"

#include <gmsh.h>

#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>

#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"
#include "core/mesh/face_key.h"
#include "core/util/error.h"

namespace cvtmesh {

std::vector<int> shells_of(const SurfaceMesh& s, int& nb_shells) {
  const int nf = static_cast<int>(s.tris.size() / 3);
  std::vector<int> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::unordered_map<EdgeKey, int, EdgeKeyHash> first;
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const EdgeKey e = edge_key(s.tris[3 * f + k], s.tris[3 * f + (k + 1) % 3]);
      auto [it, fresh] = first.emplace(e, f);
      if (!fresh) parent[find(f)] = find(it->second);
    }
  std::map<int, int> id;
  std::vector<int> shell(nf);
  for (int f = 0; f < nf; ++f)
    shell[f] = id.emplace(find(f), static_cast<int>(id.size())).first->second;
  nb_shells = static_cast<int>(id.size());
  return shell;
}

namespace {

// Winding number of the closed shell `sh` around point p (solid angles, van Oosterom-Strackee).
double winding(const SurfaceMesh& s, const std::vector<int>& shell, int sh, const double* p) {
  double total = 0;
  for (std::size_t f = 0; f < shell.size(); ++f) {
    if (shell[f] != sh) continue;
    double a[3], b[3], c[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = s.xyz[3 * s.tris[3 * f] + k] - p[k];
      b[k] = s.xyz[3 * s.tris[3 * f + 1] + k] - p[k];
      c[k] = s.xyz[3 * s.tris[3 * f + 2] + k] - p[k];
    }
    const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    const double lc = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    const double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                       a[2] * (b[0] * c[1] - b[1] * c[0]);
    const double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const double ac = a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
    const double bc = b[0] * c[0] + b[1] * c[1] + b[2] * c[2];
    total += 2 * std::atan2(det, la * lb * lc + ab * lc + ac * lb + bc * la);
  }
  return total / (4 * M_PI);
}

}  // namespace

bool surface_closes_up(const SurfaceMesh& s) {
  std::unordered_map<EdgeKey, int, EdgeKeyHash> count;
  for (std::size_t f = 0; f < s.tris.size() / 3; ++f)
    for (int k = 0; k < 3; ++k) ++count[edge_key(s.tris[3 * f + k], s.tris[3 * f + (k + 1) % 3])];
  for (const auto& [e, c] : count)
    if (c % 2) return false;
  return !count.empty();
}

void orient_shells(SurfaceMesh& s) {
  const std::size_t nf = s.tris.size() / 3;
  std::unordered_map<EdgeKey, std::vector<int>, EdgeKeyHash> faces_of;
  for (std::size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      faces_of[edge_key(s.tris[3 * f + k], s.tris[3 * f + (k + 1) % 3])].push_back(
          static_cast<int>(f));
  auto runs = [&](int f, int a, int b) {  // does triangle f run a -> b?
    for (int k = 0; k < 3; ++k)
      if (s.tris[3 * f + k] == a && s.tris[3 * f + (k + 1) % 3] == b) return true;
    return false;
  };
  std::vector<char> seen(nf, 0);
  std::vector<int> queue;
  for (std::size_t start = 0; start < nf; ++start) {
    if (seen[start]) continue;
    seen[start] = 1;
    queue.assign(1, static_cast<int>(start));
    while (!queue.empty()) {
      const int f = queue.back();
      queue.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int a = s.tris[3 * f + k], b = s.tris[3 * f + (k + 1) % 3];
        for (int g : faces_of[edge_key(a, b)]) {
          if (seen[g]) continue;
          seen[g] = 1;
          if (runs(g, a, b)) std::swap(s.tris[3 * g + 1], s.tris[3 * g + 2]);
          queue.push_back(g);
        }
      }
    }
  }
}

void nest_shells(const SurfaceMesh& surface, const std::vector<int>& shell, int nb,
                 std::vector<int>& depth, std::vector<int>& parent) {
  depth.assign(nb, 0);
  parent.assign(nb, -1);
  std::vector<const double*> probe(nb, nullptr);
  for (std::size_t f = 0; f < shell.size(); ++f)
    if (!probe[shell[f]]) probe[shell[f]] = &surface.xyz[3 * surface.tris[3 * f]];
  for (int a = 0; a < nb; ++a)
    for (int b = 0; b < nb; ++b)
      if (a != b && std::fabs(winding(surface, shell, b, probe[a])) > 0.5) ++depth[a];
  for (int a = 0; a < nb; ++a)  // the innermost shell containing a: depth one less
    for (int b = 0; b < nb; ++b)
      if (a != b && depth[b] == depth[a] - 1 &&
          std::fabs(winding(surface, shell, b, probe[a])) > 0.5)
        parent[a] = b;
}

void generate_volumes(const ReadOptions& options) {
  gmsh::option::setNumber("General.NumThreads", 1);
  if (!options.gmsh_optimize) gmsh::option::setNumber("Mesh.Optimize", 0);
  if (options.mesh_size_factor > 0)
    gmsh::option::setNumber("Mesh.MeshSizeFactor", options.mesh_size_factor);
  gmsh::option::setNumber("Mesh.RandomSeed", options.seed);
  gmsh::model::mesh::generate(3);
}

MeshData tetrahedralize_surface(const SurfaceMesh& surface, const std::string& what,
                                const ReadOptions& options) {
  if (surface.tris.empty()) throw InputError(what + " contains no triangles");
  GmshSession session;
  std::string previous;
  gmsh::model::getCurrent(previous);
  MeshData data;
  try {
    gmsh_checked("cannot mesh the volume inside " + what, [&] {
      gmsh::model::add("cvtmesh_surface_volume");
      // One discrete surface per shell (connected component). A shell inside an odd number of
      // others is a cavity of the innermost shell around it; the others bound a volume each.
      int nb = 0;
      const std::vector<int> shell = shells_of(surface, nb);
      std::vector<int> depth, parent;
      nest_shells(surface, shell, nb, depth, parent);
      for (int sh = 0; sh < nb; ++sh) gmsh::model::addDiscreteEntity(2, sh + 1);
      const std::size_t nv = surface.xyz.size() / 3;
      std::vector<int> node_shell(nv, 0);
      for (std::size_t f = 0; f < shell.size(); ++f)
        for (int k = 0; k < 3; ++k) node_shell[surface.tris[3 * f + k]] = shell[f];
      for (int sh = 0; sh < nb; ++sh) {
        std::vector<std::size_t> node_tags, elem_tags, conn;
        std::vector<double> xyz;
        for (std::size_t i = 0; i < nv; ++i)
          if (node_shell[i] == sh) {
            node_tags.push_back(i + 1);
            xyz.insert(xyz.end(), &surface.xyz[3 * i], &surface.xyz[3 * i] + 3);
          }
        for (std::size_t f = 0; f < shell.size(); ++f)
          if (shell[f] == sh) {
            elem_tags.push_back(f + 1);
            for (int k = 0; k < 3; ++k)
              conn.push_back(static_cast<std::size_t>(surface.tris[3 * f + k]) + 1);
          }
        gmsh::model::mesh::addNodes(2, sh + 1, node_tags, xyz);
        gmsh::model::mesh::addElementsByType(sh + 1, 2, elem_tags, conn);
      }
      int volume = 0;
      for (int sh = 0; sh < nb; ++sh) {
        if (depth[sh] % 2) continue;
        std::vector<int> loops = {gmsh::model::geo::addSurfaceLoop({sh + 1})};
        for (int c = 0; c < nb; ++c)
          if (parent[c] == sh) loops.push_back(gmsh::model::geo::addSurfaceLoop({c + 1}));
        gmsh::model::geo::addVolume(loops, ++volume);
      }
      gmsh::model::geo::synchronize();
      generate_volumes(options);
    });
    data = mesh_from_gmsh(3, what);
  } catch (...) {
    gmsh::model::remove();
    if (!previous.empty() && !session.owns()) gmsh::model::setCurrent(previous);
    throw;
  }
  gmsh::model::remove();
  if (!previous.empty() && !session.owns()) gmsh::model::setCurrent(previous);
  return data;
}

}  // namespace cvtmesh
