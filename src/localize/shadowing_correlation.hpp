#pragma once
// How correlated the fit's residuals are along the robot's path: the heard scans' residuals,
// ordered by the distance travelled, are modelled as correlated shadowing with correlation
//     rho(h) = beta exp(-h / L)
// plus white fading (beta: the shadowing's share of the variance), fitted by maximum
// likelihood (a Kalman filter over the AR(1) state gives it exactly, in O(N)),
// and the effective-sample share it implies for the whole series,
//     k = N / (N + 2 beta sum_{i<j} exp(-(s_j - s_i) / L)),
// which tempers the composite likelihood so that its curvature is honest. Private to
// src/localize.
#include <vector>

namespace rigdesign::localize::detail {

struct ResidualCorrelation {
  double correlated_share = 0.0;  // beta, the best fit
  double length = 0.0;            // L [m], the best fit
  // k: the smallest over the (beta, L) the residuals do not reject at 95 % (a short series
  // pins long lengths down poorly, and the fit absorbs part of the shadowing).
  double effective_share = 1.0;
};

// `travelled` is the distance along the path of every scan (heard or not) in time order;
// `residuals` holds the heard scans' residuals at `heard_index` positions of that series.
ResidualCorrelation residual_correlation(const std::vector<double>& travelled,
                                         const std::vector<double>& residuals,
                                         const std::vector<std::size_t>& heard_index);

}  // namespace rigdesign::localize::detail
