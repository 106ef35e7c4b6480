// Module.cpp -- the example module's entry point: the Roessler model, the tool return_times and the
// integrator dopri5 (docs/modules.md). Loaded, each is in `rollviz list problems|tools|integrators`, the GUI,
// Python, sweeps and mpirun, with no change to rollviz's own sources.
#include "Dopri5.h"
#include "ReturnTimes.h"
#include "Rossler.h"

ROLLVIZ_MODULE(registrar) {
  registrar.addModel(
      {&rossler::Rossler::staticInfo(), [](const rv::ParameterValues& p) -> std::unique_ptr<rv::Model> {
         return std::make_unique<rossler::Rossler>(p);
       }});
  registrar.addIntegrator(rossler::Dopri5::entry());
  registrar.addTool(rossler::returnTimesEntry(), rossler::returnTimesRunner(), &rossler::returnTimesTable());
}
