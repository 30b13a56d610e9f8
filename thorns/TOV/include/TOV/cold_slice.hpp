#pragma once
// A cold, barotropic EOS slice parametrised by the log-enthalpy H = ln h (h = 1 + eps + p/rho),
// the natural variable of the TOV equations (Lindblom 1992): dH = dp / (e + p), H = 0 at the surface.
#include <functional>
#include <memory>
#include <vector>

namespace remnant::tov {

struct ColdState {
  double rho = 0, eps = 0, press = 0, ye = 0;
};

class ColdSlice {
 public:
  virtual ~ColdSlice() = default;
  virtual ColdState at(double H) const = 0;   // H >= 0
  virtual double log_enthalpy(double rho) const = 0;
};

// p = K rho^Gamma, eps = K rho^(Gamma-1) / (Gamma-1); h = 1 + Gamma/(Gamma-1) K rho^(Gamma-1).
std::unique_ptr<ColdSlice> polytrope_slice(double K, double Gamma, double ye);

// Tabulated points (increasing rho) of a cold slice (e.g. beta equilibrium at T_min), integrated to
// H(rho) = int dp / (e + p) from the lowest density (H = 0 there) and interpolated monotonically.
std::unique_ptr<ColdSlice> tabulated_slice(std::vector<double> rho, std::vector<double> press,
                                           std::vector<double> eps, std::vector<double> ye);

// The same from points in segments inside which the EOS is smooth (segment_starts: index of each
// segment's first point, ascending, starting with 0; a segment's first point is the previous one's
// last): H by a third-order quadrature inside each segment, and interpolants that never straddle a
// segment boundary (the kinks of an interpolated table at its density nodes).
std::unique_ptr<ColdSlice> tabulated_slice_segments(const std::vector<double>& rho, const std::vector<double>& press,
                                                    const std::vector<double>& eps, const std::vector<double>& ye,
                                                    std::vector<std::size_t> segment_starts);

}  // namespace remnant::tov
