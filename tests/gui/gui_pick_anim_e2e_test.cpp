// styk-gui end to end (issue 7) under xvfb-run: solve the sample cantilever, pick a node by
// clicking its projected pixel (the status bar names it), add a second one with Shift, make a node
// set of them (undoable, the results stay), chart the node's value over the increments, pick an
// element and a box of faces, then animate the deformation in 4 frames to a temporary directory:
// the numbered PNGs and the APNG exist, and every frame differs from the one before. Then a
// two-step contact analysis: increment labels, contact fields, the CPRESS history of a node, and
// the animation over the increments.
#include <QAction>
#include <QApplication>
#include <QChartView>
#include <QComboBox>
#include <QCryptographicHash>
#include <QFile>
#include <QLabel>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>

#include "gl_view.hpp"
#include "main_window.hpp"
#include "results_panel.hpp"
#include "session/picking.hpp"
#include "styk/elements/element_setup.hpp"
#include "styk/render/image.hpp"

using namespace styk;

namespace {

const QString kSource = STYK_SOURCE_DIR;
const QString kOutput = QString(STYK_BINARY_DIR) + "/tests/gui/output";

QByteArray file_hash(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256);
}

}  // namespace

class GuiPickAnimate : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    qputenv("STYK_GUI_NO_MESSAGE_BOXES", "1");
    QDir().mkpath(kOutput);
    warnings_ =
        styk::setup_element_registry(registry_, libraries_, {styk::build_plugin_directory()});
    window_ = std::make_unique<gui::MainWindow>(registry_);
    window_->view()->setFixedSize(640, 480);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    QVERIFY(window_->open_file(kSource + "/samples/cantilever-c3d20.inp"));
    QSignalSpy done(window_.get(), &gui::MainWindow::solve_finished);
    window_->start_solve();
    QVERIFY(done.wait(120000));
    QCOMPARE(done.takeFirst().at(0).toBool(), true);
    window_->set_field("U.mag");
    window_->view()->repaint();
    QApplication::processEvents();
  }

  void picksANodeByClickingItsPixel() {
    gui::GlView* view = window_->view();
    QCOMPARE(view->devicePixelRatioF(), 1.0);  // xvfb: widget pixels are framebuffer pixels
    window_->findChild<QAction*>("action_pick_node")->trigger();
    const gui::Scene& scene = view->scene();
    const gui::Picker picker(scene);
    // Two visible nodes well inside the model area, far apart: the nearest to the eye at the
    // largest x and at the smallest x.
    const Model& m = window_->document().model();
    const render::PixelRect& area = scene.last_frame().overlay.model;
    int first = -1, second = -1;
    for (int n = 0; n < m.node_count(); ++n) {
      const auto p = scene.screen_position(n);
      if (p[0] < area.x + 10 || p[0] > area.x + area.width - 10 || !picker.node_visible(n))
        continue;
      if (first < 0 || m.coords[n][0] > m.coords[first][0]) first = n;
      if (second < 0 || m.coords[n][0] < m.coords[second][0]) second = n;
    }
    QVERIFY(first >= 0 && second >= 0 && first != second);
    const auto pixel = [&](int n) {
      const auto p = scene.screen_position(n);
      return QPoint(int(p[0]), int(p[1]));
    };
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, pixel(first));
    QCOMPARE(scene.selection().nodes(), std::vector<int>{first});
    QLabel* status = nullptr;
    for (QLabel* l : window_->findChildren<QLabel*>())
      if (l->parent() && l->parent()->inherits("QStatusBar")) status = l;
    QVERIFY(status);
    QVERIFY2(status->text().startsWith(QString("node %1 ").arg(m.node_ids[first])),
             qPrintable(status->text()));
    QVERIFY2(status->text().contains("U.mag = "), qPrintable(status->text()));
    QTest::mouseClick(view, Qt::LeftButton, Qt::ShiftModifier, pixel(second));
    QCOMPARE(scene.selection().size(), std::size_t(2));
    QCOMPARE(status->text(), QString("2 nodes selected"));
    view->repaint();
    view->grab_picture().save(kOutput + "/e2e-picked-nodes.png");
    first_ = first;
    second_ = second;
  }

  void makesANodeSetKeepingTheResults() {
    QVERIFY(!window_->make_set_from_selection("1bad"));  // refused, with the reason
    QVERIFY(window_->last_message().contains("must start with a letter"));
    QVERIFY(window_->make_set_from_selection("picked"));
    const NodeSet* set = window_->document().model().find_nset("PICKED");
    QVERIFY(set);
    std::vector<int> expected{std::min(first_, second_), std::max(first_, second_)};
    QCOMPARE(set->nodes, expected);
    QVERIFY(window_->document().results());
    QCOMPARE(window_->document().history().undo_text(), std::string("Add node set PICKED"));
    window_->findChild<QAction*>("action_undo")->trigger();
    QVERIFY(!window_->document().model().find_nset("PICKED"));
    QVERIFY(window_->document().results());
  }

  void chartsTheNodeOverTheIncrements() {
    gui::GlView* view = window_->view();
    view->repaint();  // the undo rebuilt the scene: draw it before asking where a node is
    const auto p = view->scene().screen_position(first_);
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, QPoint(int(p[0]), int(p[1])));
    QCOMPARE(view->scene().selection().nodes(), std::vector<int>{first_});
    window_->show_node_history();
    QChartView* chart = nullptr;
    for (QWidget* w : QApplication::topLevelWidgets())
      if (auto* v = w->findChild<QChartView*>("history_view"); v && w->isVisible()) chart = v;
    QVERIFY(chart);
    auto* values = chart->window()->findChild<QLabel*>("history_values");
    QVERIFY(values);
    QVERIFY2(values->text().startsWith("step 1, increment 1, time 1: "),
             qPrintable(values->text()));
    chart->window()->grab().save(kOutput + "/e2e-history.png");
    chart->window()->close();
  }

  void picksElementsAndABoxOfFaces() {
    gui::GlView* view = window_->view();
    window_->findChild<QAction*>("action_pick_element")->trigger();
    // A pixel on the model: the first one with a face, scanning a row through the centre.
    const gui::Picker picker(view->scene());
    QPoint inside(-1, -1);
    for (int x = 0; x < 640 && inside.x() < 0; ++x)
      if (picker.face_at(x, 240)) inside = QPoint(x + 4, 240);
    QVERIFY(inside.x() >= 0);
    const auto expected = picker.face_at(inside.x(), inside.y());
    QVERIFY(expected);
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, inside);
    QCOMPARE(view->scene().selection().elements(), std::vector<int>{expected->element});
    auto* properties = window_->findChild<QTextBrowser*>();
    QVERIFY(properties);
    QVERIFY2(properties->toPlainText().contains("C3D20, centroid ("),
             qPrintable(properties->toPlainText()));
    window_->findChild<QAction*>("action_pick_face")->trigger();
    view->pick_box(QRect(0, 0, 640, 480), Qt::NoModifier);
    QVERIFY(view->scene().selection().faces().size() > 3);
    view->repaint();
    view->grab_picture().save(kOutput + "/e2e-picked-faces.png");
    QVERIFY(window_->make_set_from_selection("SEEN"));
    QVERIFY(window_->document().model().surfaces.count("SEEN"));
  }

  void exportsAnAnimation() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    window_->results_panel()->findChild<QSpinBox*>("animation_frames")->setValue(4);
    QVERIFY2(window_->export_animation(dir.path(), "anim"), qPrintable(window_->last_message()));
    QList<QByteArray> hashes;
    for (int k = 0; k < 4; ++k) {
      const QString path = QString("%1/anim_%2.png").arg(dir.path()).arg(k, 4, 10, QChar('0'));
      QVERIFY2(QFile::exists(path), qPrintable(path));
      hashes << file_hash(path);
      if (k > 0)
        QVERIFY2(hashes[k] != hashes[k - 1], qPrintable(path + " equals the frame before"));
      QFile::copy(path, kOutput + QString("/e2e-anim_%1.png").arg(k));
    }
    QVERIFY(!QFile::exists(dir.path() + "/anim_0004.png"));
    const QString apng = dir.path() + "/anim.apng";
    QVERIFY(QFile::exists(apng));
    const render::Image first = render::read_png(apng.toStdString());  // the APNG's default image
    const render::Image frame0 = render::read_png((dir.path() + "/anim_0000.png").toStdString());
    QCOMPARE(first.width, frame0.width);
    QVERIFY(first.rgba == frame0.rgba);
    // The view is back to the full deformation afterwards.
    QCOMPARE(window_->view()->scene().drawn_scale(), window_->view()->scene().deformation_scale());
  }

  // SPEC §3.2.3's two cantilevers (sample deck) loaded in two steps of two increments (the second
  // step raises the pressure by half): four increments with contact output.
  void navigatesAMultiStepContactResult() {
    QFile sample(kSource + "/samples/spec-3.2.3-two-cantilevers-c3d20-mu0.inp");
    QVERIFY(sample.open(QIODevice::ReadOnly));
    const QString deck = QString::fromUtf8(sample.readAll());
    const QString step = deck.mid(deck.indexOf("*STEP, NAME=LOAD"));
    QVERIFY(step.startsWith("*STEP"));
    QString second = step;
    second.replace("NAME=LOAD", "NAME=MORE")
        .replace("*STATIC\n1, 1", "*STATIC\n0.25, 0.5")
        .replace("2e+06", "3e+06");
    QString first = step;
    first.replace("*STATIC\n1, 1", "*STATIC\n0.5, 1");
    QTemporaryDir dir;
    QFile out(dir.path() + "/two-steps.inp");
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write((deck.left(deck.indexOf("*STEP, NAME=LOAD")) + first + second).toUtf8());
    out.close();
    QVERIFY(window_->open_file(out.fileName()));
    QSignalSpy done(window_.get(), &gui::MainWindow::solve_finished);
    window_->start_solve();
    QVERIFY(done.wait(120000));
    QCOMPARE(done.takeFirst().at(0).toBool(), true);
    const Results& results = *window_->document().results();
    QCOMPARE(results.increments.size(), std::size_t(4));

    auto* increment = window_->results_panel()->findChild<QComboBox*>("increment");
    QCOMPARE(increment->count(), 4);
    QCOMPARE(increment->itemText(1), QString("step 1, increment 2, time 1"));
    QCOMPARE(increment->itemText(3), QString("step 2, increment 2, time 1.5"));
    auto* field = window_->results_panel()->findChild<QComboBox*>("field");
    QVERIFY(field->findText("CPRESS") > 0);
    QVERIFY(field->findText("CSTATUS") > 0);
    window_->set_field("CPRESS");
    QCOMPARE(QString::fromStdString(window_->view()->scene().field()->name), QString("CPRESS"));
    increment->setCurrentIndex(1);
    QCOMPARE(window_->view()->scene().increment(), &results.increments[1]);

    // The most pressed slave node of the last increment: its pressure over the history.
    const ContactNodeResult* most = nullptr;
    for (const ContactNodeResult& c : results.increments.back().contact)
      if (!most || c.pressure > most->pressure) most = &c;
    QVERIFY(most && most->pressure > 0);
    gui::Selection selection(gui::PickKind::Node);
    gui::PickedItem item;
    item.node = most->node;
    selection.apply(gui::SelectOp::Replace, {item});
    window_->view()->scene().set_selection(selection);
    window_->show_node_history();
    QLabel* values = nullptr;
    for (QWidget* w : QApplication::topLevelWidgets())
      if (auto* v = w->findChild<QLabel*>("history_values"); v && w->isVisible()) values = v;
    QVERIFY(values);
    QCOMPARE(values->text().count('\n'), 3);  // 4 increments
    QVERIFY2(values->text().endsWith(QString("time 1.5: %1").arg(most->pressure, 0, 'E', 4)),
             qPrintable(values->text()));
    values->window()->grab().save(kOutput + "/e2e-history-cpress.png");
    values->window()->close();

    // One frame per increment, one colour range: the pictures differ as the load grows.
    window_->results_panel()->findChild<QComboBox*>("animation_kind")->setCurrentIndex(1);
    QVERIFY2(window_->export_animation(dir.path(), "steps"), qPrintable(window_->last_message()));
    for (int k = 0; k < 4; ++k) {
      const QString path = QString("%1/steps_%2.png").arg(dir.path()).arg(k, 4, 10, QChar('0'));
      QVERIFY2(QFile::exists(path), qPrintable(path));
      if (k > 0)
        QVERIFY(
            file_hash(path) !=
            file_hash(QString("%1/steps_%2.png").arg(dir.path()).arg(k - 1, 4, 10, QChar('0'))));
      QFile::copy(path, kOutput + QString("/e2e-steps_%1.png").arg(k));
    }
  }

  void cleanupTestCase() { window_.reset(); }

 private:
  PluginLibraries libraries_;
  ElementRegistry registry_;
  std::vector<styk::PluginDiagnostic> warnings_;
  std::unique_ptr<gui::MainWindow> window_;
  int first_ = -1, second_ = -1;
};

QTEST_MAIN(GuiPickAnimate)
#include "gui_pick_anim_e2e_test.moc"
