// As-rigid-as-possible deformation of one slice (Sorkine & Alexa 2007, in 2D), used by §3.2 to fill in
// every vertex that the artist did not key. Energy, over the triangulation edges:
//   E(p) = Σ_i Σ_{j ∈ N(i)} w_ij ‖(p_i − p_j) − R_i (r_i − r_j)‖²,   r = rest positions.
// Weights: cotangent weights ½(cot α_ij + cot β_ij), clamped below at a small positive floor. Cotangent
// weights make the energy a discretization of the continuous one (a denser patch of samples does not
// pull harder), and a Delaunay slice has non-negative cotangent sums on interior edges anyway; the
// clamp only catches boundary edges opposite an obtuse angle, whose negative weight would make the
// system indefinite. Handle vertices are eliminated, so the free block of the Laplacian is factored
// once (sparse Cholesky) and each global step is two back-substitutions.
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"

namespace animpak {

namespace {

// Cotangent weights are dimensionless, so an absolute floor is scale-independent: 1e-2 is far below
// the ≈0.5–1.7 of well-shaped triangles and only matters for edges that would otherwise be ≤ 0.
constexpr double min_weight = 1e-2;

double cotangent(Vec2 apex, Vec2 a, Vec2 b) {
  const Vec2 u = a - apex, v = b - apex;
  const double area2 = std::fabs(cross(u, v));
  if (area2 <= 1e-300) return 0.0;  // degenerate triangle: contributes nothing rather than infinity
  return dot(u, v) / area2;
}

}  // namespace

struct ArapSolver::Impl {
  // Nested rather than file-local: a member type from an anonymous namespace trips -Wsubobject-linkage
  // when the file is compiled inside a unity build (scripts/test.sh).
  struct Neighbor {
    int vertex;
    double weight;
  };
  std::vector<Vec2> rest;
  std::vector<std::vector<Neighbor>> neighbors;
  std::vector<int> handles;
  std::vector<int> free_index;              ///< vertex -> row of the free system, -1 for handles
  Eigen::SparseMatrix<double> free_handle;  ///< L_fh: couples free rows to handle columns
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor;

  // The closed-form best 2D rotation for vertex i: maximizes tr(Rᵀ C), C = Σ w (p_i−p_j)(r_i−r_j)ᵀ,
  // so θ = atan2(C₂₁ − C₁₂, C₁₁ + C₂₂). No SVD and never a reflection.
  std::array<double, 2> best_rotation(int i, const std::vector<Vec2>& p) const {
    double c11 = 0, c12 = 0, c21 = 0, c22 = 0;
    for (const Neighbor& nb : neighbors[i]) {
      const Vec2 e = p[i] - p[nb.vertex], r = rest[i] - rest[nb.vertex];
      c11 += nb.weight * e.x * r.x;
      c12 += nb.weight * e.x * r.y;
      c21 += nb.weight * e.y * r.x;
      c22 += nb.weight * e.y * r.y;
    }
    const double theta = std::atan2(c21 - c12, c11 + c22);
    return {std::cos(theta), std::sin(theta)};
  }

  // Marks the handles in free_index (-1), refusing none, one out of range or one given twice.
  void mark_handles() {
    const int n = static_cast<int>(rest.size());
    if (handles.empty())
      throw InputError("ARAP: no handle vertices; at least one vertex must be pinned to place the shape");
    free_index.assign(n, 0);
    for (std::size_t k = 0; k < handles.size(); ++k) {
      const int v = handles[k];
      if (v < 0 || v >= n) {
        std::ostringstream out;
        out << "ARAP: handle " << k << " names vertex " << v << ", but the slice has " << n << " vertices";
        throw InputError(out.str());
      }
      if (free_index[v] == -1) {
        std::ostringstream out;
        out << "ARAP: vertex " << v << " is a handle twice (handle " << k
            << "); each vertex may be pinned by one handle only";
        throw InputError(out.str());
      }
      free_index[v] = -1;
    }
  }

  // The neighbours of every vertex with each edge's weight, accumulated from the one or two triangles
  // beside it.
  void weigh_edges(const SliceMesh& mesh) {
    const int n = static_cast<int>(rest.size());
    auto key = [n](int a, int b) { return static_cast<long long>(std::min(a, b)) * n + std::max(a, b); };
    std::vector<std::pair<long long, double>> cot;
    cot.reserve(mesh.triangles.size() * 3);
    for (const Triangle& tri : mesh.triangles)
      for (int c = 0; c < 3; ++c) {
        const int a = tri[(c + 1) % 3], b = tri[(c + 2) % 3];
        cot.emplace_back(key(a, b), 0.5 * cotangent(rest[tri[c]], rest[a], rest[b]));
      }
    std::sort(cot.begin(), cot.end());
    neighbors.assign(n, {});
    for (const Edge& e : mesh.edges) {
      const long long k = key(e[0], e[1]);
      auto it = std::lower_bound(cot.begin(), cot.end(), std::make_pair(k, -1e300));
      double w = 0.0;
      bool in_triangle = false;
      for (; it != cot.end() && it->first == k; ++it) {
        w += it->second;
        in_triangle = true;
      }
      // An edge in no triangle has no cotangent; weight it like a well-shaped triangle edge.
      w = in_triangle ? std::max(w, min_weight) : 1.0;
      neighbors[e[0]].push_back({e[1], w});
      neighbors[e[1]].push_back({e[0], w});
    }
  }

  // Numbers the free vertices in free_index and returns their count. Every free vertex must reach a
  // handle through edges, or its block of the Laplacian is singular.
  int number_free_vertices() {
    const int n = static_cast<int>(rest.size());
    std::vector<char> reached(n, 0);
    std::vector<int> stack(handles.begin(), handles.end());
    for (int v : stack) reached[v] = 1;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (const Neighbor& nb : neighbors[v])
        if (!reached[nb.vertex]) {
          reached[nb.vertex] = 1;
          stack.push_back(nb.vertex);
        }
    }
    int free_count = 0;
    for (int v = 0; v < n; ++v) {
      if (!reached[v]) {
        std::ostringstream out;
        out << "ARAP: vertex " << v << " is not connected to any handle, so its position is undetermined; "
            << "add a handle on every connected piece of the slice";
        throw InputError(out.str());
      }
      if (free_index[v] != -1) free_index[v] = free_count++;
    }
    return free_count;
  }

  // The free block L_ff of the weighted Laplacian, factored, and its coupling L_fh to the handles.
  void factor_laplacian(int free_count) {
    const int n = static_cast<int>(rest.size());
    std::vector<int> handle_column(n, -1);
    for (std::size_t k = 0; k < handles.size(); ++k) handle_column[handles[k]] = static_cast<int>(k);
    std::vector<Eigen::Triplet<double>> ff, fh;
    for (int v = 0; v < n; ++v) {
      const int row = free_index[v];
      if (row < 0) continue;
      double diagonal = 0.0;
      for (const Neighbor& nb : neighbors[v]) {
        diagonal += nb.weight;
        const int col = free_index[nb.vertex];
        if (col >= 0)
          ff.emplace_back(row, col, -nb.weight);
        else
          fh.emplace_back(row, handle_column[nb.vertex], -nb.weight);
      }
      ff.emplace_back(row, row, diagonal);
    }
    Eigen::SparseMatrix<double> lff(free_count, free_count);
    lff.setFromTriplets(ff.begin(), ff.end());
    free_handle.resize(free_count, static_cast<int>(handles.size()));
    free_handle.setFromTriplets(fh.begin(), fh.end());
    if (free_count > 0) {
      factor.compute(lff);
      if (factor.info() != Eigen::Success)
        throw InputError("ARAP: the slice's system matrix is singular; the slice triangulation is degenerate");
    }
  }
};

ArapSolver::ArapSolver(const SliceMesh& mesh, std::vector<int> handle_vertices) : impl_(new Impl) {
  Impl& m = *impl_;
  m.rest = mesh.vertices;
  m.handles = std::move(handle_vertices);
  m.mark_handles();
  m.weigh_edges(mesh);
  const int free_count = m.number_free_vertices();
  m.factor_laplacian(free_count);
}

ArapSolver::~ArapSolver() = default;
ArapSolver::ArapSolver(ArapSolver&&) noexcept = default;
ArapSolver& ArapSolver::operator=(ArapSolver&&) noexcept = default;

std::vector<Vec2> ArapSolver::solve(const std::vector<Vec2>& handles, const std::vector<Vec2>& initial,
                                    int iterations) const {
  const Impl& m = *impl_;
  const int n = static_cast<int>(m.rest.size());
  if (handles.size() != m.handles.size()) {
    std::ostringstream out;
    out << "ARAP: " << handles.size() << " handle positions given for " << m.handles.size() << " handles";
    throw InputError(out.str());
  }
  if (static_cast<int>(initial.size()) != n) {
    std::ostringstream out;
    out << "ARAP: initial guess has " << initial.size() << " positions for " << n << " vertices";
    throw InputError(out.str());
  }
  std::vector<Vec2> p = initial;
  for (std::size_t k = 0; k < handles.size(); ++k) p[m.handles[k]] = handles[k];
  const Eigen::Index free_count = m.free_handle.rows();
  if (free_count == 0) return p;

  // The handles' contribution to the right-hand side does not change between iterations.
  Eigen::MatrixXd handle_xy(static_cast<Eigen::Index>(handles.size()), 2);
  for (std::size_t k = 0; k < handles.size(); ++k) handle_xy.row(k) << handles[k].x, handles[k].y;
  const Eigen::MatrixXd fixed = m.free_handle * handle_xy;

  std::vector<std::array<double, 2>> rotation(n);
  Eigen::MatrixXd rhs(free_count, 2);
  for (int it = 0; it < iterations; ++it) {
    for (int v = 0; v < n; ++v) rotation[v] = m.best_rotation(v, p);  // local step
    for (int v = 0; v < n; ++v) {                                     // global step
      const int row = m.free_index[v];
      if (row < 0) continue;
      double bx = 0.0, by = 0.0;
      for (const Impl::Neighbor& nb : m.neighbors[v]) {
        // ½ (R_i + R_j)(r_i − r_j), with R = [[c, −s], [s, c]].
        const double c = 0.5 * (rotation[v][0] + rotation[nb.vertex][0]);
        const double s = 0.5 * (rotation[v][1] + rotation[nb.vertex][1]);
        const Vec2 r = m.rest[v] - m.rest[nb.vertex];
        bx += nb.weight * (c * r.x - s * r.y);
        by += nb.weight * (s * r.x + c * r.y);
      }
      rhs(row, 0) = bx;
      rhs(row, 1) = by;
    }
    const Eigen::MatrixXd solved = m.factor.solve(rhs - fixed);
    for (int v = 0; v < n; ++v)
      if (const int row = m.free_index[v]; row >= 0) p[v] = {solved(row, 0), solved(row, 1)};
  }
  return p;
}

double ArapSolver::energy(const std::vector<Vec2>& positions) const {
  const Impl& m = *impl_;
  if (positions.size() != m.rest.size()) {
    std::ostringstream out;
    out << "ARAP: energy of " << positions.size() << " positions for " << m.rest.size() << " vertices";
    throw InputError(out.str());
  }
  double e = 0.0;
  for (int v = 0; v < static_cast<int>(m.rest.size()); ++v) {
    const auto [c, s] = m.best_rotation(v, positions);
    for (const Impl::Neighbor& nb : m.neighbors[v]) {
      const Vec2 d = positions[v] - positions[nb.vertex], r = m.rest[v] - m.rest[nb.vertex];
      const Vec2 residual = d - Vec2{c * r.x - s * r.y, s * r.x + c * r.y};
      e += nb.weight * dot(residual, residual);
    }
  }
  return e;
}

}  // namespace animpak
