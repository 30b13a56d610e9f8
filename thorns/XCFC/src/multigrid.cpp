// FAS multigrid (see include/XCFC/multigrid.hpp): levels, boundary ghosts, red-black Newton-Gauss-
// Seidel, transfer operators, V-cycles and full multigrid.
//
// MPI: arrays are complete on every rank, only the work is split. Each level of dimension >= 2 that
// is large enough is cut in slabs of planes along its last used direction (k in 3D, j in 2D); a
// rank computes its own planes and keeps one halo plane on each side current by MPI_Sendrecv before
// every stencil operation. Smaller (coarser) levels are computed by every rank redundantly, from
// inputs made complete by MPI_Allgatherv. Every cell update reads exactly the values it reads in
// the serial code, in the same order, so results are bit-identical for any rank count.
#include "XCFC/multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <type_traits>

#include "level.hpp"

namespace remnant::xcfc {

struct Multigrid::Impl {
  std::vector<Level> levels;
  CellFrames frames;
  MPI_Comm comm = MPI_COMM_SELF;
  int rank = 0, nranks = 1;
  long long relaxed_fine = 0, relaxed_all = 0;  // this rank's relaxed cells in the current solve

  // Work partition of one level. Owned planes [lo, hi) along direction s (all of them when not
  // distributed); 2D: the lines along s are solved whole, split by i instead: [line_lo, line_hi).
  struct Part {
    bool dist = false;
    int s = 0, lo = 0, hi = 1, line_lo = 0, line_hi = 1;
    bool flip = false;  // 2D, the origin's mirror cell lies at theta index n1-1-j: on another rank
    std::ptrdiff_t plane = 0, iplane = 0;  // ghosted / interior plane sizes along s
    // MPI_Allgatherv layouts per rank: ghosted planes, interior planes, the i = 0 column (flip),
    // and the packed column blocks of the line split.
    std::vector<int> counts, displs, icounts, idispls, col_counts, col_displs, blk_counts, blk_displs;
    std::vector<double> sbuf, rbuf, gbuf;  // exchange buffers (no allocation in the cycles)
  };
  std::vector<Part> parts;
  // Below this a level is not split: the halo messages would cost more than the work saved.
  static constexpr std::size_t kMinCells = 1024;

  // Interior cells of a level as index ranges (i always complete).
  struct Range {
    int j0, j1, k0, k1;
  };
  Range full(std::size_t l) const {
    const GridShape& s = levels[l].shape;
    return {0, s.n[1], 0, s.n[2]};
  }
  Range range(std::size_t l) const {
    Range r = full(l);
    const Part& p = parts[l];
    if (p.dist) (p.s == 2 ? r.k0 : r.j0) = p.lo, (p.s == 2 ? r.k1 : r.j1) = p.hi;
    return r;
  }

  Impl(const GridShape& shape, MPI_Comm c) {
    if (c != MPI_COMM_SELF) {
      MPI_Comm_dup(c, &comm);  // own tag space: no mix-up with the Grid's messages
      MPI_Comm_rank(comm, &rank);
      MPI_Comm_size(comm, &nranks);
    }
    levels.emplace_back(shape);
    {
      const Level& L = levels[0];
      frames.J.assign(L.ghosted_size, Matrix3{});
      frames.f.assign(L.ghosted_size, Point3{1, 1, 1});
      for (int k = -L.g[2]; k < shape.n[2] + L.g[2]; ++k)
        for (int j = -L.g[1]; j < shape.n[1] + L.g[1]; ++j)
          for (int i = -L.g[0]; i < shape.n[0] + L.g[0]; ++i) {
            const Point3 x = shape.point(i, j, k);
            const auto p = static_cast<std::size_t>(L.at(i, j, k));
            frames.J[p] = coords::jacobian(shape.coordinates, x);
            frames.f[p] = coords::metric_diagonal(shape.coordinates, x);
          }
    }
    for (;;) {
      const GridShape& s = levels.back().shape;
      GridShape c = s;
      bool coarsened = false;
      std::array<int, 3> ratio{1, 1, 1};
      for (int d = 0; d < 3; ++d)
        if (s.used(d) && s.n[d] % 2 == 0 && s.n[d] >= 4) {
          ratio[d] = 2;
          c.n[d] = s.n[d] / 2;
          c.dx[d] = 2 * s.dx[d];
          coarsened = true;
        }
      if (!coarsened) break;
      levels.back().ratio = ratio;
      levels.emplace_back(c);
    }
    // Restriction weights: the fine volumes summed per coarse cell (in the order of restriction).
    for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
      const Level& F = levels[l];
      Level& C = levels[l + 1];
      C.restrict_volume.assign(C.cells(), 0.0);
      const GridShape& fs = F.shape;
      for (int k = 0; k < fs.n[2]; ++k)
        for (int j = 0; j < fs.n[1]; ++j)
          for (int i = 0; i < fs.n[0]; ++i)
            C.restrict_volume[C.cell(i / F.ratio[0], j / F.ratio[1], k / F.ratio[2])] += F.volume[F.cell(i, j, k)];
    }
    partition();
  }
  ~Impl() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (comm != MPI_COMM_SELF && !finalized) MPI_Comm_free(&comm);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  // ---- MPI work partition ------------------------------------------------------------------------
  bool splittable(const GridShape& s) const {
    if (nranks < 2 || s.dimension < 2) return false;
    return s.n[s.dimension - 1] >= 2 * nranks && s.n[0] >= nranks && s.cells() >= kMinCells;
  }
  // The leading splittable levels are distributed. The coarsest of them is split as evenly as
  // possible and the finer ones inherit its cuts times the coarsening ratios (nested slabs), so
  // restriction and prolongation between distributed levels stay rank-local apart from the halos.
  void partition() {
    parts.assign(levels.size(), Part{});
    for (std::size_t l = 0; l < levels.size(); ++l) {
      const Level& L = levels[l];
      Part& p = parts[l];
      p.s = L.shape.dimension - 1;
      p.hi = L.shape.n[p.s];
      p.line_hi = L.shape.n[0];
    }
    std::size_t D = 0;
    while (D < levels.size() && splittable(levels[D].shape)) ++D;
    if (D == 0) return;
    const int sd = levels[0].shape.dimension - 1;
    const auto P = static_cast<std::size_t>(nranks);
    std::vector<int> b(P + 1);
    for (std::size_t r = 0; r <= P; ++r) b[r] = static_cast<int>(static_cast<long long>(r) * levels[D - 1].shape.n[sd] / nranks);
    for (std::size_t l = D; l-- > 0;) {
      if (l + 1 < D)
        for (int& x : b) x *= levels[l].ratio[sd];
      const Level& L = levels[l];
      const GridShape& sh = L.shape;
      Part& p = parts[l];
      p.dist = true;
      p.lo = b[static_cast<std::size_t>(rank)], p.hi = b[static_cast<std::size_t>(rank) + 1];
      p.flip = sh.dimension == 2 && sh.boundary[0][0] == Boundary::origin && sh.origin_flips_theta();
      p.plane = L.st[sd];
      p.iplane = sd == 2 ? static_cast<std::ptrdiff_t>(sh.n[0]) * sh.n[1] : sh.n[0];
      for (auto* v : {&p.counts, &p.displs, &p.icounts, &p.idispls, &p.col_counts, &p.col_displs, &p.blk_counts, &p.blk_displs})
        v->assign(P, 0);
      for (std::size_t r = 0; r < P; ++r) {
        const int planes = b[r + 1] - b[r];
        p.counts[r] = static_cast<int>(planes * p.plane), p.displs[r] = static_cast<int>((b[r] + 1) * p.plane);
        p.icounts[r] = static_cast<int>(planes * p.iplane), p.idispls[r] = static_cast<int>(b[r] * p.iplane);
        p.col_counts[r] = planes, p.col_displs[r] = b[r];
      }
      if (sh.dimension == 2) {
        const int n0 = sh.n[0], n1 = sh.n[1];
        auto cut = [&](std::size_t r) { return static_cast<int>(static_cast<long long>(r) * n0 / nranks); };
        for (std::size_t r = 0; r < P; ++r)
          p.blk_counts[r] = (cut(r + 1) - cut(r)) * n1, p.blk_displs[r] = cut(r) * n1;
        p.line_lo = cut(static_cast<std::size_t>(rank)), p.line_hi = cut(static_cast<std::size_t>(rank) + 1);
        p.sbuf.assign(static_cast<std::size_t>(std::max((p.line_hi - p.line_lo) * n1, n1)), 0.0);
        p.rbuf.assign(static_cast<std::size_t>(n1), 0.0);
        p.gbuf.assign(sh.cells(), 0.0);
      }
    }
  }
  int neighbour(int dr) const {
    const int r = rank + dr;
    return r >= 0 && r < nranks ? r : MPI_PROC_NULL;
  }
  double global_max(double m) const {
    if (nranks > 1) MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_MAX, comm);
    return m;
  }
  // Owned planes (with their in-plane ghosts) of a ghosted or interior array to every rank.
  void replicate(std::size_t l, std::vector<double>& a, bool ghosted) const {
    const Part& p = parts[l];
    if (!p.dist) return;
    MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, a.data(), ghosted ? p.counts.data() : p.icounts.data(),
                   ghosted ? p.displs.data() : p.idispls.data(), MPI_DOUBLE, comm);
  }
  // The halo planes lo-1 and hi of a ghosted array from the neighbouring ranks (and, where the
  // origin's mirror crosses ranks, the column i = 0): what the stencils of the owned cells and the
  // boundary ghosts they read need.
  void halo(std::size_t l, std::vector<double>& a) {
    Part& p = parts[l];
    if (!p.dist) return;
    double* v = a.data();
    const int w = static_cast<int>(p.plane);
    auto plane = [&](int k) { return v + (k + 1) * p.plane; };
    MPI_Sendrecv(plane(p.hi - 1), w, MPI_DOUBLE, neighbour(1), 11, plane(p.lo - 1), w, MPI_DOUBLE, neighbour(-1), 11, comm,
                 MPI_STATUS_IGNORE);
    MPI_Sendrecv(plane(p.lo), w, MPI_DOUBLE, neighbour(-1), 12, plane(p.hi), w, MPI_DOUBLE, neighbour(1), 12, comm,
                 MPI_STATUS_IGNORE);
    if (!p.flip) return;
    const Level& L = levels[l];
    for (int j = p.lo; j < p.hi; ++j) p.sbuf[static_cast<std::size_t>(j - p.lo)] = v[L.at(0, j, 0)];
    MPI_Allgatherv(p.sbuf.data(), p.hi - p.lo, MPI_DOUBLE, p.rbuf.data(), p.col_counts.data(), p.col_displs.data(),
                   MPI_DOUBLE, comm);
    for (int j = 0; j < L.shape.n[1]; ++j) v[L.at(0, j, 0)] = p.rbuf[static_cast<std::size_t>(j)];
  }
  // 2D line split (lines along j, owned by i): the neighbouring lines line_lo-1 and line_hi.
  void exchange_columns(std::size_t l, std::vector<double>& a) {
    Part& p = parts[l];
    const Level& L = levels[l];
    const int n1 = L.shape.n[1];
    double* v = a.data();
    auto pack = [&](int i) {
      for (int j = 0; j < n1; ++j) p.sbuf[static_cast<std::size_t>(j)] = v[L.at(i, j, 0)];
    };
    auto unpack = [&](int i) {
      for (int j = 0; j < n1; ++j) v[L.at(i, j, 0)] = p.rbuf[static_cast<std::size_t>(j)];
    };
    pack(p.line_hi - 1);
    MPI_Sendrecv(p.sbuf.data(), n1, MPI_DOUBLE, neighbour(1), 13, p.rbuf.data(), n1, MPI_DOUBLE, neighbour(-1), 13, comm,
                 MPI_STATUS_IGNORE);
    if (rank > 0) unpack(p.line_lo - 1);
    pack(p.line_lo);
    MPI_Sendrecv(p.sbuf.data(), n1, MPI_DOUBLE, neighbour(-1), 14, p.rbuf.data(), n1, MPI_DOUBLE, neighbour(1), 14, comm,
                 MPI_STATUS_IGNORE);
    if (rank + 1 < nranks) unpack(p.line_hi);
  }
  // 2D line split: the owned lines to every rank (the whole interior complete again).
  void gather_columns(std::size_t l, std::vector<double>& a) {
    Part& p = parts[l];
    const Level& L = levels[l];
    const int n0 = L.shape.n[0], n1 = L.shape.n[1];
    double* v = a.data();
    std::size_t m = 0;
    for (int i = p.line_lo; i < p.line_hi; ++i)
      for (int j = 0; j < n1; ++j) p.sbuf[m++] = v[L.at(i, j, 0)];
    MPI_Allgatherv(p.sbuf.data(), static_cast<int>(m), MPI_DOUBLE, p.gbuf.data(), p.blk_counts.data(), p.blk_displs.data(),
                   MPI_DOUBLE, comm);
    m = 0;
    for (int i = 0; i < n0; ++i)
      for (int j = 0; j < n1; ++j) v[L.at(i, j, 0)] = p.gbuf[m++];
  }
  void count(std::size_t l, long long n) {
    relaxed_all += n;
    if (l == 0) relaxed_fine += n;
  }

  // ---- boundary ghosts -------------------------------------------------------------------------
  // Fills the face ghosts of a ghosted array (no corners: no stencil uses them). `homogeneous`:
  // the conditions of a correction (far value 0, Dirichlet value 0).
  static void fill_ghosts(const Level& L, const ScalarEquation& eq, std::vector<double>& a, bool homogeneous) {
    const GridShape& s = L.shape;
    double* v = a.data();
    for (int d = 0; d < 3; ++d) {
      if (!s.used(d)) continue;
      for (int side = 0; side < 2; ++side) {
        const Level::GhostFace& gf = L.ghost_faces[d][side];
        const std::ptrdiff_t *g = gf.ghost.data(), *in = gf.inner.data(), *mi = gf.mirror.data();
        const std::size_t count = gf.ghost.size();
        if (s.boundary[d][side] != Boundary::outer) {
          const double parity = eq.parity[d][side];
          for (std::size_t t = 0; t < count; ++t) v[g[t]] = parity * v[mi[t]];
        } else if (eq.dirichlet) {
          fill_dirichlet(L, eq, a, homogeneous, d, side);
        } else {
          const double u_inf = homogeneous ? 0.0 : eq.far_value;
          const std::vector<double>& r = eq.falloff == 2.0 ? L.robin2[d][side] : L.robin1[d][side];
          const bool power = eq.falloff != 1.0 && eq.falloff != 2.0;
          for (std::size_t t = 0; t < count; ++t) {
            const double ratio = power ? std::pow(r[t], eq.falloff) : r[t];
            v[g[t]] = u_inf + (v[in[t]] - u_inf) * ratio;
          }
        }
      }
    }
  }
  // Dirichlet values at the outer faces (manufactured solutions only: a callback per ghost).
  static void fill_dirichlet(const Level& L, const ScalarEquation& eq, std::vector<double>& a, bool homogeneous, int d,
                             int side) {
    const GridShape& s = L.shape;
    const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
    const Level::GhostFace& gf = L.ghost_faces[d][side];
    std::size_t t = 0;
    for (int t2 = 0; t2 < s.n[e2]; ++t2)
      for (int t1 = 0; t1 < s.n[e1]; ++t1, ++t) {
        std::array<int, 3> g{};
        g[d] = side == 0 ? -1 : s.n[d], g[e1] = t1, g[e2] = t2;
        Point3 xf = s.point(g[0], g[1], g[2]);
        xf[d] = s.face(d, side == 0 ? 0 : s.n[d]);
        const double inner = a[static_cast<std::size_t>(gf.inner[t])];
        a[static_cast<std::size_t>(gf.ghost[t])] = (homogeneous ? 0.0 : 2.0 * eq.dirichlet(xf)) - inner;
      }
  }

  // ---- pointwise operator ------------------------------------------------------------------------
  // Raw pointers of one level's operator and equation, hoisted out of the cell loops (s1, s7 null
  // when absent).
  struct Ops {
    const double* lo[3]{};
    const double* hi[3]{};
    const double *diag, *k, *s0, *s1, *s7, *f;
    std::ptrdiff_t st[3];
    explicit Ops(const Level& L)
        : diag(L.diagonal.data()), k(L.k.data()), s0(L.s0.data()), s1(L.s1.empty() ? nullptr : L.s1.data()),
          s7(L.s7.empty() ? nullptr : L.s7.data()), f(L.f.data()), st{L.st[0], L.st[1], L.st[2]} {
      for (int d = 0; d < 3; ++d)
        if (!L.a_lo[d].empty()) lo[d] = L.a_lo[d].data(), hi[d] = L.a_hi[d].data();
    }
    bool nonlinear() const { return s1 || s7; }
    double source(std::size_t q, double u) const {
      double r = k[q] * u + s0[q];
      if (s1) r += s1[q] / u;
      if (s7) {
        const double i2 = 1.0 / (u * u), i3 = i2 / u;
        r += s7[q] * i3 * i3 / u;
      }
      return r;
    }
    double source_derivative(std::size_t q, double u) const {
      double r = k[q];
      if (s1) r -= s1[q] / (u * u);
      if (s7) {
        const double i2 = 1.0 / (u * u), i4 = i2 * i2;
        r -= 7.0 * s7[q] * i4 * i4;
      }
      return r;
    }
    // Source and its derivative with one reciprocal (the nonlinear line relaxation).
    double source_and_derivative(std::size_t q, double u, double& dR) const {
      const double i1 = 1.0 / u;
      double r = k[q] * u + s0[q];
      dR = k[q];
      if (s1) r += s1[q] * i1, dR -= s1[q] * i1 * i1;
      if (s7) {
        const double i2 = i1 * i1, i4 = i2 * i2, i7 = i4 * i2 * i1;
        r += s7[q] * i7, dR -= 7.0 * s7[q] * i7 * i1;
      }
      return r;
    }
    template <int D>
    double sigma(const double* u, std::ptrdiff_t p, std::size_t q) const {
      double s = lo[0][q] * u[p - 1] + hi[0][q] * u[p + 1];
      if constexpr (D >= 2) s += lo[1][q] * u[p - st[1]] + hi[1][q] * u[p + st[1]];
      if constexpr (D >= 3) s += lo[2][q] * u[p - st[2]] + hi[2][q] * u[p + st[2]];
      return s;
    }
  };

  // Calls f(q, p) for every interior cell of a range in storage order (q interior, p ghosted).
  template <class F>
  static void for_cells(const Level& L, const Range& R, F&& f) {
    const GridShape& s = L.shape;
    for (int k = R.k0; k < R.k1; ++k)
      for (int j = R.j0; j < R.j1; ++j) {
        std::size_t q = L.cell(0, j, k);
        std::ptrdiff_t p = L.at(0, j, k);
        for (int i = 0; i < s.n[0]; ++i, ++q, ++p) f(q, p);
      }
  }
  template <class F>
  static void dispatch(int dimension, F&& f) {
    if (dimension == 1) f(std::integral_constant<int, 1>{});
    else if (dimension == 2) f(std::integral_constant<int, 2>{});
    else f(std::integral_constant<int, 3>{});
  }

  static void apply(const Level& L, const std::vector<double>& u, std::vector<double>& out, const Range& R) {
    const Ops o(L);
    const double* uu = u.data();
    double* r = out.data();
    dispatch(L.shape.dimension, [&](auto D) {
      for_cells(L, R, [&](std::size_t q, std::ptrdiff_t p) {
        const double uc = uu[p];
        r[q] = o.template sigma<D()>(uu, p, q) - o.diag[q] * uc - o.source(q, uc);
      });
    });
  }

  // r = f - A(u) on the owned cells; returns max|r| over all ranks (a max is exact in any order).
  double residual(std::size_t l, const ScalarEquation& eq) {
    Level& L = levels[l];
    halo(l, L.u);
    fill_ghosts(L, eq, L.u, false);
    const Range R = range(l);
    apply(L, L.u, L.r, R);
    double m = 0;
    double* r = L.r.data();
    const double* f = L.f.data();
    for_cells(L, R, [&](std::size_t q, std::ptrdiff_t) {
      r[q] = f[q] - r[q];
      m = std::max(m, std::abs(r[q]));
    });
    return global_max(m);
  }

  // Max of the source terms' magnitudes at u: the scale of the residual.
  double source_scale(std::size_t l) const {
    const Level& L = levels[l];
    const Ops o(L);
    double m = 0;
    for_cells(L, range(l), [&](std::size_t q, std::ptrdiff_t p) {
      const double u = L.u[static_cast<std::size_t>(p)];
      double t = std::abs(o.k[q] * u) + std::abs(o.s0[q]);
      if (o.s1) t += std::abs(o.s1[q] / u);
      if (o.s7) {
        const double u2 = u * u, u3 = u2 * u;
        t += std::abs(o.s7[q] / (u3 * u3 * u));
      }
      m = std::max(m, t);
    });
    return global_max(m);
  }

  // Red-black Gauss-Seidel, one Newton step per cell. A colour's cells read only the other colour:
  // with the halo planes exchanged between colours, the owned slab is updated as in one rank.
  template <int D>
  void smooth_dim(std::size_t l, const ScalarEquation& eq, int sweeps) {
    Level& L = levels[l];
    const GridShape& s = L.shape;
    const Ops o(L);
    double* u = L.u.data();
    const bool nonlinear = o.nonlinear();
    const Range R = range(l);
    long long n = 0;
    for (int sweep = 0; sweep < sweeps; ++sweep)
      for (int colour = 0; colour < 2; ++colour) {
        halo(l, L.u);
        fill_ghosts(L, eq, L.u, false);
        for (int k = R.k0; k < R.k1; ++k)
          for (int j = R.j0; j < R.j1; ++j) {
            const int i0 = (j + k + colour) & 1;
            n += (s.n[0] - i0 + 1) / 2;
            std::size_t q = L.cell(i0, j, k);
            std::ptrdiff_t p = L.at(i0, j, k);
            for (int i = i0; i < s.n[0]; i += 2, q += 2, p += 2) {
              const double uc = u[p];
              const double res = o.sigma<D>(u, p, q) - o.diag[q] * uc - o.source(q, uc) - o.f[q];
              const double jac = -o.diag[q] - o.source_derivative(q, uc);
              double un = uc - res / jac;
              if (nonlinear && !(un > 0.1 * uc)) un = 0.5 * uc;  // keep psi-like unknowns positive
              u[p] = un;
            }
          }
      }
    count(l, n);
  }
  void smooth(std::size_t l, const ScalarEquation& eq, int sweeps) {
    dispatch(levels[l].shape.dimension, [&](auto D) { smooth_dim<D()>(l, eq, sweeps); });
  }

  // Line geometry of direction d on a 1D or 2D level: lines are indexed by t along the transverse
  // direction e (none in 1D); interior and ghosted strides along and across the lines.
  struct Lines {
    int d, e, n, count;
    std::ptrdiff_t qd, qe, pd, pe;
    Lines(const Level& L, int dir) : d(dir), e(L.shape.dimension == 2 ? 1 - dir : -1), n(L.shape.n[dir]) {
      const GridShape& s = L.shape;
      count = e < 0 ? 1 : s.n[e];
      qd = d == 0 ? 1 : s.n[0];
      qe = e == 0 ? 1 : s.n[0];
      pd = L.st[d];
      pe = e < 0 ? 0 : L.st[e];
    }
    std::size_t q0(int t) const { return static_cast<std::size_t>(t * qe); }
    std::ptrdiff_t p0(const Level& L, int t) const { return d == 0 ? L.at(0, e < 0 ? 0 : t, 0) : L.at(t, 0, 0); }
  };

  // Line ends: ghost = c0 + c1 * u_end, c1 from the boundary kind (the Robin ratio is geometry);
  // c0 is taken from the current ghost in the relaxation.
  static void set_line_ends(Level& L, const ScalarEquation& eq) {
    const GridShape& s = L.shape;
    if (s.dimension > 2) return;
    for (int d = 0; d < s.dimension; ++d) {
      const Lines ln(L, d);
      for (int side = 0; side < 2; ++side) {
        const Boundary bc = s.boundary[d][side];
        for (int t = 0; t < ln.count; ++t) {
          double c1 = eq.parity[d][side];
          if (bc == Boundary::outer) {
            const double ratio = L.robin1[d][side][static_cast<std::size_t>(t)];
            c1 = eq.dirichlet ? -1.0 : eq.falloff == 1.0 ? ratio
                                     : eq.falloff == 2.0 ? L.robin2[d][side][static_cast<std::size_t>(t)]
                                                         : std::pow(ratio, eq.falloff);
          } else if (bc == Boundary::origin && s.used(1) && s.origin_flips_theta()) {
            c1 = 0.0;  // the mirror cell lies on another line: its value is held
          }
          L.end_c1[d][side][static_cast<std::size_t>(t)] = c1;
        }
      }
    }
  }

  // Thomas forward-elimination factors of the (fixed) line matrices of a linear equation.
  static void factor_lines(Level& L) {
    const GridShape& s = L.shape;
    L.factored = false;
    if (s.dimension > 2 || !L.s1.empty() || !L.s7.empty()) return;
    for (int d = 0; d < s.dimension; ++d) {
      const Lines ln(L, d);
      const double *alo = L.a_lo[d].data(), *ahi = L.a_hi[d].data();
      const double *c1lo = L.end_c1[d][0].data(), *c1hi = L.end_c1[d][1].data();
      double *w = L.line_w[d].data(), *inv = L.line_inv[d].data();
      for (int t = 0; t < ln.count; ++t) {
        std::size_t q = ln.q0(t);
        double prev_inv = 0, prev_up = 0;
        for (int m = 0; m < ln.n; ++m, q += static_cast<std::size_t>(ln.qd)) {
          double di = -L.diagonal[q] - L.k[q];
          if (m == 0) di += alo[q] * c1lo[t];
          if (m == ln.n - 1) di += ahi[q] * c1hi[t];
          const double wm = m == 0 ? 0.0 : alo[q] * prev_inv;
          di -= wm * prev_up;
          w[q] = wm;
          inv[q] = prev_inv = 1.0 / di;
          prev_up = ahi[q];
        }
      }
    }
    L.factored = true;
  }

  // Zebra line Gauss-Seidel along direction d (Thomas algorithm): robust against the anisotropy of
  // spherical grids (theta coupling dominates near the origin, radial coupling far out). Linear
  // equations use the factors of factor_lines (substitutions only); nonlinear ones take one Newton
  // linearisation per line. Line ends take the boundary ghost as an affine function of the end
  // cell; other ghosts are held. In 1D the single line is an exact (Newton) solve.
  // Lines t0 <= t < t1 of one colour; returns the number of cells relaxed.
  template <bool Factored>
  static long long line_pass(Level& L, const Lines& ln, int colour, int t0, int t1) {
    const Ops o(L);
    const int d = ln.d, n = ln.n;
    double* u = L.u.data();
    const double *alo = o.lo[d], *ahi = o.hi[d];
    const double *tlo = ln.e < 0 ? nullptr : o.lo[ln.e], *thi = ln.e < 0 ? nullptr : o.hi[ln.e];
    const double *c1lo = L.end_c1[d][0].data(), *c1hi = L.end_c1[d][1].data();
    const double *w = L.line_w[d].data(), *inv = L.line_inv[d].data();
    double *r = L.line_rhs.data(), *dd = L.line_di.data();
    const bool nonlinear = o.nonlinear();
    const std::ptrdiff_t pd = ln.pd, pe = ln.pe, qd = ln.qd;
    long long cells = 0;
    for (int t = t0 + ((colour - t0) & 1); t < t1; t += 2, cells += n) {
      const std::size_t q0 = ln.q0(t);
      const std::ptrdiff_t p0 = ln.p0(L, t);
      // Right-hand sides and forward elimination in one pass.
      double prev_r = 0, prev_d = 1, prev_up = 0;  // prev_d: inverse pivot
      std::size_t q = q0;
      std::ptrdiff_t p = p0;
      for (int m = 0; m < n; ++m, q += static_cast<std::size_t>(qd), p += pd) {
        const double u0 = u[p];
        double b = o.f[q];
        if (tlo) b -= tlo[q] * u[p - pe] + thi[q] * u[p + pe];
        if (m == 0) b -= alo[q] * (u[p - pd] - c1lo[t] * u0);
        if (m == n - 1) b -= ahi[q] * (u[p + pd] - c1hi[t] * u0);
        if constexpr (Factored) {
          b += o.s0[q];
          prev_r = b - w[q] * prev_r;
        } else {
          double dR;
          b += o.source_and_derivative(q, u0, dR) - dR * u0;
          double di = -o.diag[q] - dR;
          if (m == 0) di += alo[q] * c1lo[t];
          if (m == n - 1) di += ahi[q] * c1hi[t];
          if (m > 0) {
            const double wm = alo[q] * prev_d;
            di -= wm * prev_up;
            b -= wm * prev_r;
          }
          prev_r = b, prev_d = dd[m] = 1.0 / di, prev_up = ahi[q];
        }
        r[m] = prev_r;
      }
      // Back substitution.
      double x = 0;
      for (int m = n - 1; m >= 0; --m) {
        q -= static_cast<std::size_t>(qd), p -= pd;
        if constexpr (Factored) {
          x = (r[m] - ahi[q] * x) * inv[q];
          u[p] = x;
        } else {
          x = (r[m] - ahi[q] * x) * dd[m];  // x = 0 at the last cell
          double un = x;
          if (nonlinear && !(un > 0.1 * u[p])) un = 0.5 * u[p];
          u[p] = un;
        }
      }
    }
    return cells;
  }
  // One zebra pass. Distributed 2D levels: lines across the slabs (d = s) are local to the slab and
  // need the halo rows between colours; lines along s cross the slabs, so they are solved whole,
  // split by i, from a complete level (Allgatherv), with the neighbouring lines exchanged between
  // colours and the result made complete again.
  void smooth_lines(std::size_t l, const ScalarEquation& eq, int d) {
    Level& L = levels[l];
    const Part& p = parts[l];
    const Lines ln(L, d);
    const bool along = p.dist && d == p.s;
    int t0 = 0, t1 = ln.count;
    if (along) t0 = p.line_lo, t1 = p.line_hi, replicate(l, L.u, true);
    else if (p.dist) t0 = p.lo, t1 = p.hi;
    long long n = 0;
    for (int colour = 0; colour < (ln.count > 1 ? 2 : 1); ++colour) {
      if (along) {
        if (colour > 0) exchange_columns(l, L.u);
      } else {
        halo(l, L.u);
      }
      fill_ghosts(L, eq, L.u, false);
      n += L.factored ? line_pass<true>(L, ln, colour, t0, t1) : line_pass<false>(L, ln, colour, t0, t1);
    }
    if (along) gather_columns(l, L.u);
    count(l, n);
  }

  // Local relaxation next to the spherical origin (Brandt): the large coefficients there leave the
  // largest residual after a red-black sweep, which otherwise dominates the L-infinity stopping
  // test for V-cycles after the rest of the grid has converged.
  void relax_origin(std::size_t l, const ScalarEquation& eq) {
    Level& L = levels[l];
    const GridShape& s = L.shape;
    if (s.dimension != 1 || s.boundary[0][0] != Boundary::origin) return;
    count(l, 2 * std::min(s.n[0], 4));
    double* u = L.u.data();
    const Ops o(L);
    const bool nonlinear = o.nonlinear();
    const int m = std::min(s.n[0], 4);
    for (int pass = 0; pass < 2; ++pass) {
      u[L.at(-1, 0, 0)] = eq.parity[0][0] * u[L.at(0, 0, 0)];
      for (int i = 0; i < m; ++i) {
        const std::size_t q = static_cast<std::size_t>(i);
        const std::ptrdiff_t p = L.at(i, 0, 0);
        const double uc = u[p];
        const double res = o.sigma<1>(u, p, q) - o.diag[q] * uc - o.source(q, uc) - o.f[q];
        double un = uc - res / (-o.diag[q] - o.source_derivative(q, uc));
        if (nonlinear && !(un > 0.1 * uc)) un = 0.5 * uc;
        u[p] = un;
        if (i == 0) u[L.at(-1, 0, 0)] = eq.parity[0][0] * un;
      }
    }
  }

  // Point red-black smoothing in 1D and isotropic 3D, alternating line smoothing in 2D.
  void relax(std::size_t l, const ScalarEquation& eq, int sweeps) {
    if (levels[l].shape.dimension != 2) {
      smooth(l, eq, sweeps);
      return relax_origin(l, eq);
    }
    for (int sweep = 0; sweep < sweeps; ++sweep)
      for (int d = 0; d < 2; ++d) smooth_lines(l, eq, d);
  }

  // ---- transfers ---------------------------------------------------------------------------------
  // Volume-weighted restriction of an interior array (fine -> coarse) over the fine cells RF, which
  // cover the coarse cells RC (nested slabs): each coarse sum adds its fine cells in storage order.
  static void restrict_interior(const Level& F, const Level& C, const std::vector<double>& fine,
                                std::vector<double>& coarse, const Range& RF, const Range& RC) {
    coarse.assign(C.cells(), 0.0);
    const GridShape& s = F.shape;
    for (int k = RF.k0; k < RF.k1; ++k)
      for (int j = RF.j0; j < RF.j1; ++j)
        for (int i = 0; i < s.n[0]; ++i) {
          const std::size_t q = F.cell(i, j, k);
          coarse[C.cell(i / F.ratio[0], j / F.ratio[1], k / F.ratio[2])] += F.volume[q] * fine[q];
        }
    for_cells(C, RC, [&](std::size_t q, std::ptrdiff_t) { coarse[q] /= C.restrict_volume[q]; });
  }
  // The same from and to ghosted arrays (coarse ghosts zeroed, to be filled by the caller).
  static void restrict_ghosted(const Level& F, const Level& C, const std::vector<double>& fine,
                               std::vector<double>& coarse, const Range& RF, const Range& RC) {
    coarse.assign(C.ghosted_size, 0.0);
    const GridShape& s = F.shape;
    for (int k = RF.k0; k < RF.k1; ++k)
      for (int j = RF.j0; j < RF.j1; ++j)
        for (int i = 0; i < s.n[0]; ++i)
          coarse[static_cast<std::size_t>(C.at(i / F.ratio[0], j / F.ratio[1], k / F.ratio[2]))] +=
              F.volume[F.cell(i, j, k)] * fine[static_cast<std::size_t>(F.at(i, j, k))];
    for_cells(C, RC, [&](std::size_t q, std::ptrdiff_t p) { coarse[static_cast<std::size_t>(p)] /= C.restrict_volume[q]; });
  }
  // Adds (or, with `replace`, writes) the linear interpolation of a ghosted coarse array: each fine
  // cell takes the coarse value plus a quarter of the central coarse slope per refined direction.
  // Fine cells RF only; the coarse values they read are owned, halo or boundary ghosts.
  static void prolong(const Level& C, const Level& F, const std::vector<double>& coarse, std::vector<double>& fine,
                      bool replace, const Range& RF) {
    const GridShape& s = F.shape;
    for (int k = RF.k0; k < RF.k1; ++k)
      for (int j = RF.j0; j < RF.j1; ++j)
        for (int i = 0; i < s.n[0]; ++i) {
          const std::array<int, 3> f{i, j, k};
          std::array<int, 3> c{};
          for (int d = 0; d < 3; ++d) c[d] = f[d] / F.ratio[d];
          const std::ptrdiff_t pc = C.at(c[0], c[1], c[2]);
          double v = coarse[static_cast<std::size_t>(pc)];
          for (int d = 0; d < 3; ++d) {
            if (F.ratio[d] != 2) continue;
            const double sign = (f[d] & 1) ? 0.125 : -0.125;
            v += sign * (coarse[static_cast<std::size_t>(pc + C.st[d])] - coarse[static_cast<std::size_t>(pc - C.st[d])]);
          }
          double& out = fine[static_cast<std::size_t>(F.at(i, j, k))];
          out = replace ? v : out + v;
        }
  }

  // ---- cycles ------------------------------------------------------------------------------------
  // Coarsest level: relaxation to 1e-8 of the initial residual. A 1D level is one line, solved
  // exactly (linear) or by Newton line solves, so it needs no point sweeps at all.
  void coarse_solve(std::size_t l, const ScalarEquation& eq, int max_sweeps) {
    Level& L = levels[l];
    const double r0 = residual(l, eq);
    if (L.shape.dimension == 1) {
      for (int done = 0; done < max_sweeps; ++done) {
        smooth_lines(l, eq, 0);
        if (residual(l, eq) <= 1e-8 * r0) break;
      }
      return;
    }
    const int chunk = L.cells() <= 64 ? 2 : 10;  // tiny levels: check often, residuals are cheap
    for (int done = 0; done < max_sweeps; done += chunk) {
      relax(l, eq, chunk);
      if (residual(l, eq) <= 1e-8 * r0) break;
    }
  }

  void vcycle(std::size_t l, const ScalarEquation& eq, const SolveSettings& s) {
    Level& F = levels[l];
    if (l + 1 == levels.size()) {
      coarse_solve(l, eq, std::max(s.coarse_sweeps, 20 * static_cast<int>(F.cells())));
      return;
    }
    Level& C = levels[l + 1];
    relax(l, eq, s.pre_sweeps);
    residual(l, eq);
    // A coarse level computed by every rank needs the whole fine level on every rank.
    if (!parts[l + 1].dist) replicate(l, F.u, true), replicate(l, F.r, false);
    const Range RF = parts[l + 1].dist ? range(l) : full(l), RC = range(l + 1);
    restrict_ghosted(F, C, F.u, C.u, RF, RC);
    halo(l + 1, C.u);
    fill_ghosts(C, eq, C.u, false);
    C.ubar = C.u;
    restrict_interior(F, C, F.r, C.f, RF, RC);
    apply(C, C.ubar, C.r, RC);  // C.r as scratch: the coarse cycle recomputes it before use
    for_cells(C, RC, [&](std::size_t q, std::ptrdiff_t) { C.f[q] += C.r[q]; });
    // 2D: the lines along the split direction read f across all slabs.
    if (C.shape.dimension == 2) replicate(l + 1, C.f, false);
    vcycle(l + 1, eq, s);
    // The correction on the owned planes (all of a level that is not split), then its halos.
    const Part& pc = parts[l + 1];
    const std::size_t p0 = pc.dist ? static_cast<std::size_t>((pc.lo + 1) * pc.plane) : 0;
    const std::size_t p1 = pc.dist ? static_cast<std::size_t>((pc.hi + 1) * pc.plane) : C.u.size();
    for (std::size_t p = p0; p < p1; ++p) C.ubar[p] = C.u[p] - C.ubar[p];
    halo(l + 1, C.ubar);
    fill_ghosts(C, eq, C.ubar, true);
    prolong(C, F, C.ubar, F.u, false, range(l));
    relax(l, eq, s.post_sweeps);
  }

  void full_multigrid(const ScalarEquation& eq, const SolveSettings& s) {
    set_coarse_equations(eq);
    // The initial guess down the hierarchy by every rank (the finest level is complete).
    for (std::size_t l = 0; l + 1 < levels.size(); ++l)
      restrict_ghosted(levels[l], levels[l + 1], levels[l].u, levels[l + 1].u, full(l), full(l + 1));
    for (auto& L : levels) std::fill(L.f.begin(), L.f.end(), 0.0);
    coarse_solve(levels.size() - 1, eq, std::max(s.coarse_sweeps, 20 * static_cast<int>(levels.back().cells())));
    for (std::size_t l = levels.size() - 1; l-- > 0;) {
      halo(l + 1, levels[l + 1].u);
      fill_ghosts(levels[l + 1], eq, levels[l + 1].u, false);
      prolong(levels[l + 1], levels[l], levels[l + 1].u, levels[l].u, true, range(l));
      for (std::size_t m = l; m < levels.size(); ++m) std::fill(levels[m].f.begin(), levels[m].f.end(), 0.0);
      vcycle(l, eq, s);
    }
    replicate(0, levels[0].u, true);
  }

  // Equation coefficients: set_fine_equation on the finest level (all a residual needs);
  // set_coarse_equations on the coarse levels, line ends and line factors everywhere, only once a
  // cycle is needed (a warm start that already meets the tolerance costs one residual).
  void set_fine_equation(const ScalarEquation& eq) {
    Level& L0 = levels[0];
    const std::size_t n = L0.cells();
    auto copy = [&](const std::vector<double>& v, std::vector<double>& out) {
      if (v.empty()) out.assign(n, 0.0);
      else out.assign(v.begin(), v.end());
    };
    copy(eq.k, L0.k_eq);
    copy(eq.s0, L0.s0);
    if (eq.s1.empty()) L0.s1.clear(); else L0.s1.assign(eq.s1.begin(), eq.s1.end());
    if (eq.s7.empty()) L0.s7.clear(); else L0.s7.assign(eq.s7.begin(), eq.s7.end());
    // The geometric point term is rediscretised on each level, not restricted.
    L0.k = L0.k_eq;
    if (eq.mode != AngularMode::none) {
      const auto& mk = L0.mode_k[static_cast<int>(eq.mode)];
      for (std::size_t q = 0; q < n; ++q) L0.k[q] += mk[q];
    }
    L0.f.assign(n, 0.0);
    L0.r.resize(n);
    if (L0.u.size() != L0.ghosted_size) L0.u.assign(L0.ghosted_size, 0.0);
    L0.factored = false;
    coarse_ready = false;
  }
  void set_coarse_equations(const ScalarEquation& eq) {
    if (coarse_ready) return;
    for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
      Level &F = levels[l], &C = levels[l + 1];
      // Once per solve, by every rank: the coarse equations are complete everywhere.
      const Range RF = full(l), RC = full(l + 1);
      restrict_interior(F, C, F.k_eq, C.k_eq, RF, RC);
      restrict_interior(F, C, F.s0, C.s0, RF, RC);
      if (F.s1.empty()) C.s1.clear(); else restrict_interior(F, C, F.s1, C.s1, RF, RC);
      if (F.s7.empty()) C.s7.clear(); else restrict_interior(F, C, F.s7, C.s7, RF, RC);
      C.k = C.k_eq;
      if (eq.mode != AngularMode::none) {
        const auto& mk = C.mode_k[static_cast<int>(eq.mode)];
        for (std::size_t q = 0; q < C.k.size(); ++q) C.k[q] += mk[q];
      }
      C.f.resize(C.cells());
      C.r.resize(C.cells());
      if (C.u.size() != C.ghosted_size) C.u.assign(C.ghosted_size, 0.0);
    }
    for (auto& L : levels) {
      set_line_ends(L, eq);
      factor_lines(L);
    }
    coarse_ready = true;
  }
  bool coarse_ready = false;

  void load(const std::vector<double>& u) {
    Level& L = levels[0];
    const GridShape& s = L.shape;
    for (int k = 0; k < s.n[2]; ++k)
      for (int j = 0; j < s.n[1]; ++j)
        for (int i = 0; i < s.n[0]; ++i) L.u[static_cast<std::size_t>(L.at(i, j, k))] = u[L.cell(i, j, k)];
  }
  void store(std::vector<double>& u) const {
    const Level& L = levels[0];
    const GridShape& s = L.shape;
    for (int k = 0; k < s.n[2]; ++k)
      for (int j = 0; j < s.n[1]; ++j)
        for (int i = 0; i < s.n[0]; ++i) u[L.cell(i, j, k)] = L.u[static_cast<std::size_t>(L.at(i, j, k))];
  }
};

Multigrid::Multigrid(const GridShape& shape, MPI_Comm comm) : impl_(std::make_unique<Impl>(shape, comm)) {}
Multigrid::~Multigrid() = default;
Multigrid::Multigrid(Multigrid&&) noexcept = default;
Multigrid& Multigrid::operator=(Multigrid&&) noexcept = default;

const GridShape& Multigrid::shape() const { return impl_->levels[0].shape; }
int Multigrid::levels() const { return static_cast<int>(impl_->levels.size()); }
int Multigrid::distributed_levels() const {
  int n = 0;
  for (const auto& p : impl_->parts) n += p.dist ? 1 : 0;
  return n;
}

SolveStats Multigrid::solve(const ScalarEquation& eq, std::vector<double>& u, const SolveSettings& s) {
  Impl& m = *impl_;
  const std::size_t n = m.levels[0].cells();
  if (u.size() != n) u.assign(n, eq.nonlinear() ? 1.0 : 0.0);
  m.set_fine_equation(eq);
  m.load(u);
  m.relaxed_fine = m.relaxed_all = 0;
  SolveStats st;
  Level& L = m.levels[0];
  // No sources, no boundary values: the solution is zero (no cycles spent on round-off).
  const bool trivial = !eq.dirichlet && eq.far_value == 0.0 && !eq.nonlinear() &&
                       std::all_of(L.s0.begin(), L.s0.end(), [](double v) { return v == 0.0; });
  if (trivial) {
    std::fill(u.begin(), u.end(), 0.0);
    st.converged = true;
    return st;
  }
  // 1D: the whole level is one line, and a line solve is exact for linear equations (Newton for
  // psi), so each "cycle" is one tridiagonal solve on the finest level.
  const bool line_solve = s.direct_1d && L.shape.dimension == 1;
  if (s.full_multigrid && !line_solve) m.full_multigrid(eq, s);
  st.initial_residual = m.residual(0, eq);
  double res = st.initial_residual;
  auto scale = [&] {
    const double sc = std::max(m.source_scale(0), s.scale_floor);
    return sc > 0 ? sc : 1.0;
  };
  st.scale = scale();
  // Round-off floor of the residual: the largest operator term times a few ulps. Near the spherical
  // origin and axis the coefficients are large and a relative 1e-10 can lie below it.
  auto floor = [&] {
    const double m = L.max_diagonal;
    double umax = 0;
    for (double v : L.u) umax = std::max(umax, std::abs(v));
    return 256 * std::numeric_limits<double>::epsilon() * m * umax;
  };
  const double noise = floor();
  static const bool debug = std::getenv("XCFC_DEBUG") != nullptr;
  while (res > std::max(s.tolerance * st.scale, noise) && st.cycles < s.max_cycles) {
    m.set_coarse_equations(eq);
    if (line_solve) m.smooth_lines(0, eq, 0);
    else m.vcycle(0, eq, s);
    ++st.cycles;
    res = m.residual(0, eq);
    st.scale = scale();
    st.history.push_back(res);
    if (debug) {
      std::size_t at = 0;
      for (std::size_t q = 0; q < L.r.size(); ++q) if (std::abs(L.r[q]) > std::abs(L.r[at])) at = q;
      std::fprintf(stderr, "cycle %d residual %.3e at %zu (initial %.3e, target %.3e)\n", st.cycles, res, at, st.initial_residual, s.tolerance * st.scale);
    }
  }
  st.residual = res;
  st.converged = res <= std::max(s.tolerance * st.scale, noise);
  st.factor = st.cycles > 0 && st.initial_residual > 0 ? std::pow(res / st.initial_residual, 1.0 / st.cycles) : 0.0;
  st.relaxed_cells = m.relaxed_fine, st.relaxed_cells_all = m.relaxed_all;
  m.replicate(0, L.u, true);  // the solution complete on every rank
  m.store(u);
  return st;
}

double Multigrid::residual_norm(const ScalarEquation& eq, const std::vector<double>& u) {
  Impl& m = *impl_;
  m.set_fine_equation(eq);
  m.load(u);
  return m.residual(0, eq);
}

std::vector<double> Multigrid::with_ghosts(const ScalarEquation& eq, const std::vector<double>& u) const {
  const Level& L = impl_->levels[0];
  std::vector<double> a(L.ghosted_size, 0.0);
  const GridShape& s = L.shape;
  for (int k = 0; k < s.n[2]; ++k)
    for (int j = 0; j < s.n[1]; ++j)
      for (int i = 0; i < s.n[0]; ++i) a[static_cast<std::size_t>(L.at(i, j, k))] = u[L.cell(i, j, k)];
  Impl::fill_ghosts(L, eq, a, false);
  return a;
}

std::ptrdiff_t Multigrid::ghosted_index(int i, int j, int k) const { return impl_->levels[0].at(i, j, k); }
std::array<std::ptrdiff_t, 3> Multigrid::ghosted_strides() const { return impl_->levels[0].st; }
const CellFrames& Multigrid::frames() const { return impl_->frames; }

}  // namespace remnant::xcfc
