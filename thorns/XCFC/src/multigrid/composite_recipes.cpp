#include "composite_recipes.hpp"

#include <algorithm>
#include <tuple>

namespace remnant::xcfc {

void add_recipe(Recipes& R, std::vector<Recipe>& list, std::size_t target, std::vector<Term>& terms) {
  std::sort(terms.begin(), terms.end(), [](const Term& a, const Term& b) {
    return std::tie(a.kind, a.tier, a.patch, a.p, a.mask) < std::tie(b.kind, b.tier, b.patch, b.p, b.mask);
  });
  const std::size_t begin = R.terms.size();
  for (const Term& x : terms) {
    StoredTerm* last = R.terms.size() > begin ? &R.terms.back() : nullptr;
    if (last && x.kind != Term::dirichlet && last->kind == x.kind && last->tier == x.tier && last->patch == x.patch &&
        last->p == x.p && last->mask == x.mask) {
      last->w += x.w;
    } else if (x.kind == Term::dirichlet) {
      R.terms.push_back({x.kind, x.mask, x.tier, x.patch, static_cast<std::ptrdiff_t>(R.points.size()), x.w});
      R.points.push_back(x.x);
    } else {
      R.terms.push_back({x.kind, x.mask, x.tier, x.patch, x.p, x.w});
    }
  }
  list.push_back({target, begin, R.terms.size()});
  terms.clear();
}

std::array<double, 64> parity_factors(const ScalarEquation& eq) {
  std::array<double, 64> f{};
  for (unsigned m = 0; m < 64; ++m) {
    double v = 1;
    for (int b = 0; b < 6; ++b)
      if (m & (1u << b)) v *= eq.parity[b / 2][b % 2];
    f[m] = v;
  }
  return f;
}

}  // namespace remnant::xcfc
