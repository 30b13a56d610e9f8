#include "XCFC/multigrid/cell_share.hpp"

#include <algorithm>
#include <stdexcept>

#include "remnant/comm_counters.hpp"

namespace remnant::xcfc {

CellShare::CellShare(const std::vector<std::size_t>& part_sizes, MPI_Comm comm) : comm_(comm) {
  if (comm != MPI_COMM_SELF) {
    MPI_Comm_rank(comm, &rank_);
    MPI_Comm_size(comm, &nranks_);
  }
  offsets_.assign(1, 0);
  for (std::size_t s : part_sizes) offsets_.push_back(offsets_.back() + s);
  const std::size_t n = offsets_.back();
  split_ = nranks_ > 1 && n >= kMinCells;
  const auto P = static_cast<std::size_t>(split_ ? nranks_ : 1);
  cuts_.resize(P + 1);
  for (std::size_t r = 0; r <= P; ++r) cuts_[r] = n * r / P;
  begin_ = split_ ? cuts_[static_cast<std::size_t>(rank_)] : 0;
  end_ = split_ ? cuts_[static_cast<std::size_t>(rank_) + 1] : n;
}

std::pair<std::size_t, std::size_t> CellShare::range(int n) const {
  const auto u = static_cast<std::size_t>(n);
  const std::size_t lo = offsets_.at(u), hi = offsets_.at(u + 1);
  const std::size_t b = std::clamp(begin_, lo, hi), e = std::clamp(end_, lo, hi);
  return {b - lo, std::max(b, e) - lo};
}

namespace {
// Copies the flat cells [b, e) of a field from (to_field = false) or into (true) a buffer.
void copy_flat(std::vector<std::vector<double>>& f, const std::vector<std::size_t>& offsets, std::size_t b, std::size_t e,
               double* buf, bool to_field) {
  for (std::size_t n = 0; n + 1 < offsets.size() && b < e; ++n) {
    const std::size_t lo = std::max(b, offsets[n]), hi = std::min(e, offsets[n + 1]);
    if (lo >= hi) continue;
    double* p = f[n].data() + (lo - offsets[n]);
    if (to_field) std::copy(buf, buf + (hi - lo), p);
    else std::copy(p, p + (hi - lo), buf);
    buf += hi - lo;
  }
}
}  // namespace

void CellShare::complete(const std::vector<std::vector<std::vector<double>>*>& fields) const {
  if (!split_) return;
  for (auto* f : fields)
    if (f->size() + 1 != offsets_.size()) throw std::logic_error("CellShare::complete: a field with another part count");
  std::vector<int> counts(static_cast<std::size_t>(nranks_)), displs(static_cast<std::size_t>(nranks_));
  for (std::size_t r = 0; r < counts.size(); ++r) {
    counts[r] = static_cast<int>(cuts_[r + 1] - cuts_[r]);
    displs[r] = static_cast<int>(cuts_[r]);
  }
  // One collective per field. A single part is gathered in place (no buffer, no copies); several
  // parts go through one field-sized buffer (no buffer of all the fields: memory per cell counts).
  for (auto* f : fields) {
    comm::count("xcfc_cellshare_allgather", comm::Pattern::allgather, -1, 1,
                static_cast<long long>(sizeof(double) * (offsets_.back() - (end_ - begin_))));
    if (f->size() == 1) {
      MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DOUBLE, (*f)[0].data(), counts.data(), displs.data(), MPI_DOUBLE, comm_);
      continue;
    }
    send_.resize(end_ - begin_);
    recv_.resize(offsets_.back());
    copy_flat(*f, offsets_, begin_, end_, send_.data(), false);
    MPI_Allgatherv(send_.data(), static_cast<int>(send_.size()), MPI_DOUBLE, recv_.data(), counts.data(), displs.data(),
                   MPI_DOUBLE, comm_);
    for (int r = 0; r < nranks_; ++r) {
      if (r == rank_) continue;  // this rank's chunk is already in place
      const std::size_t b = cuts_[static_cast<std::size_t>(r)], e = cuts_[static_cast<std::size_t>(r) + 1];
      copy_flat(*f, offsets_, b, e, recv_.data() + b, true);
    }
  }
}

}  // namespace remnant::xcfc
