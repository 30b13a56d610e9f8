#include "face_prolongation.hpp"

#include <array>
#include <bit>

#include "remnant/limiters.hpp"

namespace remnant::grid {

namespace {

using Index = std::array<int, 3>;

double& at(const Field& f, const Index& p) { return f(p[0], p[1], p[2]); }

struct Prolongation {
  Block& parent;
  Block& child;
  int dim;
  Index offset{0, 0, 0};  // parent-local coarse index of the child's first cell
  std::array<Field, 3> coarse{}, fine{};

  double fine_flux(int d, const Index& f) const { return child.face_area(d, f[0], f[1], f[2]) * at(fine[d], f); }

  // Step 1 for the coarse face normal to d at parent-local index C.
  void face(int d, const Index& C) {
    const double bc = at(coarse[static_cast<std::size_t>(d)], C);
    double slope[3] = {0, 0, 0};
    for (int e = 0; e < dim; ++e) {
      if (e == d) continue;
      Index m = C, p = C;
      m[static_cast<std::size_t>(e)] -= 1;
      p[static_cast<std::size_t>(e)] += 1;
      slope[e] = mc_slope(at(coarse[static_cast<std::size_t>(d)], m), bc, at(coarse[static_cast<std::size_t>(d)], p),
                          parent.centroid(e, m[static_cast<std::size_t>(e)]), parent.centroid(e, C[static_cast<std::size_t>(e)]),
                          parent.centroid(e, p[static_cast<std::size_t>(e)]));
    }
    Index base{};
    for (std::size_t e = 0; e < 3; ++e) base[e] = static_cast<int>(e) < dim ? 2 * (C[e] - offset[e]) : 0;
    // The 2^(dim-1) fine faces: bits over the tangential used directions.
    const int faces = 1 << (dim - 1);
    double b[4], area[4], flux_sum = 0, area_sum = 0;
    Index f[4];
    for (int t = 0; t < faces; ++t) {
      f[t] = base;
      double v = bc;
      int bit = 0;
      for (int e = 0; e < dim; ++e) {
        if (e == d) continue;
        const auto ue = static_cast<std::size_t>(e);
        f[t][ue] += (t >> bit++) & 1;
        v += slope[e] * (child.centroid(e, f[t][ue]) - parent.centroid(e, C[ue]));
      }
      b[t] = v;
      area[t] = child.face_area(d, f[t][0], f[t][1], f[t][2]);
      flux_sum += area[t] * v;
      area_sum += area[t];
    }
    const double coarse_flux = parent.face_area(d, C[0], C[1], C[2]) * bc;
    const double shift = area_sum > 0 ? (coarse_flux - flux_sum) / area_sum : 0.0;
    for (int t = 0; t < faces; ++t) at(fine[static_cast<std::size_t>(d)], f[t]) = area[t] > 0 ? b[t] + shift : bc;
  }

  // Step 2 for the coarse cell at parent-local index C.
  void cell(const Index& C) {
    Index base{};
    for (std::size_t e = 0; e < 3; ++e) base[e] = static_cast<int>(e) < dim ? 2 * (C[e] - offset[e]) : 0;
    const int cells = 1 << dim;
    auto cell_index = [&](int c) {
      Index p = base;
      for (int e = 0; e < dim; ++e) p[static_cast<std::size_t>(e)] += (c >> e) & 1;
      return p;
    };
    // Net outflow of each fine cell through the coarse cell's boundary, and the cell volumes.
    double outer[8] = {}, volume[8] = {}, total_outflow = 0, total_volume = 0;
    for (int c = 0; c < cells; ++c) {
      const Index p = cell_index(c);
      volume[c] = child.cell_volume(p[0], p[1], p[2]);
      total_volume += volume[c];
      for (int d = 0; d < dim; ++d) {
        Index q = p;
        if ((c >> d) & 1) {
          q[static_cast<std::size_t>(d)] += 1;
          outer[c] += fine_flux(d, q);
        } else {
          outer[c] -= fine_flux(d, q);
        }
      }
      total_outflow += outer[c];
    }
    // Interior faces: the face between cell c (bit d clear) and c + 2^d, with its first guess.
    double guess[3][4] = {}, mean[3][4] = {}, area[3][4] = {};
    double residual[8] = {};
    for (int c = 0; c < cells; ++c) residual[c] = total_outflow * volume[c] / total_volume - outer[c];
    for (int d = 0; d < dim; ++d)
      for (int c = 0; c < cells; ++c) {
        if ((c >> d) & 1) continue;
        Index lo = cell_index(c), mid = lo, hi = lo;
        mid[static_cast<std::size_t>(d)] += 1;
        hi[static_cast<std::size_t>(d)] += 2;
        const int slot = face_slot(c, d);
        area[d][slot] = child.face_area(d, mid[0], mid[1], mid[2]);
        mean[d][slot] = 0.5 * (at(fine[static_cast<std::size_t>(d)], lo) + at(fine[static_cast<std::size_t>(d)], hi));
        guess[d][slot] = area[d][slot] * mean[d][slot];
        residual[c] -= guess[d][slot];
        residual[c + (1 << d)] += guess[d][slot];
      }
    // Potential p with L p = residual (L: Laplacian of the hypercube graph; eigenvectors are the
    // Walsh functions chi_S(c) = (-1)^|S & c| with eigenvalues 2 |S|).
    double potential[8] = {};
    for (int s = 1; s < cells; ++s) {
      double projection = 0;
      for (int c = 0; c < cells; ++c) projection += (std::popcount(static_cast<unsigned>(s & c)) & 1 ? -1.0 : 1.0) * residual[c];
      projection /= cells * 2.0 * std::popcount(static_cast<unsigned>(s));
      for (int c = 0; c < cells; ++c) potential[c] += (std::popcount(static_cast<unsigned>(s & c)) & 1 ? -1.0 : 1.0) * projection;
    }
    for (int d = 0; d < dim; ++d)
      for (int c = 0; c < cells; ++c) {
        if ((c >> d) & 1) continue;
        const int slot = face_slot(c, d);
        Index mid = cell_index(c);
        mid[static_cast<std::size_t>(d)] += 1;
        const double flux = guess[d][slot] + potential[c] - potential[c + (1 << d)];
        const double a = area[d][slot];
        at(fine[static_cast<std::size_t>(d)], mid) = a > 0 ? flux / a : mean[d][slot];
      }
  }

  // Index of the interior face below cell c in direction d among the 2^(dim-1) such faces.
  static int face_slot(int c, int d) { return (c & ((1 << d) - 1)) | ((c >> (d + 1)) << d); }
};

}  // namespace

void prolong_face_vector(Block& parent, Block& child, const FaceVector& vec, int dimension,
                         std::span<const KeptFace> kept) {
  Prolongation p{parent, child, dimension};
  for (int d = 0; d < dimension; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    p.offset[ud] = static_cast<int>(child.index[ud] % 2) * child.n[ud] / 2;
  }
  for (int comp = 0; comp < vec.ncomp; ++comp) {
    for (int d = 0; d < dimension; ++d) {
      p.coarse[static_cast<std::size_t>(d)] = parent.field(vec.group[static_cast<std::size_t>(d)], comp);
      p.fine[static_cast<std::size_t>(d)] = child.field(vec.group[static_cast<std::size_t>(d)], comp);
    }
    Index lo{0, 0, 0}, hi{1, 1, 1};
    for (int e = 0; e < dimension; ++e) {
      const auto ue = static_cast<std::size_t>(e);
      lo[ue] = p.offset[ue];
      hi[ue] = p.offset[ue] + child.n[ue] / 2;
    }
    for (int d = 0; d < dimension; ++d) {
      Index top = hi;
      top[static_cast<std::size_t>(d)] += 1;  // the upper faces of the last coarse cells
      for (int k = lo[2]; k < top[2]; ++k)
        for (int j = lo[1]; j < top[1]; ++j)
          for (int i = lo[0]; i < top[0]; ++i) p.face(d, {i, j, k});
    }
    for (const KeptFace& kf : kept) {
      // The whole face plane of the child, from the neighbour's opposite face.
      const auto ud = static_cast<std::size_t>(kf.direction);
      const Field mine = p.fine[ud];
      const Field theirs = kf.neighbour->field(vec.group[ud], comp);
      Index n{child.n[0], child.n[1], child.n[2]};
      n[ud] = 1;
      for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
          for (int i = 0; i < n[0]; ++i) {
            Index a{i, j, k}, b{i, j, k};
            a[ud] = kf.upper ? child.n[ud] : 0;
            b[ud] = kf.upper ? 0 : kf.neighbour->n[ud];
            at(mine, a) = at(theirs, b);
          }
    }
    for (int k = lo[2]; k < hi[2]; ++k)
      for (int j = lo[1]; j < hi[1]; ++j)
        for (int i = lo[0]; i < hi[0]; ++i) p.cell({i, j, k});
  }
}

}  // namespace remnant::grid
