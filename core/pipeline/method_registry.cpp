#include "core/pipeline/method_registry.h"

#include "core/pipeline/methods3.h"

namespace cvtmesh {

const std::vector<MethodInfo>& method_registry() {
  static const std::vector<MethodInfo> m = {
      {"cvdt+swap+smooth", 3, run_cvdt_swap_smooth3,
       "CVDT, SWAP, then the polish: guarded Laplacian + max-min smoothing of the poor tets + "
       "dihedral flips, ended by the repair of the slivers left (may add interior vertices)"},
      {"cvdt+swap", 3, run_cvdt_swap3,
       "the paper's CVDT+SWAP: Lloyd to a centroidal Voronoi-Delaunay triangulation, then sliver "
       "removal by flips raising the local minimum Q"},
      {"cvdt", 3, run_cvdt3, "Lloyd's iteration to a CVDT only"},
      {"combined", 3, run_combined3,
       "the classical combined optimization (CombOpt): 3 guarded Laplacian passes + flips "
       "improving the minimal dihedral angle, iterated"},
      {"swap", 3, run_swap3, "the SWAP flips only (no vertex moves)"},
      {"smooth", 3, run_polish3, "the polish of cvdt+swap+smooth alone"},
      {"cvdt", 2, nullptr, "Lloyd's iteration to a CVDT (constrained Delaunay retriangulation)"},
      {"cvdt+swap", 2, nullptr, "the CVDT, then a quality edge-flip pass"},
      {"dl", 2, nullptr, "the classical DL: Laplacian smoothing + Delaunay flips"},
      {"wdl", 2, nullptr, "the classical WDL: edge-length-weighted Laplacian + Delaunay flips"},
  };
  return m;
}

const MethodInfo* find_method(const std::string& name, int dim) {
  for (const MethodInfo& m : method_registry())
    if (m.dim == dim && m.name == name) return &m;
  return nullptr;
}

std::vector<std::string> methods_for_dim(int dim) {
  std::vector<std::string> out;
  for (const MethodInfo& m : method_registry())
    if (m.dim == dim) out.push_back(m.name);
  return out;
}

std::string default_method(int dim) {
  for (const MethodInfo& m : method_registry())
    if (m.dim == dim) return m.name;
  return "";
}

std::string methods_help(int dim) {
  std::string s;
  for (int d : {3, 2}) {
    if (dim != 0 && d != dim) continue;
    for (const MethodInfo& m : method_registry())
      if (m.dim == d)
        s += "  " + m.name + " (" + std::to_string(d) + "D" +
             (m.name == default_method(d) ? ", default" : "") + "): " + m.help + "\n";
  }
  return s;
}

}  // namespace cvtmesh
