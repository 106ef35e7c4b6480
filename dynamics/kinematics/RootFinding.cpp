#include "dynamics/kinematics/RootFinding.h"

#include <algorithm>
#include <cmath>

namespace rv {

std::vector<double> findRoots(const std::function<double(double)>& f, double a, double b, double step,
                              double accuracy) {
  std::vector<double> roots;
  // a step far below the range's width would scan for hours (a gyrostat of 4e5 makes chaplygin_ball's range
  // of G that wide; the step's minimum is 1e-12): coarsen it to at most kMaxScanIntervals intervals
  step = std::max(step, (b - a) / kMaxScanIntervals);
  double x0 = a, f0 = f(a);
  if (f0 == 0) roots.push_back(a);
  while (x0 < b) {
    const double x1 = std::min(b, x0 + step), f1 = f(x1);
    if (f1 == 0) {
      roots.push_back(x1);
    } else if (f0 != 0 && (f0 < 0) != (f1 < 0)) {
      double lo = x0, hi = x1, flo = f0;
      for (int it = 0; it < 200 && hi - lo > accuracy * std::max(1.0, std::abs(lo)); ++it) {
        const double mid = 0.5 * (lo + hi), fm = f(mid);
        if (mid <= lo || mid >= hi || fm == 0) {
          lo = hi = mid;
          break;
        }
        if ((fm < 0) == (flo < 0))
          lo = mid, flo = fm;
        else
          hi = mid;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    x0 = x1, f0 = f1;
  }
  return roots;
}

} // namespace rv
