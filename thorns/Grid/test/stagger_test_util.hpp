#pragma once
// Helpers of the staggered-field tests (the library grid_test_support, linked by Grid's and
// HydroBase's tests): a face-normal vector B (three face groups with
// prolongation divergence_preserving), a random divergence-free B as the discrete curl of a random
// edge potential consistent across levels, and the discrete divergence of each cell.
#include <cstdint>

#include "Grid/amr_grid.hpp"
#include "remnant/grid.hpp"

namespace remnant::grid::test {

struct FaceField {
  VariableRegistry vars;
  int group[3] = {-1, -1, -1};  // face_x, face_y, face_z
};
FaceField make_face_field();

// The whole domain of each coordinate system on [-1, 1] or [0, 1] in length, the full angles (an
// axis/origin where the coordinates have one); shared with HydroBase's vector-potential tests.
struct DomainBounds {
  Point3 xmin, xmax;
};
DomainBounds full_domain(CoordinateSystem c);

// Grids on full_domain with an axis/origin where the coordinates have one, max_level 2, blocks of 8 cells.
GridConfig stagger_config(CoordinateSystem c, int dimension);

// Sets every interior face (block boundaries included) of every local block to the curl of a
// random edge potential: each finest-level edge (level `finest`) has a random line integral
// (zero where the edge has zero length, one value around an axis), a coarser edge the sum of its
// finest edges, the flux through a face the circulation around it, B = flux / area.
void fill_curl_of_random_potential(AmrGrid& grid, const FaceField& f, int finest, std::uint64_t seed);

// Net outflow sum(+-A B) of cell (i, j, k) of block b, and the sum of |A B| over its faces.
double cell_outflow(Block& b, const FaceField& f, int i, int j, int k, double* magnitude = nullptr);

// max over cells of |outflow| / sum|A B| (a relative round-off measure), and the brief's measure
// max |div B| dx / max |B| (div = outflow / volume, dx the level's spacing in direction 0).
struct DivergenceStats {
  double relative = 0, scaled = 0;
};
DivergenceStats divergence_stats(AmrGrid& grid, const FaceField& f);

// The largest difference between the two copies of a face shared by same-level local blocks (not
// across periodic faces), relative to max |B|.
double shared_face_mismatch(AmrGrid& grid, const FaceField& f);

// The face field and edge groups Ex, Ey, Ez (auxiliary) for constrained-transport tests.
struct EdgeSetup {
  FaceField f;
  int edge[3] = {-1, -1, -1};
  EdgeSetup();
};

// Sets the edges of the interior of every local block to a smooth EMF pattern that differs between
// levels and, by a factor 1 + 1e-3 gid, between blocks (as ghosts near refinement boundaries make
// them), zero on edges of zero length and single-valued along an axis; in 2D only along z.
void fill_emf(AmrGrid& grid, const EdgeSetup& s);
// Sets every interior edge (block faces included) of every group, in 2D too, to a nonzero value
// that depends on the edge's level and wrapped global position and, by 1 + 1e-3 gid, on the block.
void fill_distinct_edges(AmrGrid& grid, const EdgeSetup& s);
// The largest difference between two copies of one edge among the local blocks of one level,
// across periodic faces too (the copies correct_edges must make equal).
double edge_copy_mismatch(AmrGrid& grid, const EdgeSetup& s);
// Phi -= dt * (circulation of E around the face), line integrals = value * coordinate length.
void ct_update(AmrGrid& grid, const EdgeSetup& s, double dt);

}  // namespace remnant::grid::test
