// FourierSpectrum.h -- the amplitude spectrum of an observable along a trajectory (manual §2.3.2), sampled at
// every step of a fixed-step integrator, Hann-windowed, transformed by FFTW (M. Frigo, S. G. Johnson, The
// design and implementation of FFTW3, Proc. IEEE 93 (2005) 216), with its strongest peaks located by
// parabolic interpolation of the log amplitude around each local maximum.
#pragma once
#include "dynamics/core/SettingsTable.h"
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/ToolControl.h"

#include <string>
#include <vector>

namespace rv {

struct SpectrumSettings {
  std::string function;       ///< observable to expand
  long samples = 16384;       ///< number of iterations (integration steps) sampled
  double maxFrequency = 0;    ///< frequencies above are computed but not returned (0: all)
  int peaks = 5;              ///< how many of the strongest peaks to report
  double minPeakDistance = 0; ///< peaks closer than this (in frequency) count as one
};

/// The settings of the "spectrum" scene section (samples, max_frequency, peaks, min_peak_distance), each
/// beside its member; the observable, "function", is text and read beside the table.
const SettingsTable<SpectrumSettings>& spectrumSettingsTable();

struct SpectrumPeak {
  double frequency = 0; ///< cycles per unit time
  double amplitude = 0; ///< of the sinusoid, in the observable's unit
};

struct SpectrumResult {
  std::vector<double> frequency, amplitude; ///< the one-sided amplitude spectrum
  std::vector<SpectrumPeak> peaks;          ///< strongest first
  double step = 0;                          ///< the sampling interval
  long samples = 0;                         ///< samples actually taken (fewer when stopped)
};

/// Samples the observable at t0, t0 + h, ... from a started fixed-step integrator. Throws InputError for an
/// unknown observable, too few samples or an integrator whose step varies.
SpectrumResult fourierSpectrum(const Model& model, Integrator& integrator, const SpectrumSettings& settings,
                               const ToolControl& control = {});

/// The spectrum and peaks of given samples (exposed for tests).
SpectrumResult spectrumOf(const std::vector<double>& samples, double step, const SpectrumSettings& settings);

} // namespace rv
