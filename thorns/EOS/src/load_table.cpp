// Format detection and loading: reader -> checks -> internal table.
#include <filesystem>

#include "EOS/errors.hpp"
#include "EOS/readers.hpp"
#include "hdf5_file.hpp"

namespace remnant::eos {

const char* to_string(TableFormat f) {
  switch (f) {
    case TableFormat::automatic: return "auto";
    case TableFormat::stellarcollapse: return "stellarcollapse";
    case TableFormat::compose_ascii: return "compose_ascii";
    case TableFormat::compose_hdf5: return "compose_hdf5";
  }
  return "?";
}

TableFormat detect_format(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    if (fs::exists(fs::path(path) / "eos.thermo", ec)) return TableFormat::compose_ascii;
    throw TableError(path, "", "directory without eos.thermo: not a CompOSE file set");
  }
  if (!fs::exists(path, ec)) throw TableError(path, "", "no such file or directory");
  if (detail::h5_has_dataset(path, "logrho")) return TableFormat::stellarcollapse;
  if (detail::h5_has_dataset(path, "nb")) return TableFormat::compose_hdf5;
  throw TableError(path, "", "unknown table format: neither StellarCollapse (logrho) nor CompOSE HDF5 (nb)");
}

std::shared_ptr<const TableData> load_table(const std::string& path, const ReadOptions& opts) {
  const TableFormat f = opts.format == TableFormat::automatic ? detect_format(path) : opts.format;
  RawTable raw;
  switch (f) {
    case TableFormat::stellarcollapse: raw = read_stellarcollapse(path, opts); break;
    case TableFormat::compose_ascii: raw = read_compose_ascii(path, opts); break;
    case TableFormat::compose_hdf5: raw = read_compose_hdf5(path, opts); break;
    default: throw TableError(path, "", "no table format");
  }
  return build_table(std::move(raw), opts.build);
}

}  // namespace remnant::eos
