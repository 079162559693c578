// The Ball story dock with its trails and velocity arrows, and File > Export Image, as a user
// meets them in the window (Xvfb, Mesa's OpenGL).
//
// With CAROM_SCREENSHOT_DIR set, a picture of the window with two balls' stories is saved there.

#include "sim/io/scene_file.h"
#include "tests/editor_fixture.h"
#include "ui/dialogs/image_export.h"
#include "ui/docks/ball_story_dock.h"
#include "ui/run/run_session.h"

#include <QDir>
#include <QFileDialog>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QTemporaryDir>

using carom::Vec3;
using carom::editor::ObjectKind;
using carom::ui::BallStoryDock;

class TestStoryExport : public carom::testing::EditorFixture {
  Q_OBJECT

 private slots:
  void init() { openWindow(); }
  void cleanup() { window_.reset(); }

  void storyOfASelectedBallGrowsWithTheRun();
  void newlySelectedBallsStartFromThen();
  void manySelectedBallsAreCapped();
  void showTimeMovesTheCursorAndEndsTheTrail();
  void resetRestartsTheStory();
  void anEditRestartsTheStory();
  void dockIsInTheViewMenu();
  void exportWritesTheChosenSize();
  void exportLeavesOutTheEditorsMarks();
  void exportRefusesBadSizesAndUnwritablePaths();
  void exportImageMenuAsksSizeThenFile();
  void screenshotOfTheMagicRoom();

 private:
  BallStoryDock& dock() { return *ballStoryDock(*window_); }
  // The floor scene's ball thrown sideways and up, so that it bounces between the walls.
  void throwTheBall() {
    carom::Scene edited = document().scene();
    edited.balls[0].velocity = Vec3(2, 4, 0);
    QVERIFY(carom::testing::applyEdit(document(), edited, "throw").isEmpty());
  }
  void addBalls(int count) {
    carom::Scene edited = document().scene();
    for (int i = 0; i < count; ++i) {
      carom::Ball ball = edited.balls[0];
      ball.position = Vec3(-3.0 + 0.6 * i, 2.0, 0);
      ball.radius = 0.2;
      ball.name.clear();
      edited.balls.push_back(ball);
    }
    QVERIFY(carom::testing::applyEdit(document(), edited, "more").isEmpty());
  }
  void selectBalls(std::vector<int> balls) {
    carom::editor::Selection selection;
    for (int ball : balls) selection.push_back({ObjectKind::Ball, ball});
    document().setSelection(selection);
  }
  // Runs until the story passes `time` and ball 0 has at least `samples` samples (one comes with
  // each frame shown, so a slow machine, as under a sanitizer, needs longer), then pauses and
  // waits for the paused state to be shown.
  void runUntil(double time, std::size_t samples = 0) {
    window_->setRunning(true);
    QTRY_VERIFY_WITH_TIMEOUT(dock().story().lastTime().value_or(0.0) > time &&
                                 dock().story().samples(0).size() >= samples,
                             30000);
    window_->setRunning(false);
    QTRY_VERIFY([&] {
      const auto latest = window_->simulation().latest();
      return latest && !latest->running && dock().story().lastTime() == latest->time;
    }());
  }
};

void TestStoryExport::storyOfASelectedBallGrowsWithTheRun() {
  throwTheBall();
  selectBalls({0});
  dock().show();
  dock().raise();
  dock().setQuantity(BallStoryDock::Quantity::Height);
  runUntil(1.0, 21);
  QTRY_COMPARE(dock().seriesCount(), 1);
  QTRY_VERIFY(dock().seriesPoints(0).size() > 20);
  QTRY_COMPARE(dock().seriesPoints(0).last().x(), *dock().story().lastTime());  // caught up
  const QList<QPointF> points = dock().seriesPoints(0);
  for (qsizetype i = 1; i < points.size(); ++i) QVERIFY(points[i].x() > points[i - 1].x());
  // Thrown up from resting on the floor: it rises above its start, and comes down again.
  double highest = 0.0;
  for (const QPointF& point : points) highest = std::max(highest, point.y());
  QVERIFY2(highest > 1.0, qPrintable(QString::number(highest)));
  const carom::ui::BallStory::Sample first = dock().story().samples(0).front();
  QCOMPARE(points.first().y(), first.position.y());  // gravity along -y: height is y
  // The trail and the velocity arrow in the view.
  QCOMPARE(view().trails().size(), std::size_t(1));
  QVERIFY(view().trails()[0].points.size() > 20);
  QCOMPARE(view().trails()[0].points.back(), dock().story().samples(0).back().position);
  QCOMPARE(view().velocityArrows().size(), std::size_t(1));
  const auto& [base, tip] = view().velocityArrows()[0];
  QCOMPARE(base, dock().story().samples(0).back().position);
  QVERIFY((tip - base).norm() > 0.0);
  // Speed and energy from the same samples: an elastic ball keeps its energy.
  dock().setQuantity(BallStoryDock::Quantity::Energy);
  const QList<QPointF> energy = dock().seriesPoints(0);
  QCOMPARE(energy.size(), points.size());
  const double mass = document().scene().balls[0].mass;
  const double start = 0.5 * mass * 20.0 + mass * 9.81 * 0.5;  // thrown from the floor
  for (const QPointF& point : energy) QVERIFY(std::abs(point.y() - start) < 1e-6 * start);
  dock().setQuantity(BallStoryDock::Quantity::Speed);
  QCOMPARE(dock().seriesPoints(0).first().y(), first.velocity.norm());
}

void TestStoryExport::newlySelectedBallsStartFromThen() {
  addBalls(1);
  selectBalls({0});
  // The edit restarted the run: the story of a ball selected now starts with the new start's
  // first frame, which a slow machine (a sanitizer's) may show only after Run was pressed. A
  // user sees the scene before pressing Run.
  QTRY_VERIFY(!dock().story().samples(0).empty());
  runUntil(0.5);
  selectBalls({0, 1});
  runUntil(1.0);
  const auto& first = dock().story().samples(0);
  const auto& second = dock().story().samples(1);
  QVERIFY(first.front().time < 0.1);
  QVERIFY(second.front().time > 0.5);
  QCOMPARE(second.back().time, first.back().time);
  QTRY_COMPARE(dock().seriesCount(), 2);
  selectBalls({1});  // ball 0 leaves the story
  QCOMPARE(dock().seriesCount(), 1);
  QVERIFY(dock().story().samples(0).empty());
}

void TestStoryExport::manySelectedBallsAreCapped() {
  QVERIFY(dock().note().contains("Select balls"));
  addBalls(11);
  std::vector<int> all;
  for (int i = 0; i < 12; ++i) all.push_back(i);
  selectBalls(all);
  QCOMPARE(int(dock().story().watched().size()), BallStoryDock::kMaxBalls);
  QCOMPARE(dock().seriesCount(), BallStoryDock::kMaxBalls);
  QVERIFY2(dock().note().contains("first 8 of 12"), qPrintable(dock().note()));
}

void TestStoryExport::showTimeMovesTheCursorAndEndsTheTrail() {
  throwTheBall();
  selectBalls({0});
  runUntil(2.0);
  const double end = *dock().story().lastTime();
  QCOMPARE(dock().shownTime(), end);
  QTRY_COMPARE(dock().cursorTime(), end);
  dock().showTime(1.0);
  QCOMPARE(dock().cursorTime(), 1.0);
  const auto state = dock().story().stateAt(0, 1.0);
  QVERIFY(state && state->time <= 1.0 && state->time > 0.9);
  QCOMPARE(view().trails()[0].points.back(), state->position);
  QCOMPARE(view().velocityArrows()[0].first, state->position);
  // Resumed from the rewound moment: the story after it is gone.
  dock().truncateAfter(1.0);
  QCOMPARE(dock().story().samples(0).back().time, state->time);
  QVERIFY(dock().seriesPoints(0).last().x() <= 1.0);
  dock().showLatest();
  QCOMPARE(dock().shownTime(), 1.0);
}

void TestStoryExport::resetRestartsTheStory() {
  throwTheBall();
  selectBalls({0});
  runUntil(1.0);
  QVERIFY(!view().trails().empty());
  QAction* reset = nullptr;
  for (QAction* action : window_->findChildren<QAction*>())
    if (action->shortcut() == QKeySequence(Qt::Key_R)) reset = action;
  QVERIFY(reset);
  reset->trigger();
  QTRY_COMPARE(dock().story().lastTime().value_or(-1.0), 0.0);
  QCOMPARE(dock().story().samples(0).size(), std::size_t(1));
  QVERIFY(view().trails().empty());
  QVERIFY(view().velocityArrows().empty());  // at the start the editor's handle shows it
  QTRY_COMPARE(dock().seriesPoints(0).size(), 1);
  // Running again tells the story afresh.
  runUntil(0.5);
  QCOMPARE(dock().story().samples(0).front().time, 0.0);
  QVERIFY(!view().trails().empty());
  // A new scene starts it over as well.
  window_->openScene(carom::testing::floorScene(), {}, "again");
  QTRY_VERIFY(dock().story().samples(0).size() <= 1);
}

// An edit restarts the simulation from the edited scene: the story forgets the run before at
// once, and goes on from the new start.
void TestStoryExport::anEditRestartsTheStory() {
  throwTheBall();
  selectBalls({0});
  runUntil(1.0);
  carom::Scene edited = document().scene();
  edited.balls[0].color = "#00ff00";
  QVERIFY(carom::testing::applyEdit(document(), edited, "green").isEmpty());
  QVERIFY(dock().story().samples(0).empty());
  QVERIFY(view().trails().empty());
  QTRY_COMPARE(dock().story().samples(0).size(), std::size_t(1));
  QCOMPARE(dock().story().samples(0).front().time, 0.0);
  QCOMPARE(dock().story().samples(0).front().position, edited.balls[0].position);
}

void TestStoryExport::dockIsInTheViewMenu() {
  QMenu* viewMenu = nullptr;
  for (QAction* action : window_->menuBar()->actions())
    if (action->menu() && action->text().remove('&') == "View") viewMenu = action->menu();
  QVERIFY(viewMenu);
  QAction* toggle = dock().toggleViewAction();
  QVERIFY(viewMenu->actions().contains(toggle));
  QCOMPARE(toggle->text(), QString("Ball Story"));
  QVERIFY(toggle->isChecked());
  toggle->trigger();
  QVERIFY(!toggle->isChecked());
  QVERIFY(!dock().isVisible());
}

void TestStoryExport::exportWritesTheChosenSize() {
  QTemporaryDir folder;
  const QString file = folder.filePath("view.png");
  const QSize size(640, 360);
  QVERIFY(view().size() != size);
  QCOMPARE(imageExport(*window_)->write(file, size), QString());
  const QImage image(file);
  QCOMPARE(image.size(), size);
  // The red ball where the view's camera, at the picture's aspect ratio, puts it.
  carom::render::Camera camera = view().camera();
  camera.setAspectRatio(640.0 / 360.0);
  const QPointF ndc = camera.projectToNdc(document().scene().balls[0].position);
  const QPoint centre(int(0.5 * (ndc.x() + 1.0) * size.width()),
                      int(0.5 * (1.0 - ndc.y()) * size.height()));
  QVERIFY(image.rect().contains(centre));
  const QColor seen = image.pixelColor(centre);
  QVERIFY2(seen.red() > 120 && seen.red() > seen.green() + 60 && seen.red() > seen.blue() + 60,
           qPrintable(seen.name()));
  // The same camera, not stretched: the ball's red runs across and down the picture in the
  // proportions it has in the view, scaled by the heights (the vertical field of view is kept).
  const auto extent = [](const QImage& picture, QPoint centre) {
    const auto isRed = [&](QPoint p) {
      const QColor c = picture.pixelColor(p);
      return c.red() > 90 && c.red() > c.green() + 50 && c.red() > c.blue() + 50;
    };
    QSizeF red;
    for (int x = 0; x < picture.width(); ++x) red.rwidth() += isRed(QPoint(x, centre.y()));
    for (int y = 0; y < picture.height(); ++y) red.rheight() += isRed(QPoint(centre.x(), y));
    return red;
  };
  const QImage shown = view().grabFramebuffer();
  const QSizeF inView = extent(shown, (view().project(document().scene().balls[0].position) *
                                       (shown.width() / double(view().width())))
                                          .toPoint());
  const QSizeF inPicture = extent(image, centre);
  const double scale = double(size.height()) / shown.height();
  const QString sizes = QString("view %1x%2, picture %3x%4, scale %5")
                            .arg(inView.width())
                            .arg(inView.height())
                            .arg(inPicture.width())
                            .arg(inPicture.height())
                            .arg(scale);
  QVERIFY2(inView.width() > 10 && inView.height() > 10, qPrintable(sizes));
  QVERIFY2(std::abs(inPicture.width() - scale * inView.width()) <= 0.15 * inPicture.width() + 2,
           qPrintable(sizes));
  QVERIFY2(std::abs(inPicture.height() - scale * inView.height()) <= 0.15 * inPicture.height() + 2,
           qPrintable(sizes));
}

// With the floor selected, the view shows its normal's handle in the selection's colour and the
// floor tinted by it; the exported image, at the view's own size, shows neither: it is the
// picture of the scene with nothing selected.
void TestStoryExport::exportLeavesOutTheEditorsMarks() {
  const auto isHandle = [](const QColor& c) {
    return c.red() > 225 && std::abs(c.green() - 140) < 30 && c.blue() < 60;
  };
  const auto handlePixels = [&](const QImage& image) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) count += isHandle(image.pixelColor(x, y));
    return count;
  };
  const QSize size = view().size() * view().devicePixelRatio();
  const Vec3 onFloor(2.0, 0.0, 1.0);
  const auto floorPixel = [&](const QImage& image) {
    return image.pixelColor((view().project(onFloor) * view().devicePixelRatioF()).toPoint());
  };
  const QColor unselectedFloor = floorPixel(view().grabFramebuffer());

  document().setSelection({{ObjectKind::Plane, 0}});
  const QImage shown = view().grabFramebuffer();
  QVERIFY2(handlePixels(shown) > 20, qPrintable(QString::number(handlePixels(shown))));
  QVERIFY2(floorPixel(shown) != unselectedFloor, qPrintable(floorPixel(shown).name()));

  QTemporaryDir folder;
  const QString file = folder.filePath("selected.png");
  QCOMPARE(imageExport(*window_)->write(file, size), QString());
  const QImage exported(file);
  QCOMPARE(exported.size(), size);
  if (qEnvironmentVariableIsSet("CAROM_SCREENSHOT_DIR")) {
    shown.save(qEnvironmentVariable("CAROM_SCREENSHOT_DIR") + "/export-view.png");
    exported.save(qEnvironmentVariable("CAROM_SCREENSHOT_DIR") + "/export-image.png");
  }
  QCOMPARE(handlePixels(exported), 0);
  const QColor exportedFloor = floorPixel(exported);
  const int difference = std::abs(exportedFloor.red() - unselectedFloor.red()) +
                         std::abs(exportedFloor.green() - unselectedFloor.green()) +
                         std::abs(exportedFloor.blue() - unselectedFloor.blue());
  QVERIFY2(difference <= 6, qPrintable(exportedFloor.name() + " vs " + unselectedFloor.name()));
  // The view keeps its marks.
  QCOMPARE(document().selection().size(), std::size_t(1));
  QVERIFY(handlePixels(view().grabFramebuffer()) > 20);
}

void TestStoryExport::exportRefusesBadSizesAndUnwritablePaths() {
  QSize size(1, 1);
  using carom::ui::ImageSizeDialog;
  QVERIFY(ImageSizeDialog::readSize("15", "100", &size).contains("between 16 and 8192"));
  QVERIFY(ImageSizeDialog::readSize("100", "8193", &size).startsWith("Height"));
  QVERIFY(ImageSizeDialog::readSize("abc", "100", &size).contains("whole number"));
  QVERIFY(ImageSizeDialog::readSize("12.5", "100", &size).contains("whole number"));
  QCOMPARE(size, QSize(1, 1));  // unchanged by a refusal
  QVERIFY(ImageSizeDialog::readSize(" 640", "360", &size).isEmpty());
  QCOMPARE(size, QSize(640, 360));

  QTemporaryDir folder;
  const QString file = folder.filePath("big.png");
  QVERIFY(!imageExport(*window_)->write(file, QSize(9000, 100)).isEmpty());
  QVERIFY(!QFile::exists(file));
  const QString error = imageExport(*window_)->write("/nonexistent/folder/view.png", {64, 64});
  QVERIFY2(error.startsWith("Could not write"), qPrintable(error));
}

void TestStoryExport::exportImageMenuAsksSizeThenFile() {
  QTemporaryDir folder;
  const QString typed = folder.filePath("chosen");
  QString refusal;
  QSize suggested;
  carom::testing::ModalAnswerer<carom::ui::ImageSizeDialog> sizeAnswer(
      [&](carom::ui::ImageSizeDialog* dialog) {
        auto* width = dialog->findChild<QLineEdit*>("imageWidth");
        auto* height = dialog->findChild<QLineEdit*>("imageHeight");
        suggested = QSize(width->text().toInt(), height->text().toInt());
        width->setText("0");
        dialog->accept();  // refused: stays open and says why
        refusal = dialog->error();
        width->setText("320");
        height->setText("200");
        dialog->accept();
      });
  carom::testing::ModalAnswerer<QFileDialog> fileAnswer([&](QFileDialog* dialog) {
    dialog->selectFile(typed);
    QMetaObject::invokeMethod(dialog, "accept");
  });
  QAction* exportAction = window_->findChild<QAction*>("exportImage");
  QVERIFY(exportAction);
  QCOMPARE(exportAction->text(), QString("Export &Image…"));
  exportAction->trigger();
  QTRY_VERIFY(sizeAnswer.answered() && fileAnswer.answered());
  QCOMPARE(suggested, view().size() * view().devicePixelRatio());
  QVERIFY2(refusal.startsWith("Width: must be between"), qPrintable(refusal));
  QCOMPARE(QImage(typed + ".png").size(), QSize(320, 200));
  QVERIFY2(statusMessage(*window_).contains("320×200"), qPrintable(statusMessage(*window_)));
}

void TestStoryExport::screenshotOfTheMagicRoom() {
  QVERIFY(window_->openExample("magic-room", false));
  selectBalls({0, 3});
  dock().show();
  dock().raise();
  dock().setQuantity(BallStoryDock::Quantity::Height);
  runUntil(2.5);
  QTRY_VERIFY(dock().seriesCount() == 2 && dock().seriesPoints(1).size() > 20);
  QCOMPARE(view().trails().size(), std::size_t(2));
  QCOMPARE(view().velocityArrows().size(), std::size_t(2));
  // The trail's own colour, lighter than its ball, shows along its path in the view.
  QTRY_VERIFY(framesRendered(*window_) > 0);
  const QImage frame = view().grabFramebuffer();
  const QColor trail = view().trails()[0].color;
  const std::vector<Vec3>& path = view().trails()[0].points;
  int onTrail = 0;
  const double ratio = frame.width() / double(view().width());
  for (std::size_t i = 0; i + 1 < path.size(); i += 5) {
    const QPoint at = (view().project(0.5 * (path[i] + path[i + 1])) * ratio).toPoint();
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const QPoint p = at + QPoint(dx, dy);
        if (!frame.rect().contains(p)) continue;
        const QColor seen = frame.pixelColor(p);
        if (std::abs(seen.red() - trail.red()) + std::abs(seen.green() - trail.green()) +
                std::abs(seen.blue() - trail.blue()) <
            40) {
          ++onTrail;
          dx = dy = 2;  // one a point is enough
        }
      }
  }
  QVERIFY2(onTrail > 3, qPrintable(QString::number(onTrail)));
  const QString folder = qEnvironmentVariable("CAROM_SCREENSHOT_DIR");
  if (!folder.isEmpty()) {
    QDir().mkpath(folder);
    QVERIFY(window_->grab().save(QDir(folder).filePath("ball-story.png")));
    QVERIFY(imageExport(*window_)
                ->write(QDir(folder).filePath("ball-story-view.png"), QSize(1280, 720))
                .isEmpty());
  }
}

QTEST_MAIN(TestStoryExport)
#include "test_story_export.moc"
