#pragma once
// The mesh as thorns see it: blocks of contiguous arrays (i fastest) with ghost zones, owned by
// MPI ranks. The Grid thorn implements GridDriver; the flesh calls synchronize() before a function
// that reads a variable (everywhere) whose ghosts are stale.
#include <mpi.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "remnant/coordinates.hpp"
#include "remnant/domain.hpp"
#include "remnant/variables.hpp"

namespace remnant {

class Parameters;

// A view of one component of one group on one block. (0,0,0) is the first interior point;
// ghost points have negative indices or indices >= n.
struct Field {
  double* origin = nullptr;
  std::ptrdiff_t sj = 0, sk = 0;
  double& operator()(int i, int j, int k) const { return origin[i + j * sj + k * sk]; }
};

class Block {
 public:
  Block(std::int64_t gid, int level, std::array<std::int64_t, 3> index, std::array<int, 3> n,
        std::array<int, 3> ng, std::array<double, 3> lo, std::array<double, 3> dx,
        const VariableRegistry& vars);

  std::int64_t gid;                    // global id: position along the space-filling curve
  int level;                           // refinement level (0 = base)
  std::array<std::int64_t, 3> index;   // logical block position on its level
  std::array<int, 3> n;                // interior cells per direction (1 in unused directions)
  std::array<int, 3> ng;               // ghost cells per direction (0 in unused directions)
  std::array<double, 3> lo;            // coordinate of the lower interior face
  std::array<double, 3> dx;            // cell widths

  // Cell-centre coordinate of index i in direction d (works for ghosts too).
  double x(int d, int i) const { return lo[d] + (i + 0.5) * dx[d]; }
  // Points per direction including the Grid's ghosts, for a centering.
  std::array<int, 3> extent(Centering c) const;
  // Ghost layers per direction that `group` holds: ng, or fewer where its thorn.yaml says `ghosts: N`.
  const std::array<int, 3>& ghosts(int group) const { return ghosts_[static_cast<std::size_t>(group)]; }
  // Points per direction of `group`'s arrays, its own ghosts included.
  std::array<int, 3> group_extent(int group) const;
  Field field(int group, int comp);
  double* data(int group) { return data_[static_cast<std::size_t>(group)].data(); }
  std::size_t size(int group) const { return data_[static_cast<std::size_t>(group)].size(); }
  std::size_t points_per_component(int group) const { return points_[static_cast<std::size_t>(group)]; }
  // Coordinate volume dx*dy*dz of the used directions: the cell volume of a Cartesian block.
  double cell_volume() const;

  // Geometry (exact integrals of sqrt(f), see remnant/coordinates.hpp). Cells (i, j, k) from -ng
  // to n+ng-1, faces from -ng to n+ng; the arrays are precomputed per direction, so these are
  // a few loads and multiplications.
  CoordinateSystem coordinates = CoordinateSystem::cartesian;
  // Lower face coordinate of cell i in direction d.
  double face_coordinate(int d, int i) const { return geo_[d].face[static_cast<std::size_t>(i + ng[d])]; }
  // The sqrt(f)-weighted centroid coordinate of cell i in direction d.
  double centroid(int d, int i) const { return geo_[d].centroid[static_cast<std::size_t>(i + ng[d])]; }
  // The integral of g_d over cell i in direction d (the 1D factor of the cell volume).
  double volume_weight(int d, int i) const { return geo_[d].weight[static_cast<std::size_t>(i + ng[d])]; }
  // g_d at the lower face i (the 1D factor of the face area normal to d).
  double face_factor(int d, int i) const { return geo_[d].face_factor[static_cast<std::size_t>(i + ng[d])]; }
  // Pointers to the per-direction arrays at index 0, valid from -ng on, for hot loops.
  const double* volume_weights(int d) const { return geo_[d].weight.data() + ng[d]; }
  const double* face_factors(int d) const { return geo_[d].face_factor.data() + ng[d]; }
  const double* centroids(int d) const { return geo_[d].centroid.data() + ng[d]; }
  // Exact volume of cell (i, j, k): the integral of sqrt(f) over it.
  double cell_volume(int i, int j, int k) const {
    return geo_[0].weight[static_cast<std::size_t>(i + ng[0])] * geo_[1].weight[static_cast<std::size_t>(j + ng[1])] *
           geo_[2].weight[static_cast<std::size_t>(k + ng[2])];
  }
  // Exact area (integral of sqrt(f) over the face) of the lower face of cell (i, j, k) normal to d.
  double face_area(int d, int i, int j, int k) const;
  // sqrt(f) at the centroid of cell (i, j, k).
  double sqrt_f(int i, int j, int k) const;
  // Recomputes the geometry: faces at domain_lo[d] + (index[d] * n[d] + i) * dx[d], so that
  // neighbouring blocks (at any level) compute bit-identical shared faces. Unused angular
  // directions span their whole range, unused other directions have unit weight.
  void set_geometry(CoordinateSystem c, const std::array<double, 3>& domain_lo);

 private:
  struct DirectionGeometry {
    std::vector<double> face, centroid, weight, face_factor;
  };
  std::array<DirectionGeometry, 3> geo_;
  const VariableRegistry* vars_;
  std::vector<std::vector<double>> data_;   // per group: ncomp * points, component-major
  std::vector<std::size_t> points_;
  std::vector<std::array<int, 3>> ghosts_;  // per group
};

enum class ReductionKind { minimum, maximum, sum, volume_integral, norm1, norm2 };

// Identifies a block independently of the rank that owns it (checkpoints, regrid).
struct BlockKey {
  int level = 0;
  std::array<std::int64_t, 3> index{0, 0, 0};
  bool operator==(const BlockKey&) const = default;
};
const char* to_string(ReductionKind k);

struct GridSetup {
  const Parameters& params;
  const VariableRegistry& vars;
  MPI_Comm comm;
};

class GridDriver {
 public:
  virtual ~GridDriver() = default;
  virtual int dimension() const = 0;
  virtual std::span<Block* const> local_blocks() = 0;
  // Ghost exchange between blocks and ranks, then outer boundary conditions, for these groups.
  virtual void synchronize(std::span<const int> groups) = 0;
  // Global reduction over interior cells; the same bits on every rank and for any rank count.
  virtual double reduce(int group, int comp, ReductionKind kind) = 0;
  virtual std::int64_t global_cells() const = 0;
  virtual double min_spacing() const = 0;
  // Human-readable layout (levels, blocks, cells, ranks) for --print-grid.
  virtual std::string describe() const = 0;
  virtual MPI_Comm comm() const = 0;
  virtual CoordinateSystem coordinates() const = 0;
  // The domain (faces, level-0 cells, blocks, extent) for thorns that need its symmetries, e.g. an
  // elliptic solver (remnant/domain.hpp).
  virtual Domain domain() const { throw std::runtime_error("this grid does not describe its domain"); }
  // Every block of every rank in global (gid) order: what a checkpoint must store of the mesh.
  virtual std::vector<BlockKey> all_blocks() const = 0;
  // Recovery: rebuild the mesh with exactly these blocks (in this gid order), distributed over the
  // current ranks; data are zeroed. Throws RunError when the grid cannot represent them.
  virtual void restore_blocks(std::span<const BlockKey> blocks) = 0;

  // Refluxing. `face_groups` hold flux densities (per unit face area, i.e. per unit of the
  // integral of sqrt(f) over the face) on the faces of the interior, one face-centred group per
  // direction (face_x, face_y, face_z). Where a face is shared with finer blocks, its value is
  // replaced by the area-weighted mean of the fine faces, so that the fluxes through the two sides
  // of a coarse-fine interface agree and conservation holds to round-off. Collective.
  virtual void correct_fluxes(std::span<const int> face_groups) { (void)face_groups; }

  // Constrained transport, the analogue of correct_fluxes. `edge_groups` (edge_x, edge_y, edge_z)
  // hold EMFs as covariant components (an edge's line integral is value times coordinate length)
  // on the edges of the interior. Every coarse copy of an edge that is also an edge of finer blocks
  // takes the mean of the two fine edges along it, so that a CT update keeps the coarse flux
  // through a coarse/fine interface equal to the sum of the fine ones (div B at round-off), and
  // coarse blocks sharing such an edge update their shared faces alike. Collective.
  virtual void correct_edges(std::span<const int> edge_groups) { (void)edge_groups; }

  // Adaptive refinement: a criterion returns, for one local block whose ghosts of the variables it
  // reads the thorn has synchronised, +1 (refine), 0 (keep) or -1 (may coarsen; a family of
  // 2^d blocks coarsens only when all agree). Evaluated at every regrid; several criteria combine
  // by the maximum. Throws RunError on a grid without refinement.
  using RefinementCriterion = std::function<int(Block&)>;
  virtual void add_refinement_criterion(const std::string& name, RefinementCriterion fn) {
    (void)fn;
    throw std::runtime_error("this grid has no refinement; cannot add criterion '" + name + "'");
  }

  // A thorn's own condition at `outflow` faces for one group: called by synchronize() for every
  // block face on such a face of the domain (direction d, upper or lower side), right after the
  // zero-gradient copy of the group's ghost layers there, in the same direction-by-direction
  // order. E.g. HydroBase's no-inflow condition on its primitive velocity.
  using OutflowCondition = std::function<void(Block&, int d, bool upper)>;
  virtual void add_outflow_condition(int group, OutflowCondition fn) {
    (void)group, (void)fn;
    throw std::runtime_error("this grid has no outflow faces to add a condition to");
  }
};

// Calls f(i, j, k) for every interior cell of a block, i fastest.
template <class F>
inline void for_interior(const Block& b, F&& f) {
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i) f(i, j, k);
}

}  // namespace remnant
