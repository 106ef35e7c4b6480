#include "dynamics/tools/FourierSpectrum.h"

#include "dynamics/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <fftw3.h>
#include <mutex>
#include <numbers>

namespace rv {

namespace {
std::mutex& plannerMutex() { // FFTW's planner is not thread-safe; execution is
  static std::mutex m;
  return m;
}
} // namespace

const SettingsTable<SpectrumSettings>& spectrumSettingsTable() {
  using S = SpectrumSettings;
  using T = SettingsTable<S>;
  static const T t{
      T::number(&S::samples,
                {.id = "samples",
                 .label = "Number of samples",
                 .min = 8,
                 .max = 1e9,
                 .description =
                     "integration steps sampled (a fixed-step method; the step is the sampling interval)"}),
      T::number(&S::maxFrequency,
                {.id = "max_frequency",
                 .label = "Max. frequency",
                 .min = 0,
                 .description = "frequencies above are not shown (0: up to the Nyquist frequency)"}),
      T::number(&S::peaks, {.id = "peaks",
                            .label = "Number of peaks",
                            .min = 0,
                            .max = 1000,
                            .description = "how many of the strongest peaks are reported"}),
      T::number(&S::minPeakDistance, {.id = "min_peak_distance",
                                      .label = "Min. distance between peaks",
                                      .min = 0,
                                      .description = "peaks closer than this in frequency count as one"}),
  };
  return t;
}

SpectrumResult spectrumOf(const std::vector<double>& x, double step, const SpectrumSettings& s) {
  const long n = static_cast<long>(x.size());
  if (n < 8) throw InputError("spectrum: at least 8 samples are needed");
  SpectrumResult r;
  r.step = step;
  r.samples = n;
  // Hann window; remove the mean so the zero-frequency bin does not hide low peaks
  double mean = 0;
  for (double v : x)
    mean += v;
  mean /= n;
  std::vector<double> in(n);
  double windowSum = 0;
  for (long i = 0; i < n; ++i) {
    const double w = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * i / n);
    in[i] = (x[i] - mean) * w;
    windowSum += w;
  }
  std::vector<std::complex<double>> out(n / 2 + 1);
  fftw_plan plan;
  {
    std::lock_guard lock(plannerMutex());
    plan = fftw_plan_dft_r2c_1d(static_cast<int>(n), in.data(), reinterpret_cast<fftw_complex*>(out.data()),
                                FFTW_ESTIMATE);
  }
  fftw_execute(plan);
  {
    std::lock_guard lock(plannerMutex());
    fftw_destroy_plan(plan);
  }
  const double df = 1.0 / (n * step);
  std::vector<double> amp(out.size());
  for (std::size_t k = 0; k < out.size(); ++k)
    amp[k] = 2 * std::abs(out[k]) / windowSum;
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (s.maxFrequency > 0 && k * df > s.maxFrequency) break;
    r.frequency.push_back(k * df);
    r.amplitude.push_back(amp[k]);
  }
  // local maxima, refined by a parabola through the log amplitudes of the bin and its neighbours
  std::vector<SpectrumPeak> candidates;
  for (std::size_t k = 1; k + 1 < r.amplitude.size(); ++k) {
    if (!(amp[k] > amp[k - 1] && amp[k] >= amp[k + 1]) || amp[k] <= 0) continue;
    const double a = std::log(std::max(amp[k - 1], 1e-300)), b = std::log(amp[k]),
                 c = std::log(std::max(amp[k + 1], 1e-300));
    const double d = a - 2 * b + c, offset = d < 0 ? 0.5 * (a - c) / d : 0.0;
    candidates.push_back({(k + offset) * df, std::exp(b - 0.25 * (a - c) * offset)});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const auto& p, const auto& q) { return p.amplitude > q.amplitude; });
  for (const auto& c : candidates) {
    if (static_cast<int>(r.peaks.size()) >= s.peaks) break;
    const bool separate = std::all_of(r.peaks.begin(), r.peaks.end(), [&](const SpectrumPeak& p) {
      return std::abs(p.frequency - c.frequency) >= std::max(s.minPeakDistance, 1.5 * df);
    });
    if (separate) r.peaks.push_back(c);
  }
  return r;
}

SpectrumResult fourierSpectrum(const Model& model, Integrator& integ, const SpectrumSettings& s,
                               const ToolControl& control) {
  if (!model.isMap() && !integ.fixedStep())
    throw InputError(
        "spectrum: needs a fixed-step integrator (rk4, or everhart without adaptive): the samples "
        "must be evenly spaced");
  const int i = model.findObservable(s.function);
  if (i < 0) throw InputError("spectrum: unknown function '" + s.function + "' of " + model.info().id);
  if (s.samples < 8) throw InputError("spectrum: at least 8 samples are needed");
  const Observable& f = model.observables()[i];
  std::vector<double> x;
  x.reserve(s.samples);
  x.push_back(f.value(integ.time(), integ.state().data()));
  double step = 0;
  while (static_cast<long>(x.size()) < s.samples && !control.stopRequested()) {
    integ.step();
    step = std::abs(integ.time() - integ.previousTime());
    x.push_back(f.value(integ.time(), integ.state().data()));
    if (x.size() % 1024 == 0) control.progress(static_cast<double>(x.size()) / s.samples);
  }
  if (x.size() < 8) throw ComputationError("spectrum: stopped before 8 samples were taken");
  return spectrumOf(x, step, s);
}

} // namespace rv
