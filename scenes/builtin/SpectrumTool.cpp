// SpectrumTool.cpp -- the spectrum tool: the Fourier spectrum of spectrum.function along the scene's
// trajectory (dynamics/tools/FourierSpectrum.h). Its chart is BuiltinCharts.cpp's.
#include "dynamics/core/Errors.h"
#include "dynamics/tools/FourierSpectrum.h"
#include "scenes/builtin/BuiltinTool.h"

namespace rv {

namespace {

// the Fourier spectrum of spectrum.function along the scene's trajectory
ToolResult runSpectrum(const Scene& scene, const ToolControl& control) {
  SpectrumSettings s = scene.settings(spectrumSettingsTable(), "spectrum");
  s.function = scene.document.value("spectrum", nlohmann::json::object()).value("function", std::string());
  if (s.function.empty()) throw InputError("the scene has no spectrum.function (the observable to expand)");
  auto integ = scene.startIntegrator();
  const SpectrumResult r = fourierSpectrum(*scene.model, *integ, s, control);
  ToolResult out;
  out.table.names = {"frequency", "amplitude"};
  out.table.values = {r.frequency, r.amplitude};
  nlohmann::json peaks = nlohmann::json::array();
  for (const auto& p : r.peaks)
    peaks.push_back({{"frequency", p.frequency}, {"amplitude", p.amplitude}});
  out.fields = {{"function", s.function}, {"peaks", peaks}, {"step", r.step}, {"samples", r.samples}};
  out.stopped = control.stopRequested();
  return out;
}

} // namespace

BuiltinTool spectrumTool() {
  return {.entry = {.id = "spectrum",
                    .title = "Fourier spectrum",
                    .parent = "poincare",
                    .description = "of spectrum.function along the trajectory (a chart window)",
                    .section = "spectrum",
                    .command = "spectrum",
                    .commandHelp = "Fourier spectrum of an observable along a scene's trajectory",
                    .chartView = "spectrum",
                    .outputs = {{"frequency", "the frequencies (a column of the table)"},
                                {"amplitude", "the amplitude at each frequency (a column of the table)"},
                                {"peaks", "the largest peaks, each a frequency and its amplitude"},
                                {"function", "the observable expanded (spectrum.function)"},
                                {"step", "the sampling step in time"},
                                {"samples", "the number of samples"}},
                    .reference = "manual §2.3.2; FFTW",
                    .computation = "dynamics/tools/FourierSpectrum.h (fourierSpectrum)"},
          .settings = ToolSection{.title = "Fourier spectrum",
                                  .table = &spectrumSettingsTable().table(),
                                  .observableKey = "function"},
          .runner = ToolRunner{.run = runSpectrum}};
}

} // namespace rv
