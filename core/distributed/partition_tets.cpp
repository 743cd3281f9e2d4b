#include "core/distributed/partition_tets.h"

#include <metis.h>

#include <algorithm>
#include <string>
#include <utility>

#include "core/util/error.h"

namespace cvtmesh {

namespace {

int find_root(std::vector<int>& up, int x) {
  while (up[x] != x) x = up[x] = up[up[x]];
  return x;
}

// METIS's k-way partition of a graph in CSR form (symmetric, no self loop, no repeated edge).
std::vector<idx_t> metis_parts(std::vector<idx_t>& xadj, std::vector<idx_t>& adjncy,
                               std::vector<idx_t>& adjwgt, std::vector<idx_t>* vwgt, int parts) {
  idx_t n = static_cast<idx_t>(xadj.size()) - 1;
  std::vector<idx_t> part(n, 0);
  if (parts <= 1) return part;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;  // the same parts on every rank and every run
  idx_t ncon = 1, np = parts, cut = 0;
  const int status = METIS_PartGraphKway(&n, &ncon, xadj.data(), adjncy.data(),
                                         vwgt ? vwgt->data() : nullptr, nullptr, adjwgt.data(), &np,
                                         nullptr, nullptr, options, &cut, part.data());
  if (status != METIS_OK)
    throw InvariantError("partition_tets: METIS failed (status " + std::to_string(status) + ")");
  return part;
}

}  // namespace

TetPartition partition_tets(const TetMesh& m, int parts, const std::vector<char>& avoid,
                            int avoid_weight) {
  const int nt = m.nb_tets();
  std::vector<int> live;  // graph vertex -> tet
  std::vector<int> to_graph(nt, -1);
  for (int t = 0; t < nt; ++t)
    if (m.tets[4 * t] >= 0) {
      to_graph[t] = static_cast<int>(live.size());
      live.push_back(t);
    }
  const int n = static_cast<int>(live.size());
  if (parts < 1 || parts > n)
    throw InputError("cannot cut " + std::to_string(n) + " tets into " + std::to_string(parts) +
                     " parts");
  if (m.adj.size() != 4 * static_cast<std::size_t>(nt))
    throw InvariantError("partition_tets: the adjacency is not built");
  auto face_avoided = [&](int t, int f) {
    if (avoid.empty()) return false;
    for (int k = 0; k < 3; ++k)
      if (avoid[m.tets[4 * t + kTetFace[f][k]]]) return true;
    return false;
  };
  // The tets joined across a face with an avoided vertex must stay in one part: each group of
  // them becomes one graph vertex, weighing its tets (possible while no group outweighs a part).
  std::vector<int> up(n);
  for (int i = 0; i < n; ++i) up[i] = i;
  for (int i = 0; i < n; ++i)
    for (int f = 0; f < 4; ++f) {
      const int a = m.adj[4 * live[i] + f];
      if (a < 0 || to_graph[a / 4] < 0 || !face_avoided(live[i], f)) continue;
      up[find_root(up, i)] = find_root(up, to_graph[a / 4]);
    }
  std::vector<int> group(n, -1), weight;
  for (int i = 0; i < n; ++i) {
    const int root = find_root(up, i);
    if (group[root] < 0) {
      group[root] = static_cast<int>(weight.size());
      weight.push_back(0);
    }
    group[i] = group[root];
    ++weight[group[i]];
  }
  const bool contract =
      !avoid.empty() && parts == 2 && *std::max_element(weight.begin(), weight.end()) <= n / 4;
  const int ng = contract ? static_cast<int>(weight.size()) : n;
  auto node = [&](int i) { return contract ? group[i] : i; };
  // The graph in CSR form: groups (or tets) joined by their common faces, each pair once with the
  // number of faces (or the avoided faces' weight) as the edge weight.
  std::vector<std::vector<std::pair<int, int>>> edges(ng);
  for (int i = 0; i < n; ++i)
    for (int f = 0; f < 4; ++f) {
      const int a = m.adj[4 * live[i] + f];
      if (a < 0 || to_graph[a / 4] < 0) continue;
      const int u = node(i), w = node(to_graph[a / 4]);
      if (u == w) continue;
      edges[u].push_back({w, !contract && face_avoided(live[i], f) ? avoid_weight : 1});
    }
  std::vector<idx_t> xadj(ng + 1, 0), adjncy, adjwgt, vwgt;
  for (int u = 0; u < ng; ++u) {
    auto& e = edges[u];
    std::sort(e.begin(), e.end());
    for (std::size_t k = 0; k < e.size(); ++k) {
      if (k > 0 && e[k].first == e[k - 1].first) {
        adjwgt.back() += e[k].second;
        continue;
      }
      adjncy.push_back(e[k].first);
      adjwgt.push_back(e[k].second);
    }
    xadj[u + 1] = static_cast<idx_t>(adjncy.size());
    std::vector<std::pair<int, int>>().swap(e);
  }
  if (contract) vwgt.assign(weight.begin(), weight.end());
  const std::vector<idx_t> gpart =
      metis_parts(xadj, adjncy, adjwgt, contract ? &vwgt : nullptr, parts);
  TetPartition r;
  r.part.assign(nt, -1);
  for (int i = 0; i < n; ++i) r.part[live[i]] = static_cast<int>(gpart[node(i)]);
  for (int i = 0; i < n; ++i) {
    const int t = live[i];
    for (int f = 0; f < 4; ++f) {
      const int a = m.adj[4 * t + f];
      if (a < 0 || a / 4 < t || r.part[a / 4] < 0 || r.part[a / 4] == r.part[t]) continue;
      ++r.nb_cut_faces;
      if (face_avoided(t, f)) ++r.nb_avoided_cut;
    }
  }
  return r;
}

}  // namespace cvtmesh
