#pragma once
// Load-time table checks kept out of table_build.cpp (one check per file): internal to the EOS thorn.
#include "EOS/check_report.hpp"
#include <vector>

#include "EOS/table.hpp"

namespace remnant::eos {

// Thermal index (dp/deps)_rho / rho on each T interval of each (rho, Ye) column: an interval whose
// index exceeds opts.thermal_index_max and opts.thermal_index_jump times its neighbouring
// intervals' is counted in one warning naming the worst node (dataset "thermal_index").
void check_thermal_index(const RawTable& raw, const BuildOptions& opts, CheckReport& rep);

}  // namespace remnant::eos

namespace remnant::eos {

// Thermal index (p1 - p0) / (eps1 - eps0) / rho of the T interval [it, it + 1] of column (ir, iy);
// NaN where eps does not rise.
double thermal_index(const RawTable& raw, std::size_t ir, std::size_t it, std::size_t iy);
// Whether interval it of a column's indices g jumps: g[it] > opts.thermal_index_max and
// > opts.thermal_index_jump times nb, the largest |index| of its neighbouring intervals (set here).
bool thermal_index_jumps(const std::vector<double>& g, std::size_t it, const BuildOptions& opts, double& nb);

// With opts.repair_thermal_index (repair_thermal_index.cpp): the pressure of the outlying node of
// each jumping interval is replaced by log-linear interpolation in log T from its column's
// neighbouring nodes (extrapolation at T_min and T_max); one warning (dataset
// "thermal_index_repair") counts the nodes and names the largest change.
void repair_thermal_index(RawTable& raw, const BuildOptions& opts, CheckReport& rep);

}  // namespace remnant::eos
