#include "work_partition.hpp"

#include <algorithm>
#include <stdexcept>

#include "remnant/comm_counters.hpp"

namespace remnant::xcfc {

WorkPartition::WorkPartition(MPI_Comm c) {
  if (c == MPI_COMM_SELF) return;
  MPI_Comm_dup(c, &comm);  // own tag space: no mix-up with the Grid's messages
  MPI_Comm_rank(comm, &rank_);
  MPI_Comm_size(comm, &nranks_);
}

WorkPartition::~WorkPartition() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (comm != MPI_COMM_SELF && !finalized) MPI_Comm_free(&comm);
}

Range WorkPartition::range(std::size_t l) const {
  Range r = full(l);
  const Part& p = parts[l];
  if (p.dist) (p.s == 2 ? r.k0 : r.j0) = p.lo, (p.s == 2 ? r.k1 : r.j1) = p.hi;
  return r;
}

Range WorkPartition::restricted_range(std::size_t l) const {
  const Part& p = parts[l];
  if (!p.agglomerated) return range(l);
  Range r = full(l);
  (p.s == 2 ? r.k0 : r.j0) = p.agg_lo, (p.s == 2 ? r.k1 : r.j1) = p.agg_hi;
  return r;
}

void WorkPartition::agglomerate(std::size_t l, std::vector<double>& a, bool ghosted) const {
  const Part& p = parts[l];
  if (!p.agglomerated) return;
  const auto& c = ghosted ? p.agg_gcounts : p.agg_counts;
  MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, a.data(), c.data(), ghosted ? p.agg_gdispls.data() : p.agg_displs.data(),
                 MPI_DOUBLE, comm);
  long long n = 0;
  for (int r = 0; r < nranks_; ++r) n += r == rank_ ? 0 : c[static_cast<std::size_t>(r)];
  received_ += static_cast<long long>(sizeof(double)) * n;
  comm::count("mg_base_allgather", comm::Pattern::allgather, static_cast<int>(l), 1, static_cast<long long>(sizeof(double)) * n);
}

bool WorkPartition::splittable(const GridShape& s) const {
  // 3D cylindrical and spherical levels are computed whole by every rank: their periodic and
  // axis images (phi + pi) lie on other ranks' slabs.
  if (nranks_ < 2 || s.dimension < 2 || s.turns_phi() || s.boundary[2][0] == Boundary::periodic) return false;
  return s.n[s.dimension - 1] >= 2 * nranks_ && s.n[0] >= nranks_ && s.cells() >= kMinCells;
}
// The leading splittable levels are distributed. The coarsest of them is split as evenly as
// possible and the finer ones inherit its cuts times the coarsening ratios (nested slabs), so
// restriction and prolongation between distributed levels stay rank-local apart from the halos.
std::vector<int> WorkPartition::line_cuts(int n0, int extra) const {
  const int P = nranks_;
  std::vector<int> c(static_cast<std::size_t>(P) + 1, n0);
  c[0] = 0;
  if (P == 1) return c;
  // Rank 0: c0 columns plus `extra` lines; the others (n0 - c0) / (P - 1) columns each.
  const long long c0 = (static_cast<long long>(n0) - static_cast<long long>(extra) * (P - 1)) / P;
  c[1] = static_cast<int>(std::clamp<long long>(c0, 1, n0 - (P - 1)));
  for (int r = 2; r < P; ++r)
    c[static_cast<std::size_t>(r)] = c[1] + static_cast<int>(static_cast<long long>(r - 1) * (n0 - c[1]) / (P - 1));
  return c;
}

void WorkPartition::build(const std::vector<Level>& levels, const std::vector<int>& rank0_extra, bool distributed_storage) {
  lv = &levels;
  parts.assign(lv->size(), Part{});
  for (std::size_t l = 0; l < lv->size(); ++l) {
    const Level& L = (*lv)[l];
    Part& p = parts[l];
    p.s = L.shape.dimension - 1;
    p.hi = L.shape.n[p.s];
    p.line_hi = L.shape.n[0];
  }
  std::size_t D = 0;
  while (D < lv->size() && splittable((*lv)[D].shape)) ++D;
  if (D == 0) return;
  const int sd = (*lv)[0].shape.dimension - 1;
  const auto P = static_cast<std::size_t>(nranks_);
  std::vector<int> b(P + 1);
  const bool windowed = distributed_storage && sd == 2;
  // Windowed: cuts on multiples of the coarsening ratio below the split (splittable: n >= 2P).
  const int unit = windowed && D < lv->size() ? (*lv)[D - 1].ratio[sd] : 1;
  for (std::size_t r = 0; r <= P; ++r)
    b[r] = unit * static_cast<int>(static_cast<long long>(r) * ((*lv)[D - 1].shape.n[sd] / unit) / nranks_);
  if (windowed && D < lv->size()) {  // the level below the split, restricted into by every rank
    Part& a = parts[D];
    const GridShape& sh = (*lv)[D].shape;
    const std::ptrdiff_t plane = (*lv)[D].st[sd], iplane = static_cast<std::ptrdiff_t>(sh.n[0]) * sh.n[1];
    a.agglomerated = true;
    a.agg_lo = b[static_cast<std::size_t>(rank_)] / unit, a.agg_hi = b[static_cast<std::size_t>(rank_) + 1] / unit;
    for (auto* v : {&a.agg_counts, &a.agg_displs, &a.agg_gcounts, &a.agg_gdispls}) v->assign(P, 0);
    for (std::size_t r = 0; r < P; ++r) {
      const int k0 = b[r] / unit, planes = b[r + 1] / unit - k0;
      a.agg_counts[r] = static_cast<int>(planes * iplane), a.agg_displs[r] = static_cast<int>(k0 * iplane);
      a.agg_gcounts[r] = static_cast<int>(planes * plane), a.agg_gdispls[r] = static_cast<int>((k0 + 1) * plane);
    }
  }
  for (std::size_t l = D; l-- > 0;) {
    if (l + 1 < D)
      for (int& x : b) x *= (*lv)[l].ratio[sd];
    const Level& L = (*lv)[l];
    const GridShape& sh = L.shape;
    Part& p = parts[l];
    p.dist = true;
    p.lo = b[static_cast<std::size_t>(rank_)], p.hi = b[static_cast<std::size_t>(rank_) + 1];
    p.flip = sh.dimension == 2 && sh.boundary[0][0] == Boundary::origin && sh.origin_flips_theta();
    p.plane = L.st[sd];
    p.windowed = windowed;
    p.gbase = windowed ? static_cast<std::ptrdiff_t>(p.lo) * p.plane : 0;  // Level::set_window's
    p.iplane = sd == 2 ? static_cast<std::ptrdiff_t>(sh.n[0]) * sh.n[1] : sh.n[0];
    for (auto* v :
         {&p.counts, &p.displs, &p.icounts, &p.idispls, &p.col_counts, &p.col_displs, &p.blk_counts, &p.blk_displs})
      v->assign(P, 0);
    for (std::size_t r = 0; r < P; ++r) {
      const int planes = b[r + 1] - b[r];
      p.counts[r] = static_cast<int>(planes * p.plane), p.displs[r] = static_cast<int>((b[r] + 1) * p.plane);
      p.icounts[r] = static_cast<int>(planes * p.iplane), p.idispls[r] = static_cast<int>(b[r] * p.iplane);
      p.col_counts[r] = planes, p.col_displs[r] = b[r];
    }
    if (sh.dimension == 2) {
      const int n0 = sh.n[0], n1 = sh.n[1];
      const std::vector<int> cuts = line_cuts(n0, l < rank0_extra.size() ? rank0_extra[l] : 0);
      auto cut = [&](std::size_t r) { return cuts[r]; };
      for (std::size_t r = 0; r < P; ++r) p.blk_counts[r] = (cut(r + 1) - cut(r)) * n1, p.blk_displs[r] = cut(r) * n1;
      p.line_lo = cut(static_cast<std::size_t>(rank_)), p.line_hi = cut(static_cast<std::size_t>(rank_) + 1);
      p.sbuf.assign(static_cast<std::size_t>(std::max((p.line_hi - p.line_lo) * n1, n1)), 0.0);
      p.rbuf.assign(static_cast<std::size_t>(n1), 0.0);
      p.gbuf.assign(sh.cells(), 0.0);
      set_transposes(p, sh, b, cuts);
    }
  }
}
void WorkPartition::set_transposes(Part& p, const GridShape& sh, const std::vector<int>& slab, const std::vector<int>& cols) {
  const auto P = static_cast<std::size_t>(nranks_), me = static_cast<std::size_t>(rank_);
  const int n0 = sh.n[0];
  p.cols = cols;
  auto ext = [&](std::size_t r) { return std::min(n0, p.cols[r + 1] + 1) - std::max(0, p.cols[r] - 1); };
  auto own = [&](std::size_t r) { return p.cols[r + 1] - p.cols[r]; };
  auto rows = [&](std::size_t r) { return slab[r + 1] - slab[r]; };
  for (auto* v : {&p.tc_s, &p.tc_sd, &p.tc_r, &p.tc_rd, &p.ts_s, &p.ts_sd, &p.ts_r, &p.ts_rd}) v->assign(P, 0);
  for (std::size_t r = 0; r < P; ++r) {
    p.tc_s[r] = ext(r) * rows(me), p.tc_r[r] = ext(me) * rows(r);
    p.ts_s[r] = own(me) * rows(r), p.ts_r[r] = own(r) * rows(me);
    if (r > 0) {
      p.tc_sd[r] = p.tc_sd[r - 1] + p.tc_s[r - 1], p.tc_rd[r] = p.tc_rd[r - 1] + p.tc_r[r - 1];
      p.ts_sd[r] = p.ts_sd[r - 1] + p.ts_s[r - 1], p.ts_rd[r] = p.ts_rd[r - 1] + p.ts_r[r - 1];
    }
  }
  const std::size_t most = static_cast<std::size_t>(
      std::max({p.tc_sd[P - 1] + p.tc_s[P - 1], p.tc_rd[P - 1] + p.tc_r[P - 1], p.ts_sd[P - 1] + p.ts_s[P - 1],
                p.ts_rd[P - 1] + p.ts_r[P - 1]}));
  p.tsend.assign(most, 0.0), p.trecv.assign(most, 0.0);
}

void WorkPartition::to_columns(std::size_t l, std::vector<double>& a) {
  Part& p = parts[l];
  const Level& L = (*lv)[l];
  const int n0 = L.shape.n[0];
  double* v = a.data();
  std::size_t m = 0;
  for (int r = 0; r < nranks_; ++r) {
    const auto u = static_cast<std::size_t>(r);
    const int i0 = std::max(0, p.cols[u] - 1), i1 = std::min(n0, p.cols[u + 1] + 1);
    for (int j = p.lo; j < p.hi; ++j)
      for (int i = i0; i < i1; ++i) p.tsend[m++] = v[L.at(i, j, 0)];
  }
  MPI_Alltoallv(p.tsend.data(), p.tc_s.data(), p.tc_sd.data(), MPI_DOUBLE, p.trecv.data(), p.tc_r.data(),
                p.tc_rd.data(), MPI_DOUBLE, comm);
  const auto me = static_cast<std::size_t>(rank_);
  const int i0 = std::max(0, p.cols[me] - 1), i1 = std::min(n0, p.cols[me + 1] + 1);
  m = 0;
  for (int r = 0; r < nranks_; ++r) {
    const auto u = static_cast<std::size_t>(r);
    for (int j = p.col_displs[u]; j < p.col_displs[u] + p.col_counts[u]; ++j)
      for (int i = i0; i < i1; ++i) {
        if (r != rank_) v[L.at(i, j, 0)] = p.trecv[m];
        ++m;
      }
  }
  received_ += static_cast<long long>(sizeof(double)) * (static_cast<long long>(m) - p.tc_r[me]);
  comm::count("mg_base_transpose", comm::Pattern::alltoall, static_cast<int>(l), 1,
              static_cast<long long>(sizeof(double)) * (static_cast<long long>(m) - p.tc_r[me]));
}

void WorkPartition::to_slabs(std::size_t l, std::vector<double>& a) {
  Part& p = parts[l];
  const Level& L = (*lv)[l];
  double* v = a.data();
  const auto me = static_cast<std::size_t>(rank_);
  std::size_t m = 0;
  for (int r = 0; r < nranks_; ++r) {
    const auto u = static_cast<std::size_t>(r);
    for (int j = p.col_displs[u]; j < p.col_displs[u] + p.col_counts[u]; ++j)
      for (int i = p.cols[me]; i < p.cols[me + 1]; ++i) p.tsend[m++] = v[L.at(i, j, 0)];
  }
  MPI_Alltoallv(p.tsend.data(), p.ts_s.data(), p.ts_sd.data(), MPI_DOUBLE, p.trecv.data(), p.ts_r.data(),
                p.ts_rd.data(), MPI_DOUBLE, comm);
  m = 0;
  for (int r = 0; r < nranks_; ++r) {
    const auto u = static_cast<std::size_t>(r);
    for (int j = p.lo; j < p.hi; ++j)
      for (int i = p.cols[u]; i < p.cols[u + 1]; ++i) {
        if (r != rank_) v[L.at(i, j, 0)] = p.trecv[m];
        ++m;
      }
  }
  received_ += static_cast<long long>(sizeof(double)) * (static_cast<long long>(m) - p.ts_r[me]);
  comm::count("mg_base_transpose", comm::Pattern::alltoall, static_cast<int>(l), 1,
              static_cast<long long>(sizeof(double)) * (static_cast<long long>(m) - p.ts_r[me]));
}

void WorkPartition::columns_to_root(std::size_t l, std::vector<double>& a, int ncols) {
  Part& p = parts[l];
  const Level& L = (*lv)[l];
  const auto P = static_cast<std::size_t>(nranks_);
  p.root_counts.assign(P, 0), p.root_displs.assign(P, 0);
  for (std::size_t r = 0; r < P; ++r) p.root_counts[r] = p.col_counts[r] * ncols, p.root_displs[r] = p.col_displs[r] * ncols;
  const std::size_t all = static_cast<std::size_t>(L.shape.n[1]) * static_cast<std::size_t>(ncols);
  if (p.trecv.size() < all) p.trecv.resize(all);
  if (p.tsend.size() < all) p.tsend.resize(all);
  double* v = a.data();
  std::size_t m = 0;
  for (int j = p.lo; j < p.hi; ++j)
    for (int i = 0; i < ncols; ++i) p.tsend[m++] = v[L.at(i, j, 0)];
  MPI_Gatherv(p.tsend.data(), static_cast<int>(m), MPI_DOUBLE, p.trecv.data(), p.root_counts.data(),
              p.root_displs.data(), MPI_DOUBLE, 0, comm);
  if (rank_ != 0) return;
  m = 0;
  for (int j = 0; j < L.shape.n[1]; ++j)
    for (int i = 0; i < ncols; ++i, ++m)
      if (j >= p.hi) v[L.at(i, j, 0)] = p.trecv[m];  // rank 0's own rows are j < hi
  received_ += static_cast<long long>(sizeof(double)) * static_cast<long long>(all - static_cast<std::size_t>(p.root_counts[0]));
  comm::count("mg_base_root_gather", comm::Pattern::gather, static_cast<int>(l), 1,
              static_cast<long long>(sizeof(double)) * static_cast<long long>(all - static_cast<std::size_t>(p.root_counts[0])));
}

void WorkPartition::columns_from_root(std::size_t l, std::vector<double>& a, int ncols) {
  Part& p = parts[l];
  const Level& L = (*lv)[l];
  double* v = a.data();
  if (rank_ == 0) {
    std::size_t m = 0;
    for (int j = 0; j < L.shape.n[1]; ++j)
      for (int i = 0; i < ncols; ++i) p.tsend[m++] = v[L.at(i, j, 0)];
  }
  const int mine = p.root_counts[static_cast<std::size_t>(rank_)];
  MPI_Scatterv(p.tsend.data(), p.root_counts.data(), p.root_displs.data(), MPI_DOUBLE, p.trecv.data(), mine, MPI_DOUBLE,
               0, comm);
  if (rank_ == 0) return;
  std::size_t m = 0;
  for (int j = p.lo; j < p.hi; ++j)
    for (int i = 0; i < ncols; ++i) v[L.at(i, j, 0)] = p.trecv[m++];
  received_ += static_cast<long long>(sizeof(double)) * mine;
  comm::count("mg_base_root_scatter", comm::Pattern::gather, static_cast<int>(l), 1, static_cast<long long>(sizeof(double)) * mine);
}

int WorkPartition::neighbour(int dr) const {
  const int r = rank_ + dr;
  return r >= 0 && r < nranks_ ? r : MPI_PROC_NULL;
}
double WorkPartition::global_max(double m) const {
  if (nranks_ > 1) {
    MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_MAX, comm);
    comm::count("mg_base_allreduce", comm::Pattern::allreduce, -1, 1, sizeof(double));
  }
  return m;
}
void WorkPartition::replicate(std::size_t l, std::vector<double>& a, bool ghosted) const {
  const Part& p = parts[l];
  if (!p.dist) return;
  const Level& L = (*lv)[l];
  if (a.size() != (ghosted ? L.ghosted_size : L.cells()))  // a window has nothing to complete
    throw std::logic_error("WorkPartition::replicate: not an array of the whole level");
  MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, a.data(), ghosted ? p.counts.data() : p.icounts.data(),
                 ghosted ? p.displs.data() : p.idispls.data(), MPI_DOUBLE, comm);
  const auto& c = ghosted ? p.counts : p.icounts;
  long long n = 0;
  for (int r = 0; r < nranks_; ++r) n += r == rank_ ? 0 : c[static_cast<std::size_t>(r)];
  received_ += static_cast<long long>(sizeof(double)) * n;
  comm::count("mg_base_allgather", comm::Pattern::allgather, static_cast<int>(l), 1, static_cast<long long>(sizeof(double)) * n);
}
void WorkPartition::halo(std::size_t l, std::vector<double>& a) {
  Part& p = parts[l];
  if (!p.dist) return;
  double* v = a.data();
  const int w = static_cast<int>(p.plane);
  auto plane = [&](int k) { return v + ((k + 1) * p.plane - p.gbase); };
  MPI_Sendrecv(plane(p.hi - 1), w, MPI_DOUBLE, neighbour(1), 11, plane(p.lo - 1), w, MPI_DOUBLE, neighbour(-1), 11,
               comm, MPI_STATUS_IGNORE);
  MPI_Sendrecv(plane(p.lo), w, MPI_DOUBLE, neighbour(-1), 12, plane(p.hi), w, MPI_DOUBLE, neighbour(1), 12, comm,
               MPI_STATUS_IGNORE);
  received_ += static_cast<long long>(sizeof(double)) * w * ((rank_ > 0) + (rank_ + 1 < nranks_));
  comm::count("mg_base_halo", comm::Pattern::p2p, static_cast<int>(l), (rank_ > 0) + (rank_ + 1 < nranks_),
              static_cast<long long>(sizeof(double)) * w * ((rank_ > 0) + (rank_ + 1 < nranks_)));
  if (!p.flip) return;
  const Level& L = (*lv)[l];
  for (int j = p.lo; j < p.hi; ++j) p.sbuf[static_cast<std::size_t>(j - p.lo)] = v[L.at(0, j, 0)];
  MPI_Allgatherv(p.sbuf.data(), p.hi - p.lo, MPI_DOUBLE, p.rbuf.data(), p.col_counts.data(), p.col_displs.data(),
                 MPI_DOUBLE, comm);
  for (int j = 0; j < L.shape.n[1]; ++j) v[L.at(0, j, 0)] = p.rbuf[static_cast<std::size_t>(j)];
  comm::count("mg_base_allgather", comm::Pattern::allgather, static_cast<int>(l), 1,
              static_cast<long long>(sizeof(double)) * (L.shape.n[1] - (p.hi - p.lo)));
}
void WorkPartition::exchange_columns(std::size_t l, std::vector<double>& a) {
  Part& p = parts[l];
  const Level& L = (*lv)[l];
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
  if (rank_ > 0) unpack(p.line_lo - 1);
  pack(p.line_lo);
  MPI_Sendrecv(p.sbuf.data(), n1, MPI_DOUBLE, neighbour(-1), 14, p.rbuf.data(), n1, MPI_DOUBLE, neighbour(1), 14, comm,
               MPI_STATUS_IGNORE);
  if (rank_ + 1 < nranks_) unpack(p.line_hi);
  received_ += static_cast<long long>(sizeof(double)) * n1 * ((rank_ > 0) + (rank_ + 1 < nranks_));
  comm::count("mg_base_halo", comm::Pattern::p2p, static_cast<int>(l), (rank_ > 0) + (rank_ + 1 < nranks_),
              static_cast<long long>(sizeof(double)) * n1 * ((rank_ > 0) + (rank_ + 1 < nranks_)));
}
void WorkPartition::gather_columns(std::size_t l, std::vector<double>& a) {
  Part& p = parts[l];
  const Level& L = (*lv)[l];
  const int n0 = L.shape.n[0], n1 = L.shape.n[1];
  double* v = a.data();
  std::size_t m = 0;
  for (int i = p.line_lo; i < p.line_hi; ++i)
    for (int j = 0; j < n1; ++j) p.sbuf[m++] = v[L.at(i, j, 0)];
  MPI_Allgatherv(p.sbuf.data(), static_cast<int>(m), MPI_DOUBLE, p.gbuf.data(), p.blk_counts.data(),
                 p.blk_displs.data(), MPI_DOUBLE, comm);
  received_ += static_cast<long long>(sizeof(double)) * (static_cast<long long>(n0) * n1 - static_cast<long long>(m));
  comm::count("mg_base_allgather", comm::Pattern::allgather, static_cast<int>(l), 1,
              static_cast<long long>(sizeof(double)) * (static_cast<long long>(n0) * n1 - static_cast<long long>(m)));
  m = 0;
  for (int i = 0; i < n0; ++i)
    for (int j = 0; j < n1; ++j) v[L.at(i, j, 0)] = p.gbuf[m++];
}

}  // namespace remnant::xcfc
