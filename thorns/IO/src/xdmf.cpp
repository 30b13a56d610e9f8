#include "xdmf.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "remnant/error.hpp"

namespace remnant::io {

namespace fs = std::filesystem;

namespace {

std::string join(const std::vector<std::int64_t>& v) {
  std::ostringstream s;
  for (std::size_t i = 0; i < v.size(); ++i) s << (i ? " " : "") << v[i];
  return s.str();
}

// A hyperslab of row `row` of dataset `path` (shape [nb] + row_shape), as an XDMF DataItem.
std::string slab(const std::string& h5, const std::string& path, std::int64_t nb, std::int64_t row,
                 const std::vector<std::int64_t>& row_shape, const std::string& indent) {
  const std::size_t rank = row_shape.size() + 1;
  std::vector<std::int64_t> start(rank, 0), stride(rank, 1), count{1}, full{nb};
  start[0] = row;
  count.insert(count.end(), row_shape.begin(), row_shape.end());
  full.insert(full.end(), row_shape.begin(), row_shape.end());
  std::ostringstream s;
  s << indent << "<DataItem ItemType=\"HyperSlab\" Dimensions=\"" << join(row_shape) << "\" Type=\"HyperSlab\">\n"
    << indent << "  <DataItem Dimensions=\"3 " << rank << "\" NumberType=\"Int\" Format=\"XML\">" << join(start) << " "
    << join(stride) << " " << join(count) << "</DataItem>\n"
    << indent << "  <DataItem Dimensions=\"" << join(full) << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
    << h5 << ":" << path << "</DataItem>\n"
    << indent << "</DataItem>\n";
  return s.str();
}

std::string number(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

}  // namespace

std::string xdmf_grid_element(const GridFileSpec& spec, const GridFileSummary& summary, const std::string& h5_name) {
  const int dim = static_cast<int>(spec.cut.axes.size());
  if (dim < 2 || summary.blocks.empty()) return "";
  const auto& n = summary.blocks.front().n;
  const auto nb = static_cast<std::int64_t>(summary.blocks.size());
  std::vector<std::int64_t> cells, nodes;
  for (int a = dim - 1; a >= 0; --a) {
    cells.push_back(n[static_cast<std::size_t>(a)]);
    nodes.push_back(n[static_cast<std::size_t>(a)] + 1);
  }
  const bool rect = spec.coordinates == CoordinateSystem::cartesian;
  const int ncart = spec.grid_dimension == 3 ? 3 : 2;
  std::ostringstream s;
  s << "    <Grid Name=\"" << spec.cut.name << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
    << "      <Time Value=\"" << number(spec.time) << "\"/>\n"
    << "      <Information Name=\"iteration\" Value=\"" << spec.iteration << "\"/>\n";
  for (std::int64_t b = 0; b < nb; ++b) {
    s << "      <Grid Name=\"block" << summary.blocks[static_cast<std::size_t>(b)].gid << "\" GridType=\"Uniform\">\n";
    const std::string topo = std::to_string(dim) + "D" + (rect ? "RectMesh" : "SMesh");
    s << "        <Topology TopologyType=\"" << topo << "\" Dimensions=\"" << join(nodes) << "\"/>\n";
    if (rect) {
      s << "        <Geometry GeometryType=\"" << (dim == 3 ? "VXVYVZ" : "VXVY") << "\">\n";
      for (int a = 0; a < dim; ++a) {
        const std::string name = axis_name(spec.coordinates, spec.cut.axes[static_cast<std::size_t>(a)]);
        s << slab(h5_name, "/coords/" + name + "_nodes", nb, b, {n[static_cast<std::size_t>(a)] + 1}, "          ");
      }
    } else {
      auto shape = nodes;
      shape.push_back(ncart);
      s << "        <Geometry GeometryType=\"" << (ncart == 3 ? "XYZ" : "XY") << "\">\n";
      s << slab(h5_name, "/cartesian_nodes", nb, b, shape, "          ");
    }
    s << "        </Geometry>\n";
    for (const auto& v : spec.variables) {
      s << "        <Attribute Name=\"" << v.file << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
      if (!v.centering_note.empty()) s << "          <Information Name=\"centering\" Value=\"" << v.centering_note << "\"/>\n";
      s << slab(h5_name, "/data/" + v.file, nb, b, cells, "          ");
      s << "        </Attribute>\n";
    }
    s << "      </Grid>\n";
  }
  s << "    </Grid>\n";
  return s.str();
}

void write_xdmf_document(const std::string& path, const std::string& grids, bool temporal) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::trunc);
    f << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n  <Domain>\n";
    if (temporal) f << "  <Grid Name=\"series\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    f << grids;
    if (temporal) f << "  </Grid>\n";
    f << "  </Domain>\n</Xdmf>\n";
    if (!f) throw RunError("IO: cannot write " + tmp);
  }
  fs::rename(tmp, path);
}

std::int64_t iteration_of(const std::string& filename, const std::string& series, const std::string& ext) {
  const std::string head = series + ".it", tail = "." + ext;
  if (filename.size() <= head.size() + tail.size() || filename.rfind(head, 0) != 0 ||
      filename.compare(filename.size() - tail.size(), tail.size(), tail) != 0)
    return -1;
  const std::string digits = filename.substr(head.size(), filename.size() - head.size() - tail.size());
  if (digits.empty() || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) return -1;
  return std::stoll(digits);
}

void write_xdmf_series(const std::string& dir, const std::string& series, std::int64_t last) {
  std::vector<std::pair<std::int64_t, std::string>> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    const std::int64_t it = iteration_of(name, series, "xmf");
    if (it >= 0 && it <= last) files.emplace_back(it, name);
  }
  std::sort(files.begin(), files.end());
  // XInclude of each file's grid: the series stays small however many outputs there are.
  std::string grids;
  for (const auto& [it, name] : files)
    grids += "    <xi:include href=\"" + name + "\" xpointer=\"xpointer(//Xdmf/Domain/Grid)\"/>\n";
  write_xdmf_document(dir + "/" + series + ".xmf", grids, true);
}

}  // namespace remnant::io
