// Qt Tests of the widgets (offscreen platform). The control panel: forms generated from the parameter tables
// (every parameter of the problem, the method and the tools has an editor), edits written into the scene
// document (only the touched fields, choices by name), and Apply emitting the document. The tool manager: the
// jobs as a tree, stop / continue / restart / delete on the selected one. The map's Undo / Redo history: its
// order and bounds. The 3D view's appearance edits: saved into the scene, read back as shown.
#include "app/gui/ControlPanel.h"
#include "app/gui/MapHistory.h"
#include "app/gui/ParameterForm.h"
#include "app/gui/PlotFilterDialog.h"
#include "app/gui/ToolManager.h"
#include "app/gui/ViewEdits.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/jobs/JobTree.h"
#include "dynamics/jobs/MegnoTask.h"
#include "dynamics/jobs/PoincareTask.h"
#include "dynamics/tools/ToolRegistry.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/SceneLoader.h"
#include "tests/gui/JobStatusText.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QToolButton>
#include <QTreeWidget>
#include <QtTest>

namespace rv {

class ControlPanelTest : public QObject {
  Q_OBJECT
private slots:
  void everyParameterHasAnEditor() {
    const Scene scene = loadScene(defaultScenePath("chaplygin_ball"));
    ControlPanel panel;
    panel.setScene(scene);
    for (const auto& s : scene.model->info().parameters.specs())
      QVERIFY2(panel.form("problem")->editor(s.id), s.id.c_str());
    for (const auto& s : scene.integratorEntry->parameters->specs())
      QVERIFY2(panel.form("method")->editor(s.id), s.id.c_str());
    for (const auto& t : toolSections())
      for (const auto& s : t.table->specs())
        QVERIFY2(panel.form(t.key)->editor(s.id), (t.key + "." + s.id).c_str());
    auto* energy = qobject_cast<QDoubleSpinBox*>(panel.form("problem")->editor("energy"));
    QVERIFY(energy);
    QCOMPARE(energy->value(), 0.5);
    // small values are kept exactly and shown readably
    auto* accuracy = qobject_cast<QDoubleSpinBox*>(panel.form("problem")->editor("root_accuracy"));
    QCOMPARE(accuracy->value(), 1e-15);
    QCOMPARE(accuracy->text(), QString("1e-15"));
  }

  // the observable a section names (poincare.section, spectrum.function) is chosen beside its table's form
  // and written into the document only when changed
  void theObservableOfASectionIsChosenBesideItsForm() {
    const Scene scene = loadScene(defaultScenePath("chaplygin_ball"));
    ControlPanel panel;
    panel.setScene(scene);
    auto* function = panel.findChild<QComboBox*>("spectrum_function");
    auto* section = panel.findChild<QComboBox*>("poincare_section");
    QVERIFY(function && section);
    QVERIFY(function->findText(QString::fromStdString(scene.model->observables().back().id)) >= 0);
    QVERIFY(!panel.editedDocument().contains("spectrum"));
    function->setCurrentText(QString::fromStdString(scene.model->observables().back().id));
    QCOMPARE(panel.editedDocument()["spectrum"]["function"].get<std::string>(),
             scene.model->observables().back().id);
    QCOMPARE(sceneFromJson(panel.editedDocument(), "edited.json")
                 .document["spectrum"]["function"]
                 .get<std::string>(),
             scene.model->observables().back().id);
  }

  void typingOutsideTheRangeSaysSoNextToTheField() {
    const Scene scene = loadScene(defaultScenePath("chaplygin_ball"));
    ControlPanel panel;
    panel.setScene(scene);
    ParameterForm* form = panel.form("problem");
    auto* box = qobject_cast<QDoubleSpinBox*>(form->editor("I1"));
    QVERIFY(box);
    QCOMPARE(form->problem("I1"), QString());
    auto* line = box->findChild<QLineEdit*>();
    QVERIFY(line);
    line->selectAll();
    QTest::keyClicks(line, "-5");
    QVERIFY2(form->problem("I1").startsWith("must lie in [0, inf]"), qPrintable(form->problem("I1")));
    line->selectAll();
    QTest::keyClicks(line, "abc");
    QCOMPARE(form->problem("I1"), QString("not a number"));
    line->selectAll();
    QTest::keyClicks(line, "2.5");
    QCOMPARE(form->problem("I1"), QString());
    // leaving a refused value: Qt keeps the last valid one, and the panel says so (the Results dock shows it)
    QTest::keyClick(line, Qt::Key_Return);
    const double kept = box->value();
    QSignalSpy refused(&panel, &ControlPanel::message);
    line->selectAll();
    QTest::keyClicks(line, "-5");
    QTest::keyClick(line, Qt::Key_Return);
    QCOMPARE(box->value(), kept);
    QCOMPARE(refused.size(), 1);
    const QString said = refused.first().at(0).toString();
    QVERIFY2(said.contains("-5 must lie in [0, inf]") && said.endsWith("kept 2.5"), qPrintable(said));
    QVERIFY(form->problem("I1").isEmpty());
    // validated when committed, not on each keystroke: typing 1e400 never takes the 1e4 met on the way
    line->selectAll();
    QTest::keyClicks(line, "1e400");
    QCOMPARE(box->value(), kept);
    QTest::keyClick(line, Qt::Key_Return);
    QCOMPARE(box->value(), kept);
    QCOMPARE(refused.size(), 2);
    const QString again = refused.at(1).at(0).toString();
    QVERIFY2(again.contains("1e400") && again.endsWith("kept 2.5"), qPrintable(again));
  }

  void editsBecomeTheSceneDocument() {
    const Scene scene = loadScene(defaultScenePath("chaplygin_ball"));
    ControlPanel panel;
    panel.setScene(scene);
    QCOMPARE(panel.editedDocument(),
             scene.document); // nothing touched: nothing changes (1e-15 is not rounded)
    auto* applyButton = panel.findChild<QPushButton*>("apply");
    QVERIFY(!panel.pending() && !applyButton->font().bold());
    const auto labelOf = [&](const char* id) { // the form's label of a field (its buddy row)
      auto* field = panel.form("problem")->editor(id);
      for (auto* l : panel.form("problem")->findChildren<QLabel*>())
        if (l->toolTip() == field->toolTip()) return l;
      return static_cast<QLabel*>(nullptr);
    };
    QVERIFY(labelOf("energy") && !labelOf("energy")->font().bold());
    qobject_cast<QDoubleSpinBox*>(panel.form("problem")->editor("energy"))->setValue(0.75);
    // a changed value waits for Apply, and shows it: its label bold, Apply bold with a dot
    QVERIFY(panel.pending() && applyButton->font().bold() && applyButton->text().contains("●"));
    QVERIFY(labelOf("energy")->font().bold());
    // put back to the scene's value: nothing waits (issue 61 (6): it stayed marked pending)
    auto* energy = qobject_cast<QDoubleSpinBox*>(panel.form("problem")->editor("energy"));
    const double was = scene.model->parameters()["energy"];
    energy->setValue(was);
    QVERIFY(!panel.pending() && !applyButton->font().bold() && !labelOf("energy")->font().bold());
    QCOMPARE(panel.editedDocument(), scene.document);
    energy->setValue(0.75);
    QVERIFY(panel.pending() && labelOf("energy")->font().bold());
    qobject_cast<QComboBox*>(panel.form("fixedpoint")->editor("method"))->setCurrentText("gradient");
    QSignalSpy applied(&panel, &ControlPanel::apply);
    QTest::mouseClick(panel.findChild<QPushButton*>("apply"), Qt::LeftButton);
    QCOMPARE(applied.count(), 1);
    const auto doc = applied.at(0).at(0).value<nlohmann::json>();
    QCOMPARE(doc["parameters"]["energy"].get<double>(), 0.75);
    QCOMPARE(doc["fixedpoint"]["method"].get<std::string>(), std::string("gradient"));
    QVERIFY(!doc["parameters"].contains("root_accuracy"));                   // untouched: not written
    QCOMPARE(doc["parameters"].size(), scene.document["parameters"].size()); // energy was there already
    // the document runs: the new scene has the new energy
    const Scene edited = sceneFromJson(doc, "edited");
    QCOMPARE(edited.model->parameters()["energy"], 0.75);
    QCOMPARE(edited.model->integrals(edited.initialState.data())[0], 0.75);
    QCOMPARE(edited.tool("fixedpoint").choice("method"), std::string("gradient"));
    panel.setScene(edited); // run: nothing waits any more
    QVERIFY(!panel.pending() && !applyButton->font().bold() && applyButton->text() == "Apply");
    QVERIFY(!labelOf("energy")->font().bold());
  }

  // Issue 43, item 8: what the problem refuses (I2 = 0, the triangle inequality) is said as soon as the value
  // is typed, naming the tab and the field; a scene loader's refusal at Apply names them too, not a JSON
  // path.
  void theProblemObjectsAtOnceNamingTabAndField() {
    const Scene scene = loadScene(defaultScenePath("chaplygin_ball"));
    ControlPanel panel;
    panel.setScene(scene);
    QVERIFY(panel.objection().isEmpty());
    auto* i2 = qobject_cast<QDoubleSpinBox*>(panel.form("problem")->editor("I2"));
    i2->setValue(0);
    QVERIFY2(panel.objection().startsWith("Problem tab, I2") && panel.objection().contains("positive"),
             qPrintable(panel.objection()));
    i2->setValue(5);
    QVERIFY2(panel.objection().contains("triangle inequality"), qPrintable(panel.objection()));
    i2->setValue(1.4);
    QVERIFY(panel.objection().isEmpty());
    const QString said = ControlPanel::inPanelWords(
        "scenes/x.json:poincare.points: points = -5 is out of range [1, 1e+15]", "scenes/x.json");
    QVERIFY2(said.endsWith(" tab, points: points = -5 is out of range [1, 1e+15]") &&
                 !said.contains("x.json"),
             qPrintable(said));
    QCOMPARE(ControlPanel::inPanelWords("scenes/x.json:parameters: I2: a moment of inertia must be positive",
                                        "scenes/x.json"),
             QString("Problem tab, I2: a moment of inertia must be positive"));
    // not a tab's value: as it is
    QCOMPARE(ControlPanel::inPanelWords("scenes/x.json:initial.map: no state there", "scenes/x.json"),
             QString("scenes/x.json:initial.map: no state there"));
  }

  // Issue 43: a panel narrower than its tabs -- every tab is one menu choice away (the corner button), and
  // the Tools tab shows the selected tool's whole description (its column is cut off in a narrow panel).
  void everyTabIsReachableAndAToolsDescriptionIsWhole() {
    const Scene scene = loadScene(defaultScenePath("henon_heiles"));
    ControlPanel panel;
    panel.setScene(scene);
    auto* tabs = panel.findChild<QTabWidget*>("tabs");
    auto* corner = panel.findChild<QToolButton*>("all_tabs");
    QVERIFY(tabs && corner && tabs->count() > 5);
    QMenu* menu = corner->menu();
    QVERIFY(menu);
    QMetaObject::invokeMethod(menu, "aboutToShow");
    const QList<QAction*> actions = menu->actions();
    QCOMPARE(actions.size(), tabs->count());
    QCOMPARE(actions.back()->text(), tabs->tabText(tabs->count() - 1));
    actions.back()->trigger();
    QCOMPARE(tabs->currentIndex(), tabs->count() - 1);
    auto* about = panel.findChild<QLabel*>("tool_about");
    QVERIFY(about);
    panel.selectTool("lyapunov");
    const ToolEntry* lyapunov = ToolRegistry::global().find("lyapunov");
    QVERIFY(lyapunov);
    QVERIFY2(about->text().contains(QString::fromStdString(lyapunov->description)) &&
                 about->text().contains(QString::fromStdString(lyapunov->reference)),
             qPrintable(about->text()));
  }

  // manual §2.2 / §2.1: the Method tab chooses the integrator (its own parameters shown), the Problem tab the
  // problem (its default scene opens)
  void methodAndProblemAreChosenInTheirTabs() {
    const Scene scene = loadScene(defaultScenePath("chaplygin_ball")); // rk4
    ControlPanel panel;
    panel.setScene(scene);
    auto* methods = panel.findChild<QComboBox*>("method_choice");
    QVERIFY(methods && methods->count() >= 3);
    QCOMPARE(methods->currentText(), QString("rk4"));
    QVERIFY(panel.chooseMethod("everhart"));
    QVERIFY(panel.form("method")->editor("order")); // Everhart's own parameters
    qobject_cast<QDoubleSpinBox*>(panel.form("method")->editor("step"))->setValue(0.02);
    const auto doc = panel.editedDocument();
    QCOMPARE(doc["integrator"]["method"].get<std::string>(), std::string("everhart"));
    QCOMPARE(doc["integrator"]["step"].get<double>(), 0.02);
    const Scene edited = sceneFromJson(doc, "edited");
    QCOMPARE(edited.integratorEntry->id, std::string("everhart"));
    QCOMPARE((*edited.integratorParameters)["step"], 0.02);
    QVERIFY(!panel.chooseMethod("no_such_method"));
    auto* problems = panel.findChild<QComboBox*>("problem_choice");
    QVERIFY(problems);
    QSignalSpy chosen(&panel, &ControlPanel::problemChosen);
    const int lorenz = problems->findText("lorenz");
    QVERIFY(lorenz >= 0);
    problems->setCurrentIndex(lorenz);
    emit problems->activated(lorenz); // as a user's pick does
    QCOMPARE(chosen.count(), 1);
    QCOMPARE(chosen.at(0).at(0).value<std::string>(), std::string("lorenz"));
  }
};

class ToolManagerTest : public QObject {
  Q_OBJECT
private slots:
  // the 3D plot filter proposes three different axes when the scene's plot gives fewer (not Z = t = X)
  void aThreeDimensionalPlotProposesThreeDifferentAxes() {
    const Scene scene = loadScene(defaultScenePath("chaplygin_ball"));
    PlotView none = scene.plot;
    none.settings.axes.clear();
    PlotFilterDialog dialog(*scene.model, none, scene.tool("plot"), 3);
    const auto axes = dialog.plot().settings.axes;
    QCOMPARE(axes.size(), std::size_t(3));
    QCOMPARE(axes[0], std::string("t"));
    QVERIFY(axes[2] != axes[0] && axes[2] != axes[1]);
  }

  void actsOnTheSelectedJob() {
    RunSpec spec(ModelRegistry::global().get("henon_heiles"), IntegratorRegistry::global().get("everhart"));
    spec.initialState = spec.makeModel()->stateFromMap({0.1, 0.1}, {}, "test");
    JobTree jobs;
    Job& trajectory = jobs.add(std::make_unique<PoincareTask>(spec, SectionSettings{.maxPoints = 0}));
    MegnoSettings ms;
    ms.maxTime = 1e9;
    Job& lyapunov = jobs.add(std::make_unique<MegnoTask>(spec, ms), &trajectory);
    std::vector<int> removed;
    ToolManager manager(jobs, [&](Job& j) {
      removed.push_back(j.id());
      jobs.remove(j);
    });
    manager.refresh();
    QCOMPARE(manager.tree()->topLevelItemCount(), 1);
    QCOMPARE(manager.tree()->topLevelItem(0)->childCount(), 1); // the MEGNO job under its trajectory
    QCOMPARE(manager.tree()->topLevelItem(0)->text(1), QString("Poincare map"));

    manager.select(lyapunov.id());
    manager.continueSelected();
    QVERIFY(lyapunov.running());
    QVERIFY(!trajectory.running());
    manager.stopSelected();
    QCOMPARE(lyapunov.status(), Job::Status::Stopped);
    QCOMPARE(manager.tree()->topLevelItem(0)->child(0)->text(2), QString("stopped"));
    QCOMPARE(manager.tree()->topLevelItem(0)->child(0)->foreground(1).style(), Qt::NoBrush); // default ink
    manager.restartSelected();
    QVERIFY(lyapunov.running());
    manager.refresh();
    QCOMPARE(manager.tree()->topLevelItem(0)->child(0)->foreground(1).color(), QColor(200, 20, 20)); // in red

    manager.select(trajectory.id());
    manager.deleteSelected(); // and the MEGNO job with it
    QCOMPARE(removed, std::vector<int>{1});
    QVERIFY(jobs.jobs().empty());
    QCOMPARE(manager.tree()->topLevelItemCount(), 0);
  }
};

class MapHistoryTest : public QObject {
  Q_OBJECT
private slots:
  // newest first, at most kSteps; a new change forgets what was undone; a redo keeps the other redos
  void keepsStepsInOrderAndForgetsRedoOnANewChange() {
    int changes = 0;
    MapHistory history([&] { ++changes; });
    const auto step = [](int k) { return MapHistory::Step{QString("step %1").arg(k), std::nullopt, {}, {}}; };
    for (int k = 1; k <= int(MapHistory::kSteps) + 5; ++k)
      history.push(step(k));
    QCOMPARE(changes, int(MapHistory::kSteps) + 5);
    int undone = 0;
    QString last;
    while (auto s = history.takeUndo())
      ++undone, last = s->what;
    QCOMPARE(undone, int(MapHistory::kSteps)); // the oldest five are gone
    QCOMPARE(last, QString("step 6"));
    QVERIFY(history.undoText().isEmpty());

    history.push(step(1));
    history.push(step(2));
    auto s = history.takeUndo();
    history.undone(s->what, Session{}); // the map before the undo, for Redo
    s = history.takeUndo();
    history.undone(s->what, Session{});
    QCOMPARE(history.redoText(), QString("step 1"));
    auto r = history.takeRedo();
    QCOMPARE(r->what, QString("step 1"));
    QVERIFY(r->map.has_value());
    history.redone(r->what, Session{});
    QCOMPARE(history.undoText(), QString("step 1"));
    QCOMPARE(history.redoText(), QString("step 2")); // the other redo stays
    history.push(step(3));
    QVERIFY(history.redoText().isEmpty()); // a new change: what was undone stays undone
    QCOMPARE(history.undoText(), QString("step 3"));
  }
};

class ViewEditsTest : public QObject {
  Q_OBJECT
private slots:
  // what Save writes of the user's edits, the scene loader reads back as the view that was shown
  void editsSavedIntoTheSceneReadBackAsShown() {
    const Scene scene = loadScene(defaultScenePath("ellipsoid_on_plane"));
    ViewEdits edits;
    ObjectOptions body = scene.view.object("body");
    body.colour = Rgb{0.2, 0.4, 0.6};
    body.style = SurfaceStyle::Grid;
    body.opacity = 0.5;
    body.gridDensity = 2;
    ObjectOptions trace = scene.view.object("trace");
    trace.enabled = false;
    edits.setObject("body", body);
    edits.setObject("trace", trace);
    AxesOptions axes;
    axes.style = AxesOptions::Style::Box;
    axes.tickmarks = 3, axes.subticks = 2;
    axes.min = std::array<double, 3>{-1, -2, -3}, axes.max = std::array<double, 3>{1, 2, 3};
    edits.setAxes(axes);
    edits.setFollow(!scene.view.camera.follow);
    const ViewOptions shown = edits.over(scene.view);

    nlohmann::json doc = scene.document;
    edits.writeInto(doc);
    const ViewOptions read = sceneFromJson(doc, "edited").view;
    const ObjectOptions& b = read.object("body");
    QVERIFY(b.colour && *b.colour == *shown.object("body").colour);
    QVERIFY(b.style == SurfaceStyle::Grid);
    QVERIFY(b.opacity && *b.opacity == 0.5);
    QCOMPARE(b.gridDensity, 2.0);
    QVERIFY(!read.object("trace").enabled);
    QVERIFY(read.axes.style == AxesOptions::Style::Box);
    QCOMPARE(read.axes.tickmarks, 3);
    QCOMPARE(read.axes.subticks, 2);
    QVERIFY(read.axes.min == axes.min && read.axes.max == axes.max);
    QCOMPARE(read.camera.follow, shown.camera.follow);
    QVERIFY(read.camera.follow != scene.view.camera.follow);

    edits.clear(); // another scene: none
    nlohmann::json untouched = scene.document;
    edits.writeInto(untouched);
    QCOMPARE(untouched, scene.document);
  }
};

} // namespace rv

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  int failed = 0;
  {
    rv::ControlPanelTest t;
    failed += QTest::qExec(&t, argc, argv);
  }
  {
    rv::ToolManagerTest t;
    failed += QTest::qExec(&t, argc, argv);
  }
  {
    rv::MapHistoryTest t;
    failed += QTest::qExec(&t, argc, argv);
  }
  {
    rv::ViewEditsTest t;
    failed += QTest::qExec(&t, argc, argv);
  }
  return failed ? 1 : 0;
}
#include "GuiTest.moc"
