// Qt Test of the control panel: forms generated from the parameter tables (every parameter of the problem,
// the method and the tools has an editor), edits written into the scene document (only the touched fields,
// choices by name), and Apply emitting the document. Runs on the offscreen platform.
#include "app/gui/ControlPanel.h"
#include "app/gui/ParameterForm.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/SceneLoader.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSignalSpy>
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

  void editsBecomeTheSceneDocument() {
    const Scene scene = loadScene(defaultScenePath("chaplygin_ball"));
    ControlPanel panel;
    panel.setScene(scene);
    QCOMPARE(panel.editedDocument(),
             scene.document); // nothing touched: nothing changes (1e-15 is not rounded)
    qobject_cast<QDoubleSpinBox*>(panel.form("problem")->editor("energy"))->setValue(0.75);
    qobject_cast<QComboBox*>(panel.form("fixedpoint")->editor("method"))->setCurrentText("gradient");
    QSignalSpy applied(&panel, &ControlPanel::apply);
    QTest::mouseClick(panel.findChild<QPushButton*>("apply"), Qt::LeftButton);
    QCOMPARE(applied.count(), 1);
    const auto doc = applied.at(0).at(0).value<nlohmann::json>();
    QCOMPARE(doc["parameters"]["energy"].get<double>(), 0.75);
    QCOMPARE(doc["fixedpoint"]["method"].get<std::string>(), std::string("gradient"));
    QVERIFY(!doc["parameters"].contains("root_accuracy")); // untouched: not written
    QCOMPARE(doc["parameters"].size(), scene.document["parameters"].size()); // energy was there already
    // the document runs: the new scene has the new energy
    const Scene edited = sceneFromJson(doc, "edited");
    QCOMPARE(edited.model->parameters()["energy"], 0.75);
    QCOMPARE(edited.model->integrals(edited.initialState.data())[0], 0.75);
    QCOMPARE(edited.tool("fixedpoint").choice("method"), std::string("gradient"));
  }
};

} // namespace rv

QTEST_MAIN(rv::ControlPanelTest)
#include "ControlPanelTest.moc"
