// Writes one HDF5 grid file (+ XDMF) of a fake 2D grid in the coordinates named on the command
// line, with f = R^2 + 3 z (cylindrical: (R, z); spherical: (r, theta); Cartesian: (x, y)) in
// every cell, for test_cylindrical_output.py to read back with h5py.
//   io_fake_output <out_dir> cartesian|cylindrical|spherical
#include <mpi.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "fake_grid.hpp"
#include "grid_file.hpp"
#include "patches.hpp"
#include "xdmf.hpp"

using namespace remnant;

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (argc != 3) {
    if (rank == 0) std::cerr << "usage: io_fake_output <out_dir> cartesian|cylindrical|spherical\n";
    MPI_Finalize();
    return 2;
  }
  const std::string dir = argv[1], cname = argv[2];
  const CoordinateSystem c = cname == "cylindrical" ? CoordinateSystem::cylindrical
                             : cname == "spherical" ? CoordinateSystem::spherical
                                                    : CoordinateSystem::cartesian;
  std::filesystem::create_directories(dir);
  auto vars = io::test::one_scalar_registry();
  // Cylindrical/Cartesian: R in [0, 2], z in [-1, 1]; spherical: r in [0, 2], theta in [0, pi].
  const double hi1 = c == CoordinateSystem::spherical ? 3.14159265358979323846 : 1.0;
  const double lo1 = c == CoordinateSystem::spherical ? 0.0 : -1.0;
  io::test::FakeGrid grid(vars, c, 2, {4, 3, 1}, {8, 6, 1}, {0, lo1, 0}, {2, hi1, 1}, MPI_COMM_WORLD);
  for (Block* b : grid.local_blocks()) {
    const Field f = b->field(0, 0);
    for_interior(*b, [&](int i, int j, int k) { f(i, j, k) = b->x(0, i) * b->x(0, i) + 3 * b->x(1, j); });
  }
  io::GridFileSpec spec;
  spec.path = dir + "/grid-volume.it00000000.h5";
  spec.coordinates = c;
  spec.grid_dimension = 2;
  spec.cut = io::make_cut("volume", 2, {0, 0, 0});
  spec.provenance = {"# fake parfile\n", "Test", "none", "test"};
  spec.variables = {io::VariableRef{0, 0, "Test::f.f", "Test-f.f"}};
  const auto patches = io::extract_patches(grid.local_blocks(), 2, spec.cut, spec.variables);
  const auto summary = io::write_grid_file(spec, patches, MPI_COMM_WORLD);
  if (rank == 0) {
    io::write_xdmf_document(dir + "/grid-volume.it00000000.xmf",
                            io::xdmf_grid_element(spec, summary, "grid-volume.it00000000.h5"), false);
    io::write_xdmf_series(dir, "grid-volume", 0);
  }
  MPI_Finalize();
  return 0;
}
