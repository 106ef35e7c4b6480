// Diagram.h -- bifurcation diagrams on the plane of first integrals (manual §2.3.10): a diagram is a set of
// parametric branches (curves, segments, rays, points) in a plane whose axes are functions of the integrals,
// and a rule that places any state on the same plane. Models that know their diagrams list them; the
// tools draw any of them alike.
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

namespace rv {

/// A point of a diagram's plane.
using DiagramPoint = std::array<double, 2>;

/// One branch, given parametrically: `points(s)` for s in [min, max] sampled with `step`. A branch may have
/// no point at some s (outside where it exists: the curve is drawn in pieces) or several (symmetric parts).
struct DiagramBranch {
  std::string id;                       ///< e.g. "sigma", "sigma0", "sigma1", "tau", "T0"
  std::string description;              ///< what it is and what its parameter means
  std::string parameter;                ///< the parameter's name, e.g. "lambda"
  double min = 0, max = 1, step = 0.01; ///< default range and step
  std::function<std::vector<DiagramPoint>(double s)> points;
};

/// A diagram: its axes, its branches, and where a state lies on it.
struct Diagram {
  std::string id;                  ///< e.g. "nh" (the (n, h) plane)
  std::string title;               ///< one line
  std::array<std::string, 2> axes; ///< names of the horizontal and vertical coordinates
  std::vector<DiagramBranch> branches;
  std::function<DiagramPoint(const double* x)> place; ///< a state's point (its integrals)
};

/// The diagram `id` of a problem's list (empty id: the first). Throws InputError naming `flag` with the
/// known ids when there is none such (or no diagram at all, naming `problem`).
const Diagram& findDiagram(const std::vector<Diagram>& diagrams, const std::string& id,
                           const std::string& flag, const std::string& problem);

} // namespace rv
