#pragma once
// Load-time table checks kept out of table_build.cpp (one check per file): internal to the EOS thorn.
#include "EOS/check_report.hpp"
#include "EOS/table.hpp"

namespace remnant::eos {

// Thermal index (dp/deps)_rho / rho on each T interval of each (rho, Ye) column: an interval whose
// index exceeds opts.thermal_index_max and opts.thermal_index_jump times its neighbouring
// intervals' is counted in one warning naming the worst node (dataset "thermal_index").
void check_thermal_index(const RawTable& raw, const BuildOptions& opts, CheckReport& rep);

}  // namespace remnant::eos
