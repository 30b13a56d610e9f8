#pragma once
// Ghost "recipes" of the composite multigrid: the value of a ghost cell (or of a cell of a coarse
// window) as an affine combination of stored interior values, the far value and Dirichlet values,
// built once per boundary signature by CompositeMultigrid (symmetry mirrors, outer boundaries and
// coarse-fine interpolation resolved symbolically) and evaluated before every stencil pass.
#include <array>
#include <cstddef>
#include <vector>

#include "XCFC/multigrid/multigrid.hpp"

namespace remnant::xcfc {

// One contribution: a stored interior value (tier, patch, ghosted offset), the far value or a
// Dirichlet value at a face point, times w and the parities of the symmetry faces crossed on the way
// (bit 2d + side of mask).
struct Term {
  enum Kind : unsigned char { stored, far, dirichlet };
  Kind kind = stored;
  unsigned char mask = 0;
  int tier = 0, patch = 0;
  std::ptrdiff_t p = 0;
  double w = 0;
  Point3 x{};
};

// A term as stored in Recipes: 32 bytes instead of Term's 56 (a recipe list holds ~1.6 terms per
// cell of the composite grid; issue 21, goal 7). Dirichlet terms keep their face point in
// Recipes::points, p being its index there.
struct StoredTerm {
  Term::Kind kind = Term::stored;
  unsigned char mask = 0;
  int tier = 0, patch = 0;
  std::ptrdiff_t p = 0;
  double w = 0;
};
static_assert(sizeof(StoredTerm) == 32);

struct Recipe {
  std::size_t target;      // ghosted offset (ghosts) or window index (windows)
  std::size_t begin, end;  // terms
};

// Recipes of one boundary signature (Robin fall-off power or Dirichlet): per [tier][patch] the face
// ghosts of the patch and the cells of its coarse window (footprint plus one coarse cell around).
struct Recipes {
  std::vector<StoredTerm> terms;
  std::vector<Point3> points;  // the face points of the Dirichlet terms
  std::vector<std::vector<std::vector<Recipe>>> ghosts, window;
};

// Quadratic Lagrange weights at offset xi (coarse cells) from the centre node of nodes -1, 0, 1.
inline std::array<double, 3> quadratic(double xi) { return {0.5 * xi * (xi - 1), 1 - xi * xi, 0.5 * xi * (xi + 1)}; }

// Appends one recipe made of `terms` (sorted, equal references merged; `terms` is cleared).
void add_recipe(Recipes& R, std::vector<Recipe>& list, std::size_t target, std::vector<Term>& terms);

// The parity factor of each crossing mask for an equation.
std::array<double, 64> parity_factors(const ScalarEquation& eq);

// Value of a recipe over the arrays field(tier, patch) (ghosted); homogeneous: a correction (far and
// Dirichlet values zero).
template <class Field>
double evaluate(const Recipes& R, const Recipe& r, const std::array<double, 64>& par, const ScalarEquation& eq,
                bool homogeneous, Field&& field) {
  double v = 0;
  for (std::size_t m = r.begin; m < r.end; ++m) {
    const StoredTerm& x = R.terms[m];
    const double w = par[x.mask] * x.w;
    if (x.kind == Term::stored) v += w * field(x.tier, x.patch)[static_cast<std::size_t>(x.p)];
    else if (!homogeneous)
      v += w * (x.kind == Term::far ? eq.far_value : eq.dirichlet(R.points[static_cast<std::size_t>(x.p)]));
  }
  return v;
}

}  // namespace remnant::xcfc
