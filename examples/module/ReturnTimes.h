// ReturnTimes.h -- the tool `return_times`: statistics of the times between successive crossings of the
// scene's Poincare section (its mean, spread, least and largest, and a histogram), e.g. the return time of a
// linear centre is its period 2 pi / omega. Settings (scene section "return_times"): points, bins.
// Reference: H. Poincare, Les methodes nouvelles de la mecanique celeste I (1892); the first-return map of
// the section as in the manual §2.3.1.
#pragma once
#include "scenes/Module.h"

namespace rossler {

/// The entry: outputs mean, std, min, max, count (sweep quantities: mean and std), CLI `return-times`.
rv::ToolEntry returnTimesEntry();
/// Its settings: points (the number of return times), bins (of the histogram).
const rv::ParameterTable& returnTimesTable();
/// Its computation on a scene.
rv::ToolRunner returnTimesRunner();

} // namespace rossler
