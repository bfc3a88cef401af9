#include "evenness_output.hpp"

#include <iomanip>
#include <sstream>

namespace animpak::cli {
namespace {

std::string fixed(const std::optional<double>& v) {
  if (!v) return "none";
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << *v;
  return s.str();
}

}  // namespace

std::string evenness_line(const EvennessSummary& e) {
  std::string line = "evenness: wall ratio " + fixed(e.wall_ratio_median);
  if (e.wall_ratio_min) line += " (" + fixed(e.wall_ratio_min) + "–" + fixed(e.wall_ratio_max) + ")";
  line +=
      ", largest empty disc " + fixed(e.empty_disc_median) + " element radii (worst " + fixed(e.empty_disc_worst) + ")";
  // What leaves less room empty: a narrower channel, more elements, smaller ones in the pockets
  // (docs/parameters.md, "Secondary elements").
  if (e.empty_disc_median && *e.empty_disc_median > sparse_empty_disc)
    line += "; sparse: try a smaller params.offset, higher counts (\"count\": \"fill\") or secondary elements";
  return line;
}

}  // namespace animpak::cli
