#pragma once
// Point values of 3D source data: the finest refinement level whose valid points surround the
// point, third-order (cubic) Lagrange interpolation on a 4^3 stencil, limited near
// discontinuities: a component whose cubic value leaves the range of the 8 nearest points takes
// the trilinear value instead (no new extrema at a star's surface or a shock). Exact at the
// points themselves; ghost and invalid points are never used (a level whose stencil touches one
// falls back to trilinear, then to the next coarser level).
#include <string>
#include <vector>

#include "HandOff/source_data.hpp"
#include "remnant/coordinates.hpp"

namespace remnant::handoff {

class Sampler {
 public:
  Sampler(const SourceData& src, const std::vector<std::string>& fields);
  // Writes one value per field into out; false where no level has data around X.
  bool sample(const Point3& X, double* out, int* level_used = nullptr) const;
  std::size_t size() const { return nfields_; }
  // The spacing of the finest level with data at the point nearest X (the coarsest spacing outside).
  double spacing_at(const Point3& X) const;

 private:
  bool sample_level(const SourceLevel& L, const std::vector<const double*>& f, const Point3& X, double* out) const;
  const SourceData& src_;
  std::size_t nfields_;
  std::vector<std::vector<const double*>> fields_;  // per level, per field
};

}  // namespace remnant::handoff
