// CompOSE HDF5 tables as written by PyCompOSE: axes nb (fm^-3), t (MeV), yq; scalars mn, mp
// (MeV); Q1..Q7 and optional cs2, Y[i], A[N], Z[N], each shaped (nb, yq, t), t fastest.
#include "EOS/errors.hpp"
#include "EOS/readers.hpp"
#include "compose_common.hpp"
#include "hdf5_file.hpp"

namespace remnant::eos {

RawTable read_compose_hdf5(const std::string& path, const ReadOptions& opts) {
  detail::H5File f(path);
  detail::ComposeGrid g;
  g.file = path;
  g.thermo_dataset = "Q";
  auto axis = [&](const char* name) {
    if (f.shape(name).size() != 1) throw TableError(path, name, "axis must be one-dimensional");
    return f.read(name);
  };
  g.nb = axis("nb");
  g.T = axis("t");
  g.yq = axis("yq");
  g.m_n = f.scalar("mn");
  g.m_p = f.has("mp") ? f.scalar("mp") : 0.0;
  const hsize_t nr = g.nb.size(), nt = g.T.size(), ny = g.yq.size();
  const std::vector<hsize_t> shape{nr, ny, nt};
  // (nb, yq, t) -> our [yq][t][nb] order.
  auto reorder = [&](const std::vector<double>& in) {
    std::vector<double> out(in.size());
    for (hsize_t ir = 0; ir < nr; ++ir)
      for (hsize_t iy = 0; iy < ny; ++iy)
        for (hsize_t it = 0; it < nt; ++it) out[(iy * nt + it) * nr + ir] = in[(ir * ny + iy) * nt + it];
    return out;
  };
  for (int k = 0; k < 7; ++k) g.Q[k] = reorder(f.read("Q" + std::to_string(k + 1), shape));
  if (f.has("cs2")) g.cs2 = reorder(f.read("cs2", shape));
  // Composition: number fractions Y_i, mass fractions X_i = A_i Y_i.
  if (f.has("Y[n]") && f.has("Y[p]")) {
    g.Xn = reorder(f.read("Y[n]", shape));
    g.Xp = reorder(f.read("Y[p]", shape));
    if (f.has("Y[He4]")) {
      g.Xa = reorder(f.read("Y[He4]", shape));
      for (auto& x : g.Xa) x *= 4;
    }
    if (f.has("Y[N]") && f.has("A[N]") && f.has("Z[N]")) {
      g.Abar = reorder(f.read("A[N]", shape, true));
      g.Zbar = reorder(f.read("Z[N]", shape, true));
      g.Xh = reorder(f.read("Y[N]", shape));
      for (std::size_t i = 0; i < g.Xh.size(); ++i) g.Xh[i] *= g.Abar[i];
    }
  }
  return detail::compose_to_raw(std::move(g), opts, "CompOSE HDF5");
}

}  // namespace remnant::eos
