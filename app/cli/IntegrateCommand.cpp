// IntegrateCommand.cpp -- `rollviz integrate SCENE --time T --every DT --columns a,b,... [-o out.csv]`.
#include "app/cli/Commands.h"
#include "app/cli/Progress.h"
#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "dynamics/io/FileNames.h"
#include "render/export/VtkXmlFiles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <sstream>

namespace rv {

namespace {
struct IntegrateOptions {
  SceneArgs scene;
  double time = 10, every = 0.1;
  std::string columns, output; ///< empty: every observable (as Python's integrate)
};
} // namespace

Command addIntegrateCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("integrate", "integrate a scene and write observables as CSV");
  auto o = std::make_shared<IntegrateOptions>();
  addSceneArgs(cmd, o->scene);
  cmd->add_option("--time", o->time, "how long to integrate (simulation time)")->required();
  cmd->add_option("--every", o->every, "output period (rows at t = 0, every, 2 every, ...)")->required();
  cmd->add_option("--columns", o->columns,
                  "observables, comma separated (rollviz describe PROBLEM; default: all of them)");
  cmd->add_option(
         "-o,--output", o->output,
         "CSV file (default: standard output); a .vtp file is a polyline for ParaView through the first "
         "three columns, every column as point data")
      ->check(writesOneOf({".csv", ".vtp"}));
  return {cmd, [o] {
            const double time = o->time, every = o->every;
            const std::string &columns = o->columns, &output = o->output;
            const auto& args = o->scene;
            if (!(std::isfinite(time) && time >= 0)) throw InputError("--time: must be a finite number >= 0");
            if (!(std::isfinite(every) && every > 0)) throw InputError("--every: must be positive");
            const Scene scene = args.load();
            std::vector<std::string> ids;
            std::stringstream list(columns);
            for (std::string c; std::getline(list, c, ',');)
              ids.push_back(c);
            if (columns.empty())
              for (const auto& observable : scene.model->observables())
                ids.push_back(observable.id);
            const std::vector<int> cols = observableColumns(*scene.model, ids, "--columns");
            const auto& obs = scene.model->observables();
            // rows printed on the terminal show how far it got, and would share the progress line
            Progress progress("integrate", !output.empty() || !stdoutIsTerminal());
            // every row goes to `emit`; the answer says whether the run went to its end. Ctrl-C and the
            // progress are polled at every step: rows may lie many steps apart
            const auto sample = [&](const std::function<void(double, const std::vector<double>&)>& emit) {
              return sampleColumns(
                  scene, time, every, cols,
                  [&](double t, const std::vector<double>& row) {
                    emit(t, row);
                    return !interrupted();
                  },
                  [&](double t) {
                    progress.update(time > 0 ? std::min(1.0, std::abs(t) / time) : 1.0);
                    return !interrupted();
                  });
            };

            if (hasExtension(output, ".vtp")) {
              checkWritable(output, "-o");
              NamedColumns table;
              for (int c : cols)
                table.names.push_back(obs[c].id);
              const bool complete =
                  sample([&](double, const std::vector<double>& row) { table.addRow(row); });
              writePolyDataVtp(output, table, {0, cols.size() > 1 ? 1 : -1, cols.size() > 2 ? 2 : -1}, true);
              return complete ? 0 : 130;
            }
            std::unique_ptr<AtomicFile> file;
            FILE* out = stdout;
            if (!output.empty()) {
              file = std::make_unique<AtomicFile>(output, "-o");
              out = std::fopen(file->tempPath().c_str(), "w");
              if (!out) throw InputError("-o " + output + ": cannot open for writing");
            }
            for (std::size_t k = 0; k < cols.size(); ++k)
              std::fprintf(out, "%s%s", k ? "," : "", obs[cols[k]].id.c_str());
            std::fputc('\n', out);

            std::string failure;
            bool stopped = false;
            try {
              stopped = !sample([&](double, const std::vector<double>& row) {
                for (std::size_t k = 0; k < row.size(); ++k)
                  std::fprintf(out, "%s%.17g", k ? "," : "", row[k]);
                std::fputc('\n', out);
              });
            } catch (const ComputationError& e) {
              failure = e.what();
            }
            const bool ok = std::fflush(out) == 0 && !std::ferror(out);
            if (file) {
              std::fclose(out);
              if (!ok) throw ComputationError("cannot write " + output);
              if (failure.empty()) file->commit(); // a failed run leaves no file behind
            }
            if (!failure.empty()) throw ComputationError(failure);
            return stopped ? 130 : 0;
          }};
}

} // namespace rv
