#include <cmath>
#include <stdexcept>

#include "animpak/element.hpp"

namespace animpak {

std::size_t SpringCsr::count(SpringClass c) const {
  std::size_t n = 0;
  for (SpringClass k : classes) n += (k == c);
  return n / 2;  // each spring is stored at both of its ends
}

SpringCsr SpringCsr::from_edges(int vertex_count, const std::vector<Edge>& edges,
                                const std::vector<SpringClass>& classes, const std::vector<double>& x,
                                const std::vector<double>& y) {
  if (edges.size() != classes.size()) throw std::invalid_argument("SpringCsr: one class per edge");
  SpringCsr csr;
  csr.offsets.assign(static_cast<std::size_t>(vertex_count) + 1, 0);
  // Count, exclusive scan, fill: each vertex's springs keep the order of `edges` (stable).
  for (const Edge& e : edges) {
    ++csr.offsets[e[0] + 1];
    ++csr.offsets[e[1] + 1];
  }
  for (int v = 0; v < vertex_count; ++v) csr.offsets[v + 1] += csr.offsets[v];
  const std::size_t total = csr.offsets.back();
  csr.neighbors.resize(total);
  csr.rest.resize(total);
  csr.classes.resize(total);
  std::vector<int> cursor(csr.offsets.begin(), csr.offsets.end() - 1);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto [a, b] = edges[i];
    const double length = std::hypot(x[b] - x[a], y[b] - y[a]);
    for (auto [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
      const int slot = cursor[from]++;
      csr.neighbors[slot] = to;
      csr.rest[slot] = length;
      csr.classes[slot] = classes[i];
    }
  }
  return csr;
}

}  // namespace animpak
