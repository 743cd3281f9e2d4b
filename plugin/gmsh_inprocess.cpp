#include "plugin/gmsh_inprocess.h"

#include <gmsh.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/io/gmsh_mid_edge_projector.h"
#include "core/io/place_mid_edge_nodes.h"
#include "core/quality/quality_fields.h"
#include "core/io/gmsh_cad_boundary.h"
#include "core/io/gmsh_missing_facets.h"
#include "core/io/gmsh_model.h"
#include "core/mesh/check_surface_mesh.h"
#include "core/io/gmsh_session.h"
#include "core/io/read_mesh.h"
#include "core/io/read_sizing_reference.h"
#include "core/pipeline/option_schema.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

// Highest dimension of the current model that has mesh elements, -1 if none.
int meshed_dim() {
  gmsh::vectorpair ents;
  gmsh::model::getEntities(ents);
  int d_max = -1;
  for (const auto& [d, t] : ents) {
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, d, t);
    if (!types.empty()) d_max = std::max(d_max, d);
  }
  return d_max;
}

std::string current_model_name() {
  std::string name;
  gmsh::model::getCurrent(name);
  return name.empty() ? "the current Gmsh model" : "the current Gmsh model '" + name + "'";
}

// Removes the views named like ours (quality_view_names).
void remove_quality_views();

}  // namespace

std::vector<std::string> quality_view_names(int dim) {
  MeshData empty;
  empty.dim = dim == 2 ? 2 : 3;
  std::vector<std::string> names;
  for (const auto& f : quality_fields(empty)) names.push_back(f.name);
  return names;
}

std::vector<std::string> our_view_names(bool stale) {
  std::vector<std::string> names = quality_view_names(2);
  for (const auto& n : quality_view_names(3))
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  names.push_back(kHistogramViewName);
  if (stale) {
    const std::size_t n = names.size();
    for (std::size_t i = 0; i < n; ++i) names.push_back(names[i] + kStaleSuffix);
  }
  return names;
}

std::vector<std::size_t> element_tags_of(const MeshData& data) {
  if (data.dim == 2) return data.tri.tri_tags;
  return is_surface_mesh(data.tet) ? data.tet.tri_tags : data.tet.tet_tags;
}

MeshData gmsh_read_current(const GmshOptimizeOptions& options) {
  set_gmsh_initialized_by_caller(true);
  GmshSession session;
  std::string what;
  int have = -1, model_dim = -1;
  gmsh_checked("cannot inspect the current Gmsh model", [&] {
    what = current_model_name();
    have = meshed_dim();
    model_dim = gmsh::model::getDimension();
  });
  if (have < 0) {
    if (model_dim < 1)
      throw InputError(what +
                       " is empty: call gmsh.initialize() and open or build a model "
                       "(gmsh.open(...)) first");
    if (!options.generate)
      throw InputError(what + " has no mesh: generate it first (gmsh.model.mesh.generate(" +
                       std::to_string(model_dim) + ")) or pass generate=True");
    gmsh_checked("cannot mesh " + what, [&] {
      gmsh::model::mesh::generate(options.dim > 0 ? options.dim : model_dim);
      have = meshed_dim();
    });
    if (have < 0) throw InputError("Gmsh could not mesh " + what);
  }
  // A model opened from a .msh saved with physical groups lacks the boundary elements of the
  // surfaces outside every group (and of the interfaces between volumes): restore them, as the
  // CLI's reader does, so that its boundary is closed. They are added to the current model.
  gmsh_checked("cannot restore the boundary elements of " + what,
               [&] { add_missing_facets(options.dim > 0 ? options.dim : have); });
  return mesh_from_gmsh(options.dim, what);
}

GmshOptimizeResult gmsh_write_back(const MeshData& data, const OptimizeResult& result,
                                   const GmshOptimizeOptions& options) {
  set_gmsh_initialized_by_caller(true);
  GmshSession session;
  GmshOptimizeResult out;
  out.result = result;
  out.method = options.optimize.method;
  out.dim = data.dim;
  out.surface_mesh = data.dim == 3 && is_surface_mesh(data.tet);
  const GmshWritten written = replace_gmsh_mesh(data);
  // Views of an earlier run refer to elements that no longer exist.
  remove_quality_views();
  // A mesh of quadrangles only (its triangles none) has no element these views measure.
  if (options.quality_views && !written.element_tags.empty())
    out.views = add_element_views(quality_fields(data), written.element_tags);
  return out;
}

namespace {

void remove_quality_views() {
  gmsh_checked("cannot remove the previous quality views", [&] {
    const std::vector<std::string> ours = our_view_names(true);
    std::vector<int> tags;
    gmsh::view::getTags(tags);
    for (int tag : tags) {
      std::string name;
      gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(tag)) + "].Name", name);
      if (std::find(ours.begin(), ours.end(), name) != ours.end()) gmsh::view::remove(tag);
    }
  });
}

}  // namespace

GmshQualityResult gmsh_quality(const GmshOptimizeOptions& options) {
  const MeshData data = gmsh_read_current(options);
  GmshSession session;
  GmshQualityResult out;
  out.stats =
      data.dim == 3 ? quality_stats(data.tet, "current") : quality_stats(data.tri, "current");
  set_fe_measures(out.stats, data.dim == 3 ? fe_measures(data.tet, options.fe)
                                           : fe_measures(data.tri, options.fe));
  if (options.quality_views) {
    remove_quality_views();
    if (out.stats.nb_elements > 0)
      out.views = add_element_views(quality_fields(data), element_tags_of(data));
  }
  return out;
}

GmshOptimizeResult gmsh_optimize(const GmshOptimizeOptions& given) {
  GmshOptimizeOptions options = given;
  // sizing = a file (Python's sizing="ref.msh"): the reference mesh is read as the CLI reads it,
  // into a model of its own (the caller's current model is left as it is). Only mesh files: a
  // model file (.geo, STEP, ...) would be meshed in the caller's session and set its options.
  if (sizing_is_path(options.optimize) && !options.optimize.sizing_reference) {
    const std::string& path = options.optimize.sizing;
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec) && read_mesh_meshes_a_model(path))
      throw InputError("sizing reference '" + path +
                       "': a model file; inside a Gmsh session the reference must be a mesh "
                       "file (mesh the model and save it as .msh first, or use the CLI's "
                       "--sizing, which meshes it in a session of its own)");
    options.optimize.sizing_reference =
        read_sizing_reference(path, options.dim == 2 || options.dim == 3 ? options.dim : -1);
  }
  // Bad values are refused before the model is read (optimize() checks again for the dimension).
  validate(options.optimize, options.dim == 2 || options.dim == 3 ? options.dim : 0);
  MeshData data = gmsh_read_current(options);
  GmshOptimizeOptions o = options;
  o.optimize = resolve(o.optimize, data.dim);
  // The model's CAD, where it has one, is the free boundary's reference geometry.
  if (!o.optimize.boundary_model) o.optimize.boundary_model = make_gmsh_cad_boundary_if_cad;
  const FeMeasures fe_before =
      data.dim == 3 ? fe_measures(data.tet, o.fe) : fe_measures(data.tri, o.fe);
  OptimizeResult r = optimize(data, o.optimize);
  // Order 2: the mid-edge nodes of the optimized corner mesh, on the model's CAD where it has one.
  if (data.model().high_order.order == 2) {
    GmshSession session;
    r.notes.push_back(mid_edge_summary(place_mid_edge_nodes(data, gmsh_cad_mid_edge_projector())));
  }
  set_fe_measures(r.before, fe_before);
  set_fe_measures(r.after,
                  data.dim == 3 ? fe_measures(data.tet, o.fe) : fe_measures(data.tri, o.fe));
  return gmsh_write_back(data, r, o);
}

QualityTable GmshOptimizeResult::table() const {
  QualityTable t;
  QualityStats before = result.before, after = result.after;
  before.label = "Init";
  after.label = method;
  after.extra.push_back({"iterations", static_cast<double>(result.iterations)});
  after.extra.push_back({"converged", result.converged ? 1.0 : 0.0});
  after.extra.push_back({"seconds", result.seconds});
  t.columns = {before, after};
  return t;
}

std::string GmshOptimizeResult::to_json() const {
  const auto cols = nlohmann::ordered_json::parse(table().to_json());
  nlohmann::ordered_json j;
  j["method"] = method;
  j["dim"] = dim;
  j["surface_mesh"] = surface_mesh;
  j["iterations"] = result.iterations;
  j["converged"] = result.converged;
  j["seconds"] = result.seconds;
  j["views"] = views;
  if (result.boundary_free)
    j["free_boundary"] = {{"geometry", result.boundary_geometry},
                          {"surface_vertices", result.nb_surface_vertices},
                          {"curve_vertices", result.nb_curve_vertices},
                          {"fixed_vertices", result.nb_fixed_vertices},
                          {"moved", result.nb_boundary_moved},
                          {"removed", result.nb_boundary_removed},
                          {"folds_removed", result.nb_folds_removed},
                          {"hausdorff", result.hausdorff},
                          {"hausdorff_bound", result.hausdorff_tolerance},
                          {"volume_change", result.volume_change},
                          {"worst_triangle_q_before", result.tri_q_min_before},
                          {"worst_triangle_q_after", result.tri_q_min_after}};
  j["before"] = cols.at(0);
  j["after"] = cols.at(1);
  return j.dump(2) + "\n";
}

}  // namespace cvtmesh
