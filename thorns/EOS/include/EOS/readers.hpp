#pragma once
// Table readers. Each returns a RawTable (physical values in code units); load_table() also
// checks and converts it. Errors are TableError naming the file and the dataset.
#include <memory>
#include <string>

#include "EOS/table.hpp"

namespace remnant::eos {

// StellarCollapse tables store cs2 either relativistic (flag `have_rel_cs2` = 1) or Newtonian
// (old tables, no flag); a Newtonian cs2 is divided by h on load.
enum class Cs2Convention { from_file, relativistic, newtonian };

// CompOSE gives mu_b, mu_q, mu_l. The electron chemical potential is mu_l - mu_q (CompOSE manual).
// Some converters write mu_l itself as mu_e; `mu_l` reproduces them.
enum class ComposeElectronMu { mu_l_minus_mu_q, mu_l };

enum class TableFormat { automatic, stellarcollapse, compose_ascii, compose_hdf5 };

struct ReadOptions {
  TableFormat format = TableFormat::automatic;
  // Used when the StellarCollapse file has no have_rel_cs2 flag.
  Cs2Convention sc_cs2_default = Cs2Convention::newtonian;
  Cs2Convention sc_cs2 = Cs2Convention::from_file;
  ComposeElectronMu compose_mu_e = ComposeElectronMu::mu_l_minus_mu_q;
  double eps_shift = -1;  // code units; < 0: StellarCollapse energy_shift or automatic
  BuildOptions build;
};

RawTable read_stellarcollapse(const std::string& path, const ReadOptions& opts = {});
RawTable read_compose_ascii(const std::string& dir, const ReadOptions& opts = {});
RawTable read_compose_hdf5(const std::string& path, const ReadOptions& opts = {});

TableFormat detect_format(const std::string& path);
std::shared_ptr<const TableData> load_table(const std::string& path, const ReadOptions& opts = {});

const char* to_string(TableFormat f);

}  // namespace remnant::eos
