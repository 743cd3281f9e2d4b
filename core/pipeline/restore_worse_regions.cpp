#include "core/pipeline/restore_worse_regions.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/geometry/predicates.h"
#include "core/geometry/round_coordinates.h"
#include "core/quality/element_shortfall.h"

namespace cvtmesh {
namespace {

// The two meshes' arrays: N vertices an element, D coordinates a vertex.
template <class M>
struct Elements;

template <>
struct Elements<TetMesh> {
  static constexpr int N = 4, D = 3;
  static const std::vector<int>& of(const TetMesh& m) { return m.tets; }
  static std::vector<double>& coordinates(TetMesh& m) { return m.xyz; }
  static const std::vector<double>& coordinates(const TetMesh& m) { return m.xyz; }
  static bool positive(const double* const* p) { return orient3d(p[0], p[1], p[2], p[3]) > 0; }
  static double shortfall(const double* const* p, const QualityStats& ref) {
    return tet_shortfall(p[0], p[1], p[2], p[3], ref);
  }
};

template <>
struct Elements<TriMesh2> {
  static constexpr int N = 3, D = 2;
  static const std::vector<int>& of(const TriMesh2& m) { return m.tris; }
  static std::vector<double>& coordinates(TriMesh2& m) { return m.xy; }
  static const std::vector<double>& coordinates(const TriMesh2& m) { return m.xy; }
  static bool positive(const double* const* p) { return orient2d(p[0], p[1], p[2]) > 0; }
  static double shortfall(const double* const* p, const QualityStats& ref) {
    return tri_shortfall(p[0], p[1], p[2], ref);
  }
};

template <int D>
std::array<double, D> to_array(const double* p) {
  std::array<double, D> a;
  std::copy(p, p + D, a.begin());
  return a;
}

template <class M>
RestoreStats restore(M& mesh, const M& input, const QualityStats& ref, const RestoreOptions& o) {
  using E = Elements<M>;
  constexpr int N = E::N, D = E::D;
  std::vector<double>& x = E::coordinates(mesh);
  const std::vector<double>& x0 = E::coordinates(input);
  const std::vector<int>& el = E::of(mesh);
  const int ne = static_cast<int>(el.size() / N);
  const int nv = static_cast<int>(x.size() / D);
  const int nv0 = std::min(nv, static_cast<int>(x0.size() / D));
  auto live = [&](int e) { return el[static_cast<std::size_t>(N) * e] >= 0; };
  auto vertex = [&](int e, int k) { return el[static_cast<std::size_t>(N) * e + k]; };

  // Vertex -> elements (CSR).
  std::vector<int> offset(static_cast<std::size_t>(nv) + 1, 0), star;
  for (int e = 0; e < ne; ++e)
    if (live(e))
      for (int k = 0; k < N; ++k) ++offset[vertex(e, k) + 1];
  for (int v = 0; v < nv; ++v) offset[v + 1] += offset[v];
  star.resize(static_cast<std::size_t>(offset[nv]));
  {
    std::vector<int> fill(offset.begin(), offset.end() - 1);
    for (int e = 0; e < ne; ++e)
      if (live(e))
        for (int k = 0; k < N; ++k) star[fill[vertex(e, k)]++] = e;
  }
  auto shortfall = [&](int e) {
    const double* p[N];
    for (int k = 0; k < N; ++k) p[k] = &x[static_cast<std::size_t>(D) * vertex(e, k)];
    return E::positive(p) ? E::shortfall(p, ref) : 1e30;
  };
  std::vector<double> sf(ne, 0);
  for (int e = 0; e < ne; ++e)
    if (live(e)) sf[e] = shortfall(e);
  auto count_short = [&] {
    long n = 0;
    for (int e = 0; e < ne; ++e) n += live(e) && sf[e] > 0;
    return n;
  };
  RestoreStats st;
  st.nb_short_before = count_short();
  // Vertices away from their input positions (only they can go back).
  auto away = [&](int v) {
    if (v >= nv0) return false;
    for (int c = 0; c < D; ++c)
      if (x[static_cast<std::size_t>(D) * v + c] != x0[static_cast<std::size_t>(D) * v + c])
        return true;
    return false;
  };
  std::vector<char> movable(nv, 0);
  for (int v = 0; v < nv0; ++v) movable[v] = away(v);

  std::vector<char> in_region(nv);
  std::vector<double> saved(D), fresh;
  // The vertices of the elements short of the reference and `rings` rings of neighbours around
  // them (in_region marks them); empty when no element is short.
  auto region_of = [&](int rings) {
    std::fill(in_region.begin(), in_region.end(), 0);
    std::vector<int> frontier;
    for (int e = 0; e < ne; ++e)
      if (live(e) && sf[e] > 0)
        for (int k = 0; k < N; ++k)
          if (!in_region[vertex(e, k)]) {
            in_region[vertex(e, k)] = 1;
            frontier.push_back(vertex(e, k));
          }
    std::vector<int> region = frontier;
    for (int r = 0; r < rings && !frontier.empty(); ++r) {
      std::vector<int> next;
      for (int v : frontier)
        for (int i = offset[v]; i < offset[v + 1]; ++i)
          for (int k = 0; k < N; ++k)
            if (const int w = vertex(star[i], k); !in_region[w]) {
              in_region[w] = 1;
              next.push_back(w);
            }
      region.insert(region.end(), next.begin(), next.end());
      frontier = std::move(next);
    }
    return region;
  };
  for (int round = 0; round < o.max_rounds; ++round) {
    if (region_of(round).empty()) break;
    st.rounds = round + 1;
    for (int v = 0; v < nv; ++v) {
      if (!in_region[v]) continue;
      double* p = &x[static_cast<std::size_t>(D) * v];
      const double* p0 = v < nv0 ? &x0[static_cast<std::size_t>(D) * v] : nullptr;
      double before = 0;
      for (int i = offset[v]; i < offset[v + 1]; ++i) before += sf[star[i]];
      // Moves v to q if its star stays positive and its summed shortfall does not rise (strict:
      // falls).
      auto try_move = [&](const double* q, bool strict) {
        std::copy(p, p + D, saved.begin());
        std::copy(q, q + D, p);
        fresh.clear();
        double after = 0;
        for (int i = offset[v]; i < offset[v + 1] && after <= before; ++i) {
          fresh.push_back(shortfall(star[i]));
          after += fresh.back();
        }
        if (static_cast<int>(fresh.size()) == offset[v + 1] - offset[v] &&
            (strict ? after < before : after <= before)) {
          for (int i = offset[v]; i < offset[v + 1]; ++i) sf[star[i]] = fresh[i - offset[v]];
          return true;
        }
        std::copy(saved.begin(), saved.end(), p);
        return false;
      };
      if (movable[v] && try_move(p0, false)) {
        movable[v] = 0;
        ++st.nb_restored;
        continue;
      }
      if (before <= 0) continue;
      // Not back: part of the way back, or towards the centroid of its star's other vertices
      // (an interior vertex), if that lowers the shortfall. Rounded as a writer stores it.
      if (mesh.vclass[v].dim != D) continue;
      std::vector<std::array<double, D>> targets;
      if (movable[v]) targets.push_back(to_array<D>(p0));
      {
        std::array<double, D> c{};
        int n = 0;
        for (int i = offset[v]; i < offset[v + 1]; ++i)
          for (int k = 0; k < N; ++k)
            if (const int w = vertex(star[i], k); w != v) {
              for (int d = 0; d < D; ++d) c[d] += x[static_cast<std::size_t>(D) * w + d];
              ++n;
            }
        for (int d = 0; d < D; ++d) c[d] /= n;
        targets.push_back(c);
      }
      bool moved = false;
      for (const auto& t : targets)
        for (double a = 0.5; a > 0.1 && !moved; a /= 2) {
          double q[D];
          for (int d = 0; d < D; ++d) {
            q[d] = p[d] + a * (t[d] - p[d]);
            if (o.digits > 0) q[d] = round_to_digits(q[d], o.digits);
          }
          moved = try_move(q, true);
        }
      // Then a compass search on the star's shortfall: steps along the axes, from a quarter of
      // the star's shortest edge, halved when no direction lowers it.
      double shortest = 1e300;
      for (int i = offset[v]; i < offset[v + 1]; ++i)
        for (int k = 0; k < N; ++k)
          if (const int w = vertex(star[i], k); w != v) {
            double l2 = 0;
            for (int d = 0; d < D; ++d) {
              const double dx = x[static_cast<std::size_t>(D) * w + d] - p[d];
              l2 += dx * dx;
            }
            shortest = std::min(shortest, std::sqrt(l2));
          }
      for (double step = 0.25 * shortest, trials = 0; step > 1e-3 * shortest && trials < 200;) {
        before = 0;
        for (int i = offset[v]; i < offset[v + 1]; ++i) before += sf[star[i]];
        if (before <= 0) break;
        bool better = false;
        for (int dir = 0; dir < 2 * D && !better; ++dir, ++trials) {
          double q[D];
          for (int d = 0; d < D; ++d) {
            q[d] = p[d] + (d == dir / 2 ? (dir % 2 ? -step : step) : 0.0);
            if (o.digits > 0) q[d] = round_to_digits(q[d], o.digits);
          }
          better = try_move(q, true);
        }
        moved |= better;
        if (!better) step /= 2;
      }
      st.nb_smoothed += moved;
    }
  }
  // Then whole neighbourhoods at once: the vertices of the elements still short and `ring` rings
  // around them all go back together (an element whose vertices all went back is the input's,
  // if the connectivity there is the input's), kept if every element stays positive and the
  // neighbourhood's summed shortfall falls; a wider neighbourhood otherwise.
  for (int ring = 1; ring <= 2 * o.max_rounds; ++ring) {
    const std::vector<int> region = region_of(ring);
    if (region.empty()) break;
    std::vector<int> moving, affected;
    for (int v : region)
      if (away(v)) moving.push_back(v);
    if (moving.empty()) continue;
    std::vector<char> seen(ne, 0);
    for (int v : moving)
      for (int i = offset[v]; i < offset[v + 1]; ++i)
        if (!seen[star[i]]) {
          seen[star[i]] = 1;
          affected.push_back(star[i]);
        }
    double before = 0, after = 0;
    for (int e : affected) before += sf[e];
    std::vector<double> old(moving.size() * D);
    for (std::size_t i = 0; i < moving.size(); ++i) {
      double* p = &x[static_cast<std::size_t>(D) * moving[i]];
      std::copy(p, p + D, old.begin() + D * i);
      std::copy(&x0[static_cast<std::size_t>(D) * moving[i]],
                &x0[static_cast<std::size_t>(D) * moving[i]] + D, p);
    }
    fresh.clear();
    for (int e : affected) {
      fresh.push_back(shortfall(e));
      after += fresh.back();
    }
    if (after < before) {
      for (std::size_t i = 0; i < affected.size(); ++i) sf[affected[i]] = fresh[i];
      st.nb_restored += static_cast<long>(moving.size());
      ring = 0;  // the next neighbourhood starts small again
    } else {
      for (std::size_t i = 0; i < moving.size(); ++i)
        std::copy(old.begin() + D * i, old.begin() + D * (i + 1),
                  &x[static_cast<std::size_t>(D) * moving[i]]);
    }
  }
  st.nb_short_after = count_short();
  return st;
}

}  // namespace

RestoreStats restore_worse_regions(TetMesh& mesh, const TetMesh& input, const QualityStats& ref,
                                   const RestoreOptions& options) {
  return restore(mesh, input, ref, options);
}

RestoreStats restore_worse_regions(TriMesh2& mesh, const TriMesh2& input, const QualityStats& ref,
                                   const RestoreOptions& options) {
  return restore(mesh, input, ref, options);
}

}  // namespace cvtmesh
