#pragma once
// The mesh as thorns see it: blocks of contiguous arrays (i fastest) with ghost zones, owned by
// MPI ranks. The Grid thorn implements GridDriver; the flesh calls synchronize() before a function
// that reads a variable (everywhere) whose ghosts are stale.
#include <mpi.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

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
  // Points per direction including ghosts, for a centering.
  std::array<int, 3> extent(Centering c) const;
  Field field(int group, int comp);
  double* data(int group) { return data_[static_cast<std::size_t>(group)].data(); }
  std::size_t size(int group) const { return data_[static_cast<std::size_t>(group)].size(); }
  std::size_t points_per_component(int group) const { return points_[static_cast<std::size_t>(group)]; }
  double cell_volume() const;  // Cartesian for now; the Grid issue adds sqrt(f)

 private:
  const VariableRegistry* vars_;
  std::vector<std::vector<double>> data_;   // per group: ncomp * points, component-major
  std::vector<std::size_t> points_;
};

enum class ReductionKind { minimum, maximum, sum, volume_integral, norm1, norm2 };

// The reference metric f_ij of the coordinates (DESIGN.md section 4): Cartesian (x, y, z),
// cylindrical (R, z, phi), spherical (r, theta, phi).
enum class CoordinateSystem { cartesian, cylindrical, spherical };
const char* to_string(CoordinateSystem c);

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
  // Every block of every rank in global (gid) order: what a checkpoint must store of the mesh.
  virtual std::vector<BlockKey> all_blocks() const = 0;
  // Recovery: rebuild the mesh with exactly these blocks (in this gid order), distributed over the
  // current ranks; data are zeroed. Throws RunError when the grid cannot represent them.
  virtual void restore_blocks(std::span<const BlockKey> blocks) = 0;
};

// Calls f(i, j, k) for every interior cell of a block, i fastest.
template <class F>
inline void for_interior(const Block& b, F&& f) {
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i) f(i, j, k);
}

}  // namespace remnant
