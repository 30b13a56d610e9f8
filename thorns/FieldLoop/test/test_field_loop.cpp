// The field loop carried through a static refined box by MoL (face groups evolved, upwind EMFs,
// correct_edges): max |div B| dx / max |B| stays at round-off, and the magnetic energy converges
// to the exact 4 pi A0^2 / 7 at second order.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <span>

#include "remnant/driver.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

struct LoopRun {
  double energy_error = 0;  // |E_B(T) - exact| / exact
  double divergence = 0;    // max |div B| dx / max |B|
  double interface = 0;     // max over coarse/fine faces of |coarse flux - sum of fine fluxes| / max |flux|
  int finest = 0;
  std::size_t blocks = 0;
};

// Every coarse face on a coarse/fine interface against its two fine faces (single rank, 2D,
// periodic): the composite divergence is at round-off only if they agree.
double interface_mismatch(GridDriver& grid, int bx, int by) {
  std::map<std::array<std::int64_t, 3>, Block*> at;  // (level, ix, iy)
  std::array<std::int64_t, 2> blocks0{0, 0};
  for (Block* b : grid.local_blocks()) {
    at[{b->level, b->index[0], b->index[1]}] = b;
    if (b->level == 0) for (int d = 0; d < 2; ++d) blocks0[d] = std::max(blocks0[d], b->index[d] + 1);
  }
  double worst = 0, scale = 0;
  for (Block* b : grid.local_blocks())
    for (int d = 0; d < 2; ++d)
      for (int j = 0; j < b->n[1] + d; ++j)
        for (int i = 0; i < b->n[0] + 1 - d; ++i)
          scale = std::max(scale, std::abs(b->face_area(d, i, j, 0) * b->field(d == 0 ? bx : by, 0)(i, j, 0)));
  for (Block* c : grid.local_blocks()) {
    if (c->level != 0) continue;
    const int n = c->n[0];
    for (int d = 0; d < 2; ++d)
      for (const int side : {-1, 1}) {
        std::array<std::int64_t, 3> K{0, c->index[0], c->index[1]};
        K[1 + d] = (K[1 + d] + side + blocks0[d]) % blocks0[d];
        if (at.count(K)) continue;
        const Field B = c->field(d == 0 ? bx : by, 0);
        for (int t = 0; t < n; ++t) {
          int p[2];
          p[d] = side > 0 ? n : 0;
          p[1 - d] = t;
          const double coarse = c->face_area(d, p[0], p[1], 0) * B(p[0], p[1], 0);
          const std::int64_t G = c->index[1 - d] * n + t;
          double fine = 0;
          for (int h = 0; h < 2; ++h) {
            std::array<std::int64_t, 3> F{1, 0, 0};
            F[1 + d] = 2 * K[1 + d] + (side > 0 ? 0 : 1);
            F[2 - d] = (2 * G + h) / n;
            Block* fb = at.at(F);
            int q[2];
            q[d] = side > 0 ? 0 : n;
            q[1 - d] = static_cast<int>((2 * G + h) % n);
            fine += fb->face_area(d, q[0], q[1], 0) * fb->field(d == 0 ? bx : by, 0)(q[0], q[1], 0);
          }
          worst = std::max(worst, std::abs(coarse - fine));
        }
      }
  }
  return scale > 0 ? worst / scale : 0;
}

LoopRun run(int scale, const std::vector<std::string>& extra = {}) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/field_loop_ct_example.yaml";
  o.quiet = true;
  const auto out = std::filesystem::temp_directory_path() /
                   ("remnant_field_loop_" + std::to_string(::getpid()) + "_" + std::to_string(scale));
  const std::string n = std::to_string(32 * scale), b = std::to_string(8 * scale);
  o.overrides = {"Flesh::out_dir=" + out.string(), "FieldLoop::analysis_every=1", "IO::tsv_every=0",
                 "Grid::ncells=[" + n + "," + n + ",1]", "Grid::block_size=[" + b + "," + b + ",1]"};
  o.overrides.insert(o.overrides.end(), extra.begin(), extra.end());
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  GridDriver& grid = *sim.grid();
  const double exact = 4 * 3.14159265358979323846 * 1e-6 / 7;
  LoopRun r;
  r.energy_error = std::abs(grid.reduce(sim.vars().find("FieldLoop::b2"), 0, ReductionKind::volume_integral) - exact) / exact;
  const int div = sim.vars().find("FieldLoop::divB");
  const double div_max = std::max(grid.reduce(div, 0, ReductionKind::maximum), -grid.reduce(div, 0, ReductionKind::minimum));
  double bmax = 0, dx = 1;
  for (Block* blk : grid.local_blocks()) {
    r.finest = std::max(r.finest, blk->level);
    dx = std::min(dx, blk->dx[0]);
    for (const char* g : {"FieldLoop::Bx", "FieldLoop::By"}) {
      const int id = sim.vars().find(g);
      for (std::size_t p = 0; p < blk->size(id); ++p) bmax = std::max(bmax, std::abs(blk->data(id)[p]));
    }
  }
  r.divergence = div_max * dx / bmax;
  r.blocks = grid.all_blocks().size();
  r.interface = interface_mismatch(grid, sim.vars().find("FieldLoop::Bx"), sim.vars().find("FieldLoop::By"));
  std::filesystem::remove_all(out);
  return r;
}

}  // namespace

TEST(FieldLoop, DivergenceAtRoundOffAndEnergyConvergesAtSecondOrder) {
  double e[3];
  for (int s = 0; s < 3; ++s) {
    const LoopRun r = run(1 << s);
    e[s] = r.energy_error;
    std::printf("field loop: n0 x %d: energy error %.4e, max |div B| dx / max |B| %.2e, coarse/fine flux mismatch %.2e, "
                "finest level %d\n", 1 << s, r.energy_error, r.divergence, r.interface, r.finest);
    EXPECT_LE(r.divergence, 1e-13);
    EXPECT_LE(r.interface, 1e-12);
    EXPECT_EQ(r.finest, 1);
  }
  const double p1 = std::log2(e[0] / e[1]), p2 = std::log2(e[1] / e[2]);
  std::printf("field loop: energy convergence orders %.3f %.3f\n", p1, p2);
  EXPECT_GT(p2, 1.8);
  EXPECT_GT(p1, 1.5);
}

// A refined region that follows the loop (regrid every 4 iterations): new fine blocks are
// prolonged divergence-free (taking the faces of kept fine neighbours), coarsened ones restricted
// by area; div B and the coarse/fine flux agreement stay at round-off.
TEST(FieldLoop, MovingRefinementKeepsTheDivergenceAtRoundOff) {
  const LoopRun fixed = run(1);
  const LoopRun moving = run(1, {"FieldLoop::refine_radius=0.45", "Grid::regrid_every=4"});
  std::printf("field loop, moving refinement: energy error %.4e, max |div B| dx / max |B| %.2e, coarse/fine flux "
              "mismatch %.2e, %zu blocks (static layout: %zu)\n", moving.energy_error, moving.divergence, moving.interface,
              moving.blocks, fixed.blocks);
  EXPECT_NE(moving.blocks, fixed.blocks) << "the refined region must have moved";
  EXPECT_LE(moving.divergence, 1e-13);
  EXPECT_LE(moving.interface, 1e-12);
  EXPECT_LT(moving.energy_error, 1.1 * fixed.energy_error);
}
