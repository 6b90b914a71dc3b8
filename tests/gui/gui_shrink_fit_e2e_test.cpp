// Issue 7 walk-through end to end under xvfb-run: the SPEC §4.2 shrink fit built from an empty
// window through the dialogs only (material with expansion, two revolves sharing the fit
// cylinder, the frictional contact pair, two steps, symmetry and support conditions, the
// heating, the axial pressure, a node set along the sleeve bore), solved through `styk solve`,
// shown as CPRESS (the bore alone: hidden under the shaft in the iso view), unrolled over angle and
// axial position, Mises at the integration points with element numbers and the probe, and CPRESS
// charted along the sleeve. With STYK_GUI_SCREENSHOTS=dir the pictures of
// docs/gui.md are written there (docs/images/gui-shrink-*.png).
//
// Expected (SPEC §4.2): heating the shaft by 100 with alpha 2e-5 makes a radial interference of
// 0.02 at r = 10; Lamé gives p = 111.1 MPa (plane stress) .. 122 MPa (plane strain) under the
// sleeve. Asserted: the mean pressure of the rings 25 <= z <= 35 at the end of step 1 lies in
// that band (friction holds the shaft's thermal elongation under the sleeve, an axial stress
// that moves it towards plane strain; measured 121.3 on this coarse mesh: C3D21 contact layers,
// 15 degrees around, 2 elements across the sleeve, 5 mm rows). The coarse rows do not resolve
// the pressure peaks at the sleeve edges (the edge rings measure 113.8, below the middle; the
// verification test's finer mesh shows them). Step 2: the sleeve, held axially by friction
// alone, is in equilibrium: the axial contact force equals the push on its top annulus.
#include <QAction>
#include <QApplication>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <cmath>
#include <map>

#include "form_dialog.hpp"
#include "gl_view.hpp"
#include "main_window.hpp"
#include "model_tree.hpp"
#include "results_panel.hpp"
#include "session/picking.hpp"
#include "styk/elements/element_setup.hpp"

using namespace styk;

namespace {

gui::FormDialog* open_dialog(gui::MainWindow& w, const QString& action) {
  auto* a = w.findChild<QAction*>(action);
  if (!a) return nullptr;
  a->trigger();
  QApplication::processEvents();
  for (gui::FormDialog* d : w.findChildren<gui::FormDialog*>())
    if (d->isVisible()) return d;
  return nullptr;
}

void set_text(gui::FormDialog* d, const QString& key, const QString& value) {
  if (auto* e = d->findChild<QLineEdit*>(key))
    e->setText(value);
  else if (auto* c = d->findChild<QComboBox*>(key))
    c->setCurrentText(value);
}

// Fills the fields, presses OK, and reports the dialog's refusal when it stays open.
QString fill_and_accept(gui::MainWindow& w, const QString& action,
                        const std::vector<std::pair<QString, QString>>& fields,
                        const QString& screenshot = {}) {
  gui::FormDialog* d = open_dialog(w, action);
  if (!d) return "no dialog for " + action;
  for (const auto& [key, value] : fields) set_text(d, key, value);
  const QString dir = qEnvironmentVariable("STYK_GUI_SCREENSHOTS");
  if (!dir.isEmpty() && !screenshot.isEmpty()) d->grab().save(dir + "/" + screenshot);
  d->accept();
  return d->isVisible() ? d->error_text() : QString();
}

// Mean contact pressure per slave ring z (rounded to 1e-6) of an increment.
std::map<double, double> pressure_by_height(const Model& model, const IncrementResult& r) {
  std::map<double, std::pair<double, int>> sums;
  for (const ContactNodeResult& c : r.contact) {
    const double z = std::round(model.coords[c.node][2] * 1e6) / 1e6;
    sums[z].first += c.pressure;
    sums[z].second += 1;
  }
  std::map<double, double> out;
  for (const auto& [z, s] : sums) out[z] = s.first / s.second;
  return out;
}

double mid_sleeve(const std::map<double, double>& rings) {
  double sum = 0.0;
  int count = 0;
  for (const auto& [z, p] : rings)
    if (z >= 25.0 - 1e-9 && z <= 35.0 + 1e-9) {
      sum += p;
      ++count;
    }
  return count ? sum / count : 0.0;
}

}  // namespace

class ShrinkFitWalkThrough : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    qputenv("STYK_GUI_NO_MESSAGE_BOXES", "1");
    shots_ = qEnvironmentVariable("STYK_GUI_SCREENSHOTS");
    if (!shots_.isEmpty()) QDir().mkpath(shots_);
    styk::setup_element_registry(registry_, libraries_, {styk::build_plugin_directory()});
    window_ = std::make_unique<gui::MainWindow>(registry_);
    window_->resize(1280, 820);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  }

  void materialWithExpansion() {
    QCOMPARE(
        fill_and_accept(
            *window_, "action_material",
            {{"name", "STEEL"}, {"young", "200000"}, {"poisson", "0.3"}, {"expansion", "-2e-5"}}),
        QString("expansion coefficient must be >= 0 (0: not given)"));
    for (gui::FormDialog* d : window_->findChildren<gui::FormDialog*>()) d->close();
    QCOMPARE(
        fill_and_accept(
            *window_, "action_material",
            {{"name", "STEEL"}, {"young", "200000"}, {"poisson", "0.3"}, {"expansion", "2e-5"}}),
        QString());
    QCOMPARE(*window_->document().model().materials.at(0).expansion, 2e-5);
  }

  void twoRevolvesSharingTheFitCylinder() {
    const std::vector<std::pair<QString, QString>> shaft = {
        {"name", "SHAFT"},       {"radii", "0 10"}, {"z", "0 60"},           {"angle", "90"},
        {"divisions", "2 12 5"}, {"type", "C3D21"}, {"layer_side", "OUTER"}, {"material", "STEEL"}};
    QCOMPARE(fill_and_accept(*window_, "action_revolve", shaft),
             QString("a solid (inner radius 0) needs an even number of divisions around per 90 "
                     "degrees: 5 around 90 degrees is not a multiple of 2"));
    for (gui::FormDialog* d : window_->findChildren<gui::FormDialog*>()) d->close();
    auto fixed = shaft;
    fixed[4].second = "2 12 6";
    QCOMPARE(fill_and_accept(*window_, "action_revolve", fixed, "gui-shrink-revolve.png"),
             QString());
    QCOMPARE(fill_and_accept(*window_, "action_revolve",
                             {{"name", "SLEEVE"},
                              {"radii", "10 15"},
                              {"z", "20 40"},
                              {"angle", "90"},
                              {"divisions", "2 4 6"},
                              {"type", "C3D21"},
                              {"layer_side", "INNER"},
                              {"material", "STEEL"}}),
             QString());
    const Model& m = window_->document().model();
    QCOMPARE(m.element_count(), 252 + 48);
    QVERIFY(m.surfaces.count("SLEEVE_INNER") && m.surfaces.count("SHAFT_OUTER"));
    window_->view()->set_named_view("iso");
    window_->view()->fit();
    window_->set_display_mode(render::DisplayMode::ShadedEdges);
    QApplication::processEvents();
    if (!shots_.isEmpty()) window_->grab().save(shots_ + "/gui-shrink-mesh.png");
    window_->set_display_mode(render::DisplayMode::Shaded);
  }

  void frictionalContactPair() {
    QCOMPARE(fill_and_accept(*window_, "action_contact",
                             {{"slave", "SLEEVE_INNER"}, {"master", "SLEEVE_INNER"}}),
             QString("slave and master are the same surface SLEEVE_INNER; self-contact is not "
                     "supported"));
    for (gui::FormDialog* d : window_->findChildren<gui::FormDialog*>()) d->close();
    QCOMPARE(
        fill_and_accept(*window_, "action_contact",
                        {{"slave", "SLEEVE_INNER"}, {"master", "SHAFT_OUTER"}, {"mu", "-0.2"}}),
        QString("friction coefficient must be >= 0, not -0.200000"));
    for (gui::FormDialog* d : window_->findChildren<gui::FormDialog*>()) d->close();
    QCOMPARE(fill_and_accept(*window_, "action_contact",
                             {{"slave", "SLEEVE_INNER"},
                              {"master", "SHAFT_OUTER"},
                              {"interaction", "FIT"},
                              {"friction", "isotropic"},
                              {"mu", "0.2"}},
                             "gui-shrink-contact.png"),
             QString());
    QCOMPARE(window_->document().model().contact_pairs.size(), std::size_t(1));
  }

  void stepsSupportsHeatingAndPressure() {
    QCOMPARE(fill_and_accept(*window_, "action_step", {{"name", "HEAT"}, {"initial", "0.25"}}),
             QString());
    QCOMPARE(fill_and_accept(*window_, "action_step", {{"name", "PUSH"}, {"initial", "0.25"}}),
             QString());
    // Quarter model: the cut at angle 0 is the plane y = 0, the one at 90 degrees x = 0.
    const std::pair<QString, QString> supports[] = {{"SHAFT_BOTTOM", "3"},
                                                    {"SHAFT_CUT0", "2"},
                                                    {"SLEEVE_CUT0", "2"},
                                                    {"SHAFT_CUT1", "1"},
                                                    {"SLEEVE_CUT1", "1"}};
    for (const auto& [set, dof] : supports)
      QCOMPARE(fill_and_accept(*window_, "action_boundary",
                               {{"nset", set},
                                {"first", dof},
                                {"last", dof},
                                {"value", "0"},
                                {"step", "0 (all steps)"}}),
               QString());
    QCOMPARE(fill_and_accept(*window_, "action_initial_temperature",
                             {{"nset", "SHAFT"}, {"value", "0"}}),
             QString());
    QCOMPARE(fill_and_accept(*window_, "action_temperature",
                             {{"nset", "SHAFT"}, {"value", "100"}, {"step", "1 HEAT"}},
                             "gui-shrink-temperature.png"),
             QString());
    QCOMPARE(
        fill_and_accept(*window_, "action_pressure",
                        {{"surface", "SLEEVE_TOP"}, {"magnitude", "52.5"}, {"step", "2 PUSH"}}),
        QString());
    QCOMPARE(fill_and_accept(
                 *window_, "action_common_nodes",
                 {{"name", "SLEEVE_LINE"}, {"first", "SLEEVE_INNER"}, {"second", "SLEEVE_CUT0"}}),
             QString());
    QCOMPARE(window_->document().model().nsets.at("SLEEVE_LINE").nodes.size(), std::size_t(9));
  }

  void deletingAUsedMaterialIsRefused() {
    auto* tree = window_->findChild<gui::ModelTree*>();
    QVERIFY(tree);
    QTreeWidgetItem* steel = tree->find_item("STEEL");
    QVERIFY(steel);
    tree->setCurrentItem(steel);
    tree->setFocus();
    QTest::keyClick(tree, Qt::Key_Delete);
    QCOMPARE(window_->last_message(),
             QString("material STEEL is used by the section on SHAFT; delete or change that "
                     "section first"));
    QCOMPARE(window_->document().model().materials.size(), std::size_t(1));
    // Double-click edits: the material dialog opens filled with the material's values.
    emit tree->itemDoubleClicked(steel, 0);
    QApplication::processEvents();
    gui::FormDialog* edit = nullptr;
    for (gui::FormDialog* d : window_->findChildren<gui::FormDialog*>())
      if (d->isVisible()) edit = d;
    QVERIFY(edit);
    QCOMPARE(edit->windowTitle(), QString("Edit material"));
    QCOMPARE(QString::fromStdString(edit->text("expansion")), QString("2e-05"));
    edit->reject();
    QTreeWidgetItem* pair = tree->find_item("SLEEVE_INNER / SHAFT_OUTER");
    QVERIFY(pair);
    tree->scrollToItem(pair);
    if (!shots_.isEmpty()) window_->grab().save(shots_ + "/gui-shrink-model.png");
  }

  void solvesAndShowsTheContactPressure() {
    QSignalSpy done(window_.get(), &gui::MainWindow::solve_finished);
    window_->start_solve();
    QVERIFY(done.wait(120000));
    QVERIFY2(done.takeFirst().at(0).toBool(), qPrintable(window_->last_message()));
    const Results* r = window_->document().results();
    QVERIFY(r);
    const Model& m = window_->document().model();
    const IncrementResult* heated = nullptr;
    for (const IncrementResult& inc : r->increments)
      if (inc.step == 1) heated = &inc;
    QVERIFY(heated);
    const std::map<double, double> rings = pressure_by_height(m, *heated);
    const double mid = mid_sleeve(rings);
    const double pushed = mid_sleeve(pressure_by_height(m, r->increments.back()));
    // Step 2: the sleeve is held axially by friction alone, so the contact force on it balances
    // the pressure on its top annulus: 52.5 x pi (15^2 - 10^2) / 4 = 5154.2 N on the quarter
    // (to 0.5 %; measured to round-off).
    const double push = 52.5 * 3.14159265358979 * (225.0 - 100.0) / 4.0;
    QVERIFY(!r->increments.back().contact_pairs.empty());
    const double held = r->increments.back().contact_pairs.at(0).force[2];
    qInfo(
        "%d elements, %d nodes; mid-sleeve contact pressure: heated %.2f MPa, pushed %.2f MPa; "
        "edge rings %.2f / %.2f; axial contact force on the sleeve %.1f N (push %.1f N)",
        m.element_count(), m.node_count(), mid, pushed, rings.begin()->second,
        rings.rbegin()->second, held, push);
    QVERIFY2(mid >= 111.1 && mid <= 122.0, qPrintable(QString::number(mid)));
    QVERIFY2(std::abs(std::abs(held) - push) < 0.005 * push, qPrintable(QString::number(held)));
    QVERIFY(pushed > 0.9 * mid && pushed < mid);  // the push unloads the grip a little

    window_->set_field("CPRESS");
    QVERIFY(window_->view()->scene().field());
    QCOMPARE(QString::fromStdString(window_->view()->scene().field()->name), QString("CPRESS"));
    // Both bodies shown, undeformed, seen from -y: the sleeve's bore lies on the shaft, behind
    // the shaft's cut face, so the first frame draws the bore alone (its concave side towards
    // the eye) and says so in the title block.
    for (QCheckBox* box : window_->results_panel()->findChildren<QCheckBox*>())
      if (box->text() == "Deformed shape") box->setChecked(false);
    window_->view()->set_named_view("-y");
    window_->findChild<QAction*>("action_smooth_edges")->trigger();  // pictures for the report
    window_->view()->repaint();
    QTest::qWait(50);
    const gui::Scene& scene = window_->view()->scene();
    QCOMPARE(scene.last_frame().samples, 4);
    QVERIFY(scene.field_faces_only());
    QVERIFY2(QString::fromStdString(scene.note()).startsWith("CPRESS on its faces alone"),
             scene.note().c_str());
    if (!shots_.isEmpty()) window_->grab().save(shots_ + "/gui-shrink-cpress.png");
  }

  // The unrolled map of the bore: the shaft's axis (z), radius 10, a quarter turn, 20 mm long.
  void unrollsTheContactPressure() {
    auto* unrolled = window_->results_panel()->findChild<QCheckBox*>("unrolled");
    QVERIFY(unrolled);
    unrolled->setChecked(true);
    window_->view()->repaint();
    QTest::qWait(50);
    const render::UnrolledSurface* map = window_->view()->scene().unrolled();
    QVERIFY(map);
    QCOMPARE(int(map->kind), int(render::UnrolledSurface::Kind::Revolved));
    QVERIFY2(std::abs(map->radius - 10.0) < 0.01, qPrintable(QString::number(map->radius)));
    QVERIFY(std::abs(std::abs(map->axis.direction[2]) - 1.0) < 1e-9);
    QVERIFY(std::abs(map->v_range[0] - 20.0) < 1e-9 && std::abs(map->v_range[1] - 40.0) < 1e-9);
    QVERIFY2(std::abs(render::map_degrees(*map, map->u_range[0])) < 1e-3 &&
                 std::abs(render::map_degrees(*map, map->u_range[1]) - 90.0) < 1e-3,
             qPrintable(QString("%1 .. %2")
                            .arg(render::map_degrees(*map, map->u_range[0]))
                            .arg(render::map_degrees(*map, map->u_range[1]))));
    // What the map shows near the lower edge is in the nodal values: around the ring at z = 20 the
    // pressure alternates between the C3D21 faces' corner nodes (every 15 degrees) and their
    // mid-edge nodes (7.5 degrees off); at mid-length it is uniform around.
    const Model& m = window_->document().model();
    const IncrementResult& last = window_->document().results()->increments.back();
    const auto ripple = [&](double z) {
      double corner = 0, mid = 0;
      int corners = 0, mids = 0;
      for (const ContactNodeResult& c : last.contact) {
        const Vec3& x = m.coords[c.node];
        if (std::abs(x[2] - z) > 1e-6) continue;
        const double degrees = std::atan2(x[1], x[0]) * 180.0 / 3.14159265358979;
        const bool at_corner = std::abs(std::remainder(degrees, 15.0)) < 1e-3;
        (at_corner ? corner : mid) += c.pressure;
        ++(at_corner ? corners : mids);
      }
      return std::abs(corner / corners - mid / mids) / (0.5 * (corner / corners + mid / mids));
    };
    qInfo("corner/mid-edge pressure ripple around the bore: z = 20: %.3f, z = 30: %.4f",
          ripple(20.0), ripple(30.0));  // measured 0.131 and 0.0169
    QVERIFY2(ripple(20.0) > 0.10, qPrintable(QString::number(ripple(20.0))));
    QVERIFY2(ripple(30.0) < 0.03, qPrintable(QString::number(ripple(30.0))));
    if (!shots_.isEmpty()) window_->grab().save(shots_ + "/gui-shrink-unrolled.png");
    // File > Export view as PNG or BMP: the map as a BMP (by the extension).
    const QString bmp = QDir::temp().filePath("styk_gui_shrink_unrolled.bmp");
    QVERIFY(window_->export_png(bmp));
    QFile file(bmp);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.read(2), QByteArray("BM"));
    file.close();
    QFile::remove(bmp);
    unrolled->setChecked(false);
    QVERIFY(!window_->view()->scene().unrolled());
  }

  // Mises at the integration points with the element numbers of the seen elements; hovering over
  // an element reports its points' values in the status bar.
  void showsIntegrationPointValuesAndNumbers() {
    window_->set_field("S.mises");
    auto* points = window_->results_panel()->findChild<QCheckBox*>("ip_values");
    QVERIFY(points);
    points->setChecked(true);
    window_->findChild<QAction*>("action_element_numbers")->trigger();
    // The sleeve alone (the shaft's layer unticked), from the iso direction.
    QTreeWidgetItem* shaft = window_->findChild<gui::ModelTree*>()->find_item("SHAFT — ");
    QVERIFY(shaft);
    shaft->setCheckState(0, Qt::Unchecked);
    window_->view()->set_named_view("iso");
    window_->view()->repaint();
    QTest::qWait(50);
    const gui::Scene& scene = window_->view()->scene();
    QVERIFY(scene.point_field());
    QVERIFY(!scene.last_frame().overlay.labels.empty());
    // The 48 sleeve elements' points (the shaft's layer is hidden).
    QCOMPARE(int(scene.last_frame().geometry.ip_points.size()), 48 * 27);
    // C3D21 and C3D20 elements: 27 points each (3 x 3 x 3 Gauss).
    const auto probe = scene.element_probe(0);
    QVERIFY(probe && probe->points.size() == 27);
    // Hover over a pixel where an element is drawn (found with the view's own picker).
    QPoint over;
    {
      const gui::Picker picker(scene);
      const qreal ratio = window_->view()->devicePixelRatioF();
      const QRect r = window_->view()->rect();
      for (int y = r.center().y(); y < r.bottom() && over.isNull(); y += 4)
        for (int x = r.left() + 10; x < r.right() && over.isNull(); x += 4)
          if (picker.face_at(int(x * ratio), int(y * ratio))) over = QPoint(x, y);
    }
    QVERIFY(!over.isNull());
    // Delivered directly: a pointer moved by QTest may not reach a window without focus.
    QMouseEvent move(QEvent::MouseMove, QPointF(over), window_->view()->mapToGlobal(QPointF(over)),
                     Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(window_->view(), &move);
    QApplication::processEvents();
    QString status;
    for (QLabel* label : window_->findChildren<QLabel*>())
      if (label->text().startsWith("element ")) status = label->text();
    QVERIFY2(status.contains("S.mises at 27 integration points"),
             qPrintable("status: '" + status + "'"));
    if (!shots_.isEmpty()) window_->grab().save(shots_ + "/gui-shrink-ip.png");
    window_->findChild<QAction*>("action_element_numbers")->trigger();
    points->setChecked(false);
    shaft->setCheckState(0, Qt::Checked);
    window_->set_field("CPRESS");
  }

  void chartsThePressureAlongTheSleeve() {
    auto* path = window_->results_panel()->findChild<QComboBox*>("path");
    QVERIFY(path);
    path->setCurrentText("SLEEVE_LINE");
    auto* chart = window_->results_panel()->findChild<QWidget*>("chart");
    QVERIFY(chart);
    QMetaObject::invokeMethod(chart, "click");
    QApplication::processEvents();
    QChartView* view = nullptr;
    for (QWidget* w : QApplication::topLevelWidgets())
      if (auto* v = w->findChild<QChartView*>("chart_view"); v && w->isVisible()) view = v;
    QVERIFY(view);
    QVERIFY(!view->chart()->series().isEmpty());
    if (!shots_.isEmpty()) view->window()->grab().save(shots_ + "/gui-shrink-chart.png");
    view->window()->close();
  }

  // The constraint dialogs on the solved model: a refusal each, then an edit that Undo takes back.
  void constraintDialogsAndUndo() {
    QCOMPARE(
        fill_and_accept(
            *window_, "action_transform",
            {{"nset", "SHAFT_CUT1"}, {"system", "cylindrical"}, {"a", "0 0 0"}, {"b", "0 0 1"}})
            .contains("lies on the axis"),
        true);
    for (gui::FormDialog* d : window_->findChildren<gui::FormDialog*>()) d->close();
    QCOMPARE(
        fill_and_accept(
            *window_, "action_transform",
            {{"nset", "SLEEVE_OUTER"}, {"system", "cylindrical"}, {"a", "0 0 0"}, {"b", "0 0 1"}}),
        QString());
    QCOMPARE(window_->document().model().transforms.size(), std::size_t(1));
    QCOMPARE(fill_and_accept(*window_, "action_equation", {{"terms", "1 1 1"}}),
             QString("an equation needs at least 2 terms (one term is a boundary condition)"));
    for (gui::FormDialog* d : window_->findChildren<gui::FormDialog*>()) d->close();
    window_->findChild<QAction*>("action_undo")->trigger();
    QVERIFY(window_->document().model().transforms.empty());
  }

  void cleanupTestCase() { window_.reset(); }

 private:
  PluginLibraries libraries_;
  ElementRegistry registry_;
  std::unique_ptr<gui::MainWindow> window_;
  QString shots_;
};

QTEST_MAIN(ShrinkFitWalkThrough)
#include "gui_shrink_fit_e2e_test.moc"
