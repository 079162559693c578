// The program in German and Russian as a user meets it: the language changed live from
// View > Language, Qt's own dialogs in the same language, dates in its format, the toolbar whole
// at the default width in every language, and the Help menu's windows.
//
// With CAROM_SCREENSHOT_DIR set, pictures of the window and of the dialogs are saved there.

#include "sim/io/scene_file.h"
#include "tests/editor_fixture.h"
#include "ui/dialogs/help_dialogs.h"
#include "ui/dialogs/image_export.h"
#include "ui/dialogs/video_export.h"
#include "ui/docks/ball_story_dock.h"
#include "ui/docks/energy_plot.h"
#include "ui/editor/number_text.h"
#include "ui/editor/outline_dock.h"
#include "ui/editor/properties_dock.h"
#include "ui/editor/scene_recovery.h"
#include "ui/language.h"
#include "ui/status_readout.h"
#include "ui/watch_menu.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QGraphicsTextItem>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QToolBar>
#include <QUndoView>

#include <algorithm>
#include <cmath>

using carom::editor::ObjectKind;

namespace {

// Saves `widget`'s picture as NAME.png in CAROM_SCREENSHOT_DIR, when that is set.
void keepPicture(QWidget* widget, const QString& name) {
  const QString folder = qEnvironmentVariable("CAROM_SCREENSHOT_DIR");
  if (folder.isEmpty()) return;
  QDir().mkpath(folder);
  QVERIFY(widget->grab().save(QDir(folder).filePath(name + ".png")));
}

// Whether `edit` shows its whole text from the first character on: the left end of its text
// area is the text's start and the right end is past its last character.
bool showsWholeText(QLineEdit* edit) {
  const QRect inner = edit->contentsRect();
  const int y = inner.center().y();
  return edit->cursorPositionAt(QPoint(inner.left() + 1, y)) == 0 &&
         edit->cursorPositionAt(QPoint(inner.right() - 1, y)) == edit->text().size();
}

// A chart's texts as drawn: its tick labels below and left of the plot area, and the rest.
struct ChartTexts {
  QStringList bottomTicks, leftTicks, others;
};

ChartTexts chartTexts(QChartView* view) {
  ChartTexts texts;
  const QRectF plot = view->chart()->mapRectToScene(view->chart()->plotArea());
  QList<QGraphicsTextItem*> items;
  for (QGraphicsItem* item : view->scene()->items())
    if (auto* text = dynamic_cast<QGraphicsTextItem*>(item); text && text->isVisible())
      items << text;
  // Left to right, top to bottom.
  std::sort(items.begin(), items.end(), [](QGraphicsTextItem* a, QGraphicsTextItem* b) {
    const QPointF pa = a->sceneBoundingRect().center(), pb = b->sceneBoundingRect().center();
    return pa.x() != pb.x() ? pa.x() < pb.x() : pa.y() > pb.y();
  });
  for (QGraphicsTextItem* item : items) {
    const QString text = item->toPlainText();
    // Written in the language's format or not, a number is a tick label.
    bool number = false;
    carom::editor::numberLocale().toDouble(text, &number);
    if (!number) QLocale::c().toDouble(text, &number);
    const QRectF box = item->sceneBoundingRect();
    if (number && box.top() >= plot.bottom())
      texts.bottomTicks << text;
    else if (number && box.right() <= plot.left())
      texts.leftTicks << text;
    else
      texts.others << text;
  }
  return texts;
}

// Whether `labels`, read in the language's format, step evenly: each says its tick's value.
bool stepEvenly(const QStringList& labels) {
  if (labels.size() < 3) return false;
  QList<double> values;
  for (const QString& label : labels) values << carom::editor::numberLocale().toDouble(label);
  std::sort(values.begin(), values.end());
  const double step = values[1] - values[0];
  for (qsizetype i = 2; i < values.size(); ++i)
    if (std::abs(values[i] - values[i - 1] - step) > 1e-9 * std::abs(step)) return false;
  return step > 0.0;
}

}  // namespace

class TestLanguage : public carom::testing::EditorFixture {
  Q_OBJECT

 private slots:
  void init() { openWindow(); }
  void cleanup() {
    window_.reset();
    carom::ui::installTranslation(*QCoreApplication::instance(), "en");
  }

  void switchesLanguageLiveFromTheMenu();
  void qtDialogsSpeakTheLanguage_data();
  void qtDialogsSpeakTheLanguage();
  void recoveryDateFollowsTheLanguage_data();
  void recoveryDateFollowsTheLanguage();
  void toolbarFitsAtTheDefaultWidth_data();
  void toolbarFitsAtTheDefaultWidth();
  void examplesAreListedByTitle();
  void keyboardAndMouseReference();
  void aboutBox();
  void userGuide();
  void countsTakeTheirPluralForms_data();
  void countsTakeTheirPluralForms();
  void exampleTitleAndToolbarMessagesFollowTheLanguage();
  void ballStoryAndExportImageFollowTheLanguage_data();
  void ballStoryAndExportImageFollowTheLanguage();
  void propertiesShowSignedValuesWholeAtTheDefaultSize_data();
  void propertiesShowSignedValuesWholeAtTheDefaultSize();
  void exponentsAreLowerCase_data();
  void exponentsAreLowerCase();
  void numbersOfARunAreReadableInTheLanguage_data();
  void numbersOfARunAreReadableInTheLanguage();

 private:
  QMenu* menu(const QString& title) {
    for (QAction* action : window_->menuBar()->actions())
      if (action->menu() && action->text().remove('&') == title) return action->menu();
    qWarning("no menu %s", qPrintable(title));
    return nullptr;
  }
  QStringList menuTitles() {
    QStringList titles;
    for (QAction* action : window_->menuBar()->actions()) titles << action->text().remove('&');
    return titles;
  }
  // Chooses a language as a user does, through View > Language.
  void chooseLanguage(const QString& code) {
    QAction* action = window_->findChild<QAction*>("language:" + code);
    QVERIFY(action);
    action->trigger();
    QVERIFY(action->isChecked());
  }
  // The text of the label standing before the properties dock's field `name` (a vector's three
  // fields share one).
  QString labelOf(const QString& name) {
    auto* field = window_->propertiesDock()->findChild<QLineEdit*>(name);
    for (QLabel* label : window_->propertiesDock()->findChildren<QLabel*>())
      if (label->buddy() == field || label->buddy() == field->parentWidget()) return label->text();
    return {};
  }
  // The quit prompt's buttons, read as it is up and then cancelled.
  QStringList quitPromptButtons(const QString& picture) {
    QStringList texts;
    carom::testing::ModalAnswerer<QMessageBox> answer([&](QMessageBox* box) {
      for (auto button : {QMessageBox::Save, QMessageBox::Discard, QMessageBox::Cancel})
        texts << box->button(button)->text().remove('&');
      keepPicture(box, picture);
      box->button(QMessageBox::Cancel)->click();
    });
    window_->close();
    [&] { QTRY_VERIFY(answer.answered()); }();
    return texts;
  }
  void makeModified() {
    carom::Scene edited = document().scene();
    edited.balls[0].mass = 2.0;
    QVERIFY(carom::testing::applyEdit(document(), edited, "heavier").isEmpty());
  }
};

void TestLanguage::switchesLanguageLiveFromTheMenu() {
  document().setSelection({});
  QCOMPARE(menuTitles().first(), QString("File"));
  QVERIFY(menuTitles().contains("Help") && menuTitles().contains("Tools"));
  makeModified();
  auto* undoView = window_->findChild<QUndoView*>();
  QVERIFY(undoView);

  chooseLanguage("de");
  // The events that carry the change are posted: the texts follow on the next turn.
  QTRY_COMPARE(menuTitles().first(), QString("Datei"));
  QVERIFY2(menuTitles().contains("Hilfe"), qPrintable(menuTitles().join(", ")));
  QCOMPARE(window_->findChild<QAction*>("run")->text().remove('&'), QString("Starten"));
  QCOMPARE(watchMenu(*window_)->title().remove('&'), QString("Überwachung"));
  QCOMPARE(window_->findChild<QAction*>("watchTolerances")->text().remove('&'),
           QString("Toleranzen…"));
  QCOMPARE(window_->findChild<QAction*>("toolAddBall")->text(), QString("Kugel hinzufügen"));
  QCOMPARE(window_->findChild<QAction*>("toolAddBall")->toolTip(), QString("Kugel hinzufügen (B)"));
  QCOMPARE(window_->propertiesDock()->windowTitle(), QString("Eigenschaften"));
  QCOMPARE(window_->outlineDock()->windowTitle(), QString("Übersicht"));
  QCOMPARE(window_->propertiesDock()->toggleViewAction()->text(), QString("Eigenschaften"));
  // The properties dock's labels, heading and numbers, in German and its number format.
  QCOMPARE(labelOf("timeStep"), QString("Zeitschritt"));
  QCOMPARE(labelOf("gravity.x"), QString("Schwerkraft"));
  QCOMPARE(window_->propertiesDock()->heading(), QString("Welt (nichts ausgewählt)"));
  auto* gravityY = window_->propertiesDock()->findChild<QLineEdit*>("gravity.y");
  QCOMPARE(gravityY->text(), QString("-9,81"));
  // The outline's groups, the toolbar's boxes and the status line.
  QCOMPARE(window_->outlineDock()->model()->groupIndex(ObjectKind::Ball).data().toString(),
           QString("Kugeln (1)"));
  QCOMPARE(window_->findChild<QDoubleSpinBox*>("gravityY")->text(), QString("-9,81"));
  // Edit > Undo names the last command after the language's own word.
  const QList<QAction*> edit = menu("Bearbeiten")->actions();
  QVERIFY2(edit.first()->text().startsWith("&Rückgängig"), qPrintable(edit.first()->text()));
  // Qt's own texts come from Qt's translation: the quit prompt's standard buttons.
  QCOMPARE(quitPromptButtons("quit-de-live"), (QStringList{"Speichern", "Verwerfen", "Abbrechen"}));
  QVERIFY(window_->isVisible());

  chooseLanguage("en");
  QTRY_COMPARE(menuTitles().first(), QString("File"));
  QCOMPARE(window_->findChild<QAction*>("run")->text().remove('&'), QString("Run"));
  QCOMPARE(watchMenu(*window_)->title().remove('&'), QString("Watch"));
  QCOMPARE(window_->propertiesDock()->windowTitle(), QString("Properties"));
  QCOMPARE(labelOf("timeStep"), QString("Time step"));
  QCOMPARE(gravityY->text(), QString("-9.81"));
  QCOMPARE(window_->outlineDock()->model()->groupIndex(ObjectKind::Ball).data().toString(),
           QString("Balls (1)"));
  QCOMPARE(quitPromptButtons("quit-en-live"), (QStringList{"Save", "Discard", "Cancel"}));
  // The choice is kept for the next start.
  QCOMPARE(carom::ui::chosenLanguage({}), QString("en"));
}

void TestLanguage::qtDialogsSpeakTheLanguage_data() {
  QTest::addColumn<QString>("code");
  QTest::addColumn<QStringList>("buttons");
  QTest::addColumn<QString>("emptyHistory");
  QTest::newRow("de") << "de" << QStringList{"Speichern", "Verwerfen", "Abbrechen"} << "<leer>";
  QTest::newRow("ru") << "ru" << QStringList{"Сохранить", "Отклонить", "Отмена"} << "<пусто>";
}

// Qt's own texts (standard buttons, the file dialog, the undo view) are Qt's translation's, for
// a window opened in the language as after a start with --lang.
void TestLanguage::qtDialogsSpeakTheLanguage() {
  QFETCH(QString, code);
  QFETCH(QStringList, buttons);
  QFETCH(QString, emptyHistory);
  window_.reset();
  QVERIFY(carom::ui::installTranslation(*QCoreApplication::instance(), code));
  openWindow();
  keepPicture(window_.get(), "window-" + code);
  makeModified();
  QCOMPARE(quitPromptButtons("quit-" + code), buttons);
  QCOMPARE(window_->findChild<QUndoView*>()->emptyLabel(), emptyHistory);
  // The file dialog's buttons.
  QString cancel;
  carom::testing::ModalAnswerer<QFileDialog> answer([&](QFileDialog* dialog) {
    for (QPushButton* button : dialog->findChildren<QPushButton*>())
      if (button->isVisible()) cancel += button->text().remove('&') + ";";
    keepPicture(dialog, "save-as-" + code);
    dialog->reject();
  });
  QVERIFY(!window_->saveAs());
  QVERIFY(answer.answered());
  QVERIFY2(cancel.contains(buttons[2]), qPrintable(cancel));
}

void TestLanguage::recoveryDateFollowsTheLanguage_data() {
  QTest::addColumn<QString>("code");
  QTest::addColumn<QString>("recover");
  QTest::newRow("de") << "de"
                      << "Wiederherstellen";
  QTest::newRow("ru") << "ru"
                      << "Восстановить";
}

void TestLanguage::recoveryDateFollowsTheLanguage() {
  QFETCH(QString, code);
  QFETCH(QString, recover);
  // What a session that crashed leaves: a scene without a live lock, saved at a known time, and
  // nothing else to offer.
  QDir folder(carom::editor::SceneRecovery::folder());
  for (const QString& old : folder.entryList({"*.carom"}, QDir::Files)) folder.remove(old);
  const QString scene = QDir(carom::editor::SceneRecovery::folder()).filePath("crashed-1.carom");
  QVERIFY(carom::io::saveSceneFile(carom::testing::floorScene(), scene, nullptr));
  const QDateTime saved(QDate(2026, 11, 23), QTime(17, 5));
  {
    QFile file(scene);
    QVERIFY(file.open(QIODevice::ReadWrite));
    QVERIFY(file.setFileTime(saved, QFileDevice::FileModificationTime));
  }
  QVERIFY(carom::ui::installTranslation(*QCoreApplication::instance(), code));
  // As at a start: the language is in place before the question is asked.
  QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
  QString text;
  QString button;
  carom::testing::ModalAnswerer<QMessageBox> answer([&](QMessageBox* box) {
    text = box->text();
    button = box->button(QMessageBox::Yes)->text().remove('&');
    keepPicture(box, "recovery-" + code);
    box->button(QMessageBox::No)->click();  // discards the copy
  });
  QVERIFY(!window_->offerRecovery());
  QVERIFY(answer.answered());
  QCOMPARE(button, recover);
  const QString date = QLocale(code).toString(saved, QLocale::ShortFormat);
  QVERIFY2(text.contains(date), qPrintable(text + " / " + date));
  QVERIFY2(!text.contains(QLocale(QLocale::English).toString(saved, QLocale::ShortFormat)),
           qPrintable(text));
  QVERIFY(!QFile::exists(scene));
}

void TestLanguage::toolbarFitsAtTheDefaultWidth_data() {
  QTest::addColumn<QString>("code");
  QTest::newRow("en") << "en";
  QTest::newRow("de") << "de";
  QTest::newRow("ru") << "ru";
}

// At 1280 x 800 no toolbar control goes into an overflow menu, and the view keeps two thirds of
// the window's width beside the docks (as wide as three signed values a row need them).
void TestLanguage::toolbarFitsAtTheDefaultWidth() {
  QFETCH(QString, code);
  window_.reset();
  carom::ui::installTranslation(*QCoreApplication::instance(), code);
  openWindow();
  window_->resize(1280, 800);
  QTRY_COMPARE(window_->width(), 1280);
  const QList<QToolBar*> bars = window_->findChildren<QToolBar*>();
  QCOMPARE(bars.size(), 3);
  // As the window opens, and with method auto and its accuracy field shown.
  auto* method = window_->findChild<QComboBox*>("worldMethod");
  QVERIFY(method);
  for (const bool automatic : {false, true}) {
    if (automatic) {
      method->setCurrentIndex(method->count() - 1);
      QTRY_VERIFY(window_->findChild<QWidget*>("accuracy")->isVisible());
    }
    for (QToolBar* bar : bars) {
      QVERIFY(bar->isVisible());
      for (QAction* action : bar->actions()) {
        if (action->isSeparator() || !action->isVisible()) continue;  // hidden on purpose
        QWidget* widget = bar->widgetForAction(action);
        QVERIFY(widget);
        QTRY_VERIFY2(widget->isVisible() && bar->rect().contains(widget->geometry()),
                     qPrintable(bar->objectName() + ": " + action->text()));
      }
      // Qt's "»" button, shown only when something does not fit.
      for (QWidget* child : bar->findChildren<QWidget*>("qt_toolbar_ext_button"))
        QVERIFY2(!child->isVisible(), qPrintable(bar->objectName()));
    }
  }
  QVERIFY2(
      window_->view()->width() * 3 > window_->width() * 2 && window_->view()->height() > 450,
      qPrintable(QString("%1x%2").arg(window_->view()->width()).arg(window_->view()->height())));
  keepPicture(window_.get(), "toolbar-" + code);
}

void TestLanguage::examplesAreListedByTitle() {
  QMenu* examples = menu("Examples");
  QVERIFY(examples);
  QStringList titles;
  for (QAction* action : examples->actions()) titles << action->text();
  QCOMPARE(titles, (QStringList{"Magic room", "Galton board", "Gas box", "Inelastic pile",
                                "Newton's cradle", "Staircase", "Marble run"}));
  // Every bundled scene is there.
  QCOMPARE(QDir(":/scenes").entryList({"*.json"}).size(), titles.size());
  window_->findChild<QAction*>("example:newtons-cradle")->trigger();
  QCOMPARE(document().scene().balls.size(), std::size_t{5});
  QVERIFY2(window_->windowTitle().startsWith("Newton's cradle"),
           qPrintable(window_->windowTitle()));
  // Save As offers the file's name, not the title.
  QStringList suggested;
  carom::testing::ModalAnswerer<QFileDialog> answer([&](QFileDialog* dialog) {
    suggested = dialog->selectedFiles();
    dialog->reject();
  });
  QVERIFY(!window_->saveAs());
  QVERIFY(answer.answered());
  QCOMPARE(suggested.size(), 1);
  QVERIFY2(suggested.first().endsWith("/newtons-cradle.carom"), qPrintable(suggested.first()));

  chooseLanguage("ru");
  QTRY_COMPARE(examples->actions().at(4)->text(), QString("Колыбель Ньютона"));
  QCOMPARE(examples->actions().last()->text(), QString("Трасса для шариков"));
  window_->findChild<QAction*>("example:galton-board")->trigger();
  QVERIFY2(window_->windowTitle().startsWith("Доска Гальтона"), qPrintable(window_->windowTitle()));
}

void TestLanguage::keyboardAndMouseReference() {
  window_->findChild<QAction*>("keyboardHelp")->trigger();
  auto* help = window_->findChild<carom::ui::HelpWindow*>();
  QVERIFY(help && help->page() == carom::ui::HelpWindow::Page::KeyboardAndMouse);
  QTRY_VERIFY(help->isVisible());
  QCOMPARE(help->windowTitle(), QString("Keyboard and Mouse"));
  const QString text = help->text();
  // A few of every kind: keys of the window, the tools, the view, the edit menu, the mouse.
  for (const char* expected :
       {"Space", "Run or pause the simulation", "F11, F1", "Home", "Add Cylinder", "Ctrl+Z",
        "Ctrl+Shift+Z, Ctrl+Y", "Ctrl+D", "Middle drag", "Alt+drag from a ball",
        "Double-click (in the outline)", "X, Y or Z held while dragging", "F3"})
    QVERIFY2(text.contains(expected), expected);
  keepPicture(help, "keyboard-en");

  chooseLanguage("de");
  QTRY_COMPARE(help->windowTitle(), QString("Tastatur und Maus"));
  // Key names from Qt's translation, descriptions from Carom's.
  QVERIFY2(help->text().contains("Strg+Z") && help->text().contains("Leertaste"),
           qPrintable(help->text()));
  QVERIFY(help->text().contains("Simulation starten oder anhalten"));
  keepPicture(help, "keyboard-de");
}

void TestLanguage::aboutBox() {
  QString title, text;
  carom::testing::ModalAnswerer<QMessageBox> answer([&](QMessageBox* box) {
    title = box->windowTitle();
    text = box->text();
    keepPicture(box, "about");
    box->accept();
  });
  window_->findChild<QAction*>("about")->trigger();
  QVERIFY(answer.answered());
  QCOMPARE(title, QString("About Carom"));
  QVERIFY2(text.contains(QString("Carom %1").arg(QCoreApplication::applicationVersion())),
           qPrintable(text));
  QVERIFY2(text.contains(QString("Qt version %1").arg(qVersion())), qPrintable(text));
  QVERIFY(text.contains("MIT"));
}

// Help > User Guide shows the page written for users (docs/user-guide.md), not the developers'
// notes; its link opens those notes in the same window, and Back returns to the guide.
void TestLanguage::userGuide() {
  window_->findChild<QAction*>("userGuide")->trigger();
  auto* guide = window_->findChild<carom::ui::HelpWindow*>();
  QVERIFY(guide && guide->page() == carom::ui::HelpWindow::Page::UserGuide);
  QTRY_VERIFY(guide->isVisible());
  QCOMPARE(guide->windowTitle(), QString("User Guide"));
  // Rendered: the guide's headings without their marks, and none of the notes' file table.
  for (const char* heading :
       {"Carom User Guide", "What is in a scene", "The world's settings",
        "Methods: which one to choose", "What to expect of the energy", "auto: let Carom choose",
        "What else to expect", "Your hands on the running world", "For developers"})
    QVERIFY2(guide->text().contains(heading), heading);
  QVERIFY(!guide->text().contains("## "));
  QVERIFY(!guide->text().contains("Where things are"));
  auto* browser = guide->findChild<QTextBrowser*>();
  QVERIFY(browser && browser->isReadOnly());
  auto* back = guide->findChild<QPushButton*>("back");
  QVERIFY(back && !back->isEnabled());
  keepPicture(guide, "user-guide");

  // A click on the link, as a user makes it.
  const QTextCursor link = browser->document()->find("physics notes");
  QVERIFY(!link.isNull() && link.charFormat().isAnchor());
  browser->setTextCursor(link);
  browser->ensureCursorVisible();
  QTextCursor middle = link;
  middle.setPosition((link.selectionStart() + link.selectionEnd()) / 2);
  const QPoint at = browser->cursorRect(middle).center();
  QTest::mouseClick(browser->viewport(), Qt::LeftButton, {}, at);
  QTRY_VERIFY2(guide->text().contains("Carom's physics"), qPrintable(guide->text().left(200)));
  QVERIFY(guide->text().contains("Where things are"));
  QVERIFY(!guide->text().contains("## "));
  QVERIFY(back->isEnabled());
  keepPicture(guide, "physics-notes");

  back->click();
  QTRY_VERIFY(guide->text().contains("What is in a scene"));
  QVERIFY(!back->isEnabled());
}

// "1 ball", "2 balls"; in Russian "1 шар", "2 шара", "5 шаров": the status line's count and the
// properties dock's heading.
void TestLanguage::countsTakeTheirPluralForms_data() {
  QTest::addColumn<QString>("code");
  QTest::addColumn<int>("balls");
  QTest::addColumn<QString>("readout");
  QTest::addColumn<QString>("heading");
  QTest::newRow("en 1") << "en" << 1 << " 1 ball "
                        << "";
  QTest::newRow("en 2") << "en" << 2 << " 2 balls "
                        << "3 objects selected";
  QTest::newRow("ru 1") << "ru" << 1 << QString::fromUtf8(" 1 шар ") << "";
  QTest::newRow("ru 2") << "ru" << 2 << QString::fromUtf8(" 2 шара ")
                        << QString::fromUtf8("Выбрано 3 объекта");
  QTest::newRow("ru 5") << "ru" << 5 << QString::fromUtf8(" 5 шаров ")
                        << QString::fromUtf8("Выбрано 6 объектов");
}

void TestLanguage::countsTakeTheirPluralForms() {
  QFETCH(QString, code);
  QFETCH(int, balls);
  QFETCH(QString, readout);
  QFETCH(QString, heading);
  chooseLanguage(code);
  carom::Scene scene = carom::testing::floorScene();
  while (static_cast<int>(scene.balls.size()) < balls) {
    carom::Ball ball = scene.balls.back();
    ball.position.x() += 1.1;
    scene.balls.push_back(ball);
  }
  window_->openScene(scene, {});
  window_->setRunning(true);
  QTRY_VERIFY2(statusText(*window_).contains(readout), qPrintable(statusText(*window_)));
  window_->setRunning(false);
  if (heading.isEmpty()) return;
  carom::editor::Selection all;
  for (int i = 0; i < balls; ++i) all.push_back({ObjectKind::Ball, i});
  all.push_back({ObjectKind::Plane, 0});
  document().setSelection(all);
  // Balls and a plane: the heading counts objects.
  const auto* label = window_->propertiesDock()->findChild<QLabel*>("propertiesHeading");
  QVERIFY(label);
  QCOMPARE(label->text(), heading);
}

// An open example's title, and a toolbar box's name in its refusal, follow a live change.
void TestLanguage::exampleTitleAndToolbarMessagesFollowTheLanguage() {
  window_->findChild<QAction*>("example:magic-room")->trigger();
  QVERIFY(window_->windowTitle().startsWith("Magic room"));
  chooseLanguage("de");
  QTRY_VERIFY2(window_->windowTitle().startsWith("Magischer Raum"),
               qPrintable(window_->windowTitle()));
  auto* timeStep = window_->findChild<QDoubleSpinBox*>("timeStep");
  QVERIFY(timeStep);
  QTest::mouseClick(timeStep, Qt::LeftButton);
  QTest::keyClick(timeStep, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClick(timeStep, Qt::Key_Backspace);
  QTest::keyClicks(timeStep, "2e9");
  QTest::keyClick(timeStep, Qt::Key_Return);
  QVERIFY2(statusMessage(*window_).startsWith("Zeitschritt"), qPrintable(statusMessage(*window_)));
}

void TestLanguage::ballStoryAndExportImageFollowTheLanguage_data() {
  QTest::addColumn<QString>("code");
  QTest::addColumn<QString>("viewMenu");
  QTest::addColumn<QString>("fileMenu");
  QTest::addColumn<QString>("dockTitle");
  QTest::addColumn<QString>("quantity");
  QTest::addColumn<QString>("exportImage");
  QTest::addColumn<QString>("badWidth");
  QTest::addColumn<QString>("exportVideo");
  QTest::addColumn<QString>("badEnd");
  QTest::newRow("de") << "de"
                      << "Ansicht"
                      << "Datei"
                      << "Kugelverlauf"
                      << "Höhe (m)"
                      << "Bild exportieren…"
                      << "Breite: muss zwischen 16 und 8192 Pixeln liegen (erhalten: 9000)"
                      << "Video exportieren…"
                      << "Ende: der Lauf ist nur bis 2 s aufgezeichnet (erhalten: 2,5 s)";
  QTest::newRow("ru") << "ru"
                      << "Вид"
                      << "Файл"
                      << "История шара"
                      << "Высота (м)"
                      << "Экспорт изображения…"
                      << "Ширина: должно быть от 16 до 8192 пикселей (получено 9000)"
                      << "Экспорт видео…"
                      << "Конец: прогон записан только до 2 с (получено 2,5 с)";
}

// The Ball story dock is listed in the View menu under its title in the language, and File >
// Export Image and Export Video and their refusals speak it too.
void TestLanguage::ballStoryAndExportImageFollowTheLanguage() {
  QFETCH(QString, code);
  chooseLanguage(code);
  carom::ui::BallStoryDock* dock = ballStoryDock(*window_);
  QFETCH(QString, dockTitle);
  // The events that carry the change are posted: the texts follow on the next turn.
  QTRY_COMPARE(dock->windowTitle(), dockTitle);
  QFETCH(QString, viewMenu);
  QMenu* view = menu(viewMenu);
  QVERIFY(view);
  QVERIFY(view->actions().contains(dock->toggleViewAction()));
  QCOMPARE(dock->toggleViewAction()->text(), dockTitle);
  QFETCH(QString, quantity);
  QCOMPARE(dock->findChild<QComboBox*>("storyQuantity")->currentText(), quantity);
  QVERIFY(!dock->note().contains("Select"));
  QFETCH(QString, fileMenu);
  QFETCH(QString, exportImage);
  QAction* exportAction = window_->findChild<QAction*>("exportImage");
  QVERIFY(menu(fileMenu)->actions().contains(exportAction));
  QCOMPARE(exportAction->text().remove('&'), exportImage);
  QFETCH(QString, badWidth);
  QSize size;
  QCOMPARE(carom::ui::ImageSizeDialog::readSize("9000", "100", &size), badWidth);
  // File > Export Video, and a refusal with a number in the language's format.
  QFETCH(QString, exportVideo);
  QAction* videoAction = window_->findChild<QAction*>("exportVideo");
  QVERIFY(menu(fileMenu)->actions().contains(videoAction));
  QCOMPARE(videoAction->text().remove('&'), exportVideo);
  QFETCH(QString, badEnd);
  carom::ui::VideoSettings video;
  video.from = 0.0;
  video.to = 2.5;
  video.size = QSize(320, 240);
  QCOMPARE(carom::ui::VideoExport::check(video, 2.0, true), badEnd);
}

void TestLanguage::propertiesShowSignedValuesWholeAtTheDefaultSize_data() {
  QTest::addColumn<QString>("code");
  QTest::newRow("en") << "en";
  QTest::newRow("de") << "de";
  QTest::newRow("ru") << "ru";
}

// Issue 34: in a window of the default size (1280 x 800) the Properties dock showed "642395"
// for -0.642395, the sign and the first digit scrolled out of the field. Every vector's three
// fields show six-digit values with their signs whole, in every language.
void TestLanguage::propertiesShowSignedValuesWholeAtTheDefaultSize() {
  QFETCH(QString, code);
  window_.reset();
  QVERIFY(carom::ui::installTranslation(*QCoreApplication::instance(), code));
  carom::Scene scene = carom::testing::floorScene();
  const carom::Vec3 signedValues(-0.642395, -1.59698, -0.253112);
  scene.balls[0].velocity = signedValues;
  carom::Plane plane;
  plane.point = carom::Vec3(3.5, 0, 0);
  plane.normal = carom::Vec3(-0.96741, -0.253112, -0.642395);
  scene.planes.push_back(plane);
  carom::Box box;
  box.center = carom::Vec3(-0.642395, -1.59698, -2.71828);
  box.halfExtents = carom::Vec3(0.5, 0.253112, 0.5);
  box.rotation = carom::Rotation{carom::Vec3(-0.577350, -0.577350, -0.577350), -33.3333};
  scene.boxes.push_back(box);
  scene.world.gravity = carom::Vec3(-0.642395, -9.81, -0.253112);
  // The window at the size it opens with, not the fixture's.
  window_ = std::make_unique<carom::ui::MainWindow>();
  window_->openScene(scene, {}, "signs");
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  QCOMPARE(window_->size(), QSize(1280, 800));
  const int planeIndex = int(scene.planes.size()) - 1;
  struct Case {
    QString picture;
    carom::editor::Selection selection;
    QStringList fields;
  };
  const std::vector<Case> cases = {
      {"ball", {{ObjectKind::Ball, 0}}, {"velocity.x", "velocity.y", "velocity.z"}},
      {"plane", {{ObjectKind::Plane, planeIndex}}, {"normal.x", "normal.y", "normal.z"}},
      {"box",
       {{ObjectKind::Box, 0}},
       {"center.x", "center.y", "center.z", "rotationAxis.x", "rotationAxis.y", "rotationAxis.z",
        "rotationDegrees"}},
      {"world", {}, {"gravity.x", "gravity.y", "gravity.z"}}};
  for (const auto& [picture, selection, names] : cases) {
    document().setSelection(selection);
    for (const QString& name : names) {
      auto* field = window_->propertiesDock()->findChild<QLineEdit*>(name);
      QVERIFY2(field && field->isVisible(), qPrintable(name));
      QVERIFY2(field->text().startsWith(QLocale().negativeSign()),
               qPrintable(name + ": " + field->text()));
      // Once the rows the selection shows are laid out at their height.
      QTRY_VERIFY2(field->height() >= field->minimumSizeHint().height() && showsWholeText(field),
                   qPrintable(QString("%1: \"%2\" in %3 pixels, cursor at %4")
                                  .arg(name, field->text())
                                  .arg(field->width())
                                  .arg(field->cursorPosition())));
    }
    keepPicture(window_->propertiesDock(), QString("properties-%1-%2").arg(picture, code));
  }
  // The view keeps two thirds of the window's width.
  QVERIFY2(window_->view()->width() * 3 > window_->width() * 2,
           qPrintable(QString::number(window_->view()->width())));
  keepPicture(window_.get(), "window-signs-" + code);
}

void TestLanguage::exponentsAreLowerCase_data() {
  QTest::addColumn<QString>("code");
  QTest::addColumn<QString>("typed");
  QTest::addColumn<QString>("message");
  QTest::newRow("en") << "en"
                      << "-2.5e12"
                      << "Gravity x: must be between -1e+12 and 1e+12 (got -2.5e+12)";
  QTest::newRow("de")
      << "de"
      << "-2,5e12"
      << "Schwerkraft x: muss zwischen -1e+12 und 1e+12 liegen (erhalten: -2,5e+12)";
  QTest::newRow("ru") << "ru"
                      << "-2,5e12"
                      << "Гравитация x: должно быть от -1e+12 до 1e+12 (получено -2,5e+12)";
}

// Issue 34: the locales' own exponent, a capital E, showed "-1E+12", which reads as a digit at a
// glance: the toolbar, the properties and the refusals write "-1e+12", in each language's own
// decimal separator, and a value typed with it is read.
void TestLanguage::exponentsAreLowerCase() {
  QFETCH(QString, code);
  QFETCH(QString, typed);
  QFETCH(QString, message);
  window_.reset();
  QVERIFY(carom::ui::installTranslation(*QCoreApplication::instance(), code));
  openWindow();
  document().setSelection({});
  carom::Scene edited = document().scene();
  edited.world.gravity.x() = -1e12;
  QVERIFY(carom::testing::applyEdit(document(), edited, "far").isEmpty());
  auto* toolbarX = window_->findChild<QDoubleSpinBox*>("gravityX");
  QVERIFY(toolbarX);
  QCOMPARE(toolbarX->text(), QString("-1e+12"));
  auto* propertiesX = window_->propertiesDock()->findChild<QLineEdit*>("gravity.x");
  QCOMPARE(propertiesX->text(), QString("-1e+12"));
  QCOMPARE(propertiesX->toolTip().section(' ', -1), QString("-1e+12"));
  QTest::mouseClick(toolbarX, Qt::LeftButton);
  QTest::keyClick(toolbarX, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(toolbarX, typed);
  QTest::keyClick(toolbarX, Qt::Key_Return);
  QCOMPARE(statusMessage(*window_), message);
  // Within the range, the same separator is read.
  QTest::keyClick(toolbarX, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(toolbarX, QString(typed).replace("12", "11"));
  QTest::keyClick(toolbarX, Qt::Key_Return);
  QCOMPARE(document().scene().world.gravity.x(), -2.5e11);
  QCOMPARE(toolbarX->text(), QString(typed).replace("e12", "e+11"));
}

void TestLanguage::numbersOfARunAreReadableInTheLanguage_data() {
  QTest::addColumn<QString>("code");
  QTest::newRow("en") << "en";
  QTest::newRow("de") << "de";
  QTest::newRow("ru") << "ru";
}

// Issue 34: in Russian the status line said "t = 23.367 s" beside the timeline's "t = 23,367 с"
// and the plots' ticks had points; the Energy plot's ticks at 0.25 and 0.75 read "0.3" and
// "0.8"; and the Ball Story's plot, at the size it opens with, showed every tick label and its
// axis title as "...". Every number follows the language's format, and both plots show whole
// labels that say their ticks' values, at the window's default size.
void TestLanguage::numbersOfARunAreReadableInTheLanguage() {
  QFETCH(QString, code);
  window_.reset();
  QVERIFY(carom::ui::installTranslation(*QCoreApplication::instance(), code));
  openWindow();
  window_->resize(1280, 800);
  const QString point = carom::editor::numberLocale().decimalPoint();
  const QString otherPoint = point == "." ? "," : ".";
  auto* energyView = energyPlot(*window_)->findChild<QChartView*>();
  QVERIFY(energyView);
  // Before the run the time axis spans 0 to 1 s: "0.0 0.3 0.5 0.8 1.0" did not step evenly.
  QTRY_VERIFY(!chartTexts(energyView).bottomTicks.isEmpty());
  QVERIFY2(stepEvenly(chartTexts(energyView).bottomTicks),
           qPrintable(chartTexts(energyView).bottomTicks.join(" ")));
  document().setSelection({{ObjectKind::Ball, 0}});
  carom::Scene bouncing = document().scene();
  bouncing.balls[0].position.y() = 2.0;
  QVERIFY(carom::testing::applyEdit(document(), bouncing, "higher").isEmpty());
  QAction* run = window_->findChild<QAction*>("run");
  run->trigger();
  auto* status = window_->findChild<carom::ui::StatusReadout*>();
  auto* timeline = window_->findChild<QLabel*>("timelineLabel");
  QVERIFY(status && timeline);
  // t = 1.234: the run's time, in each line.
  const QRegularExpression time(
      QString(R"(t = (\d+)%1(\d{3}) )").arg(QRegularExpression::escape(point)));
  QTRY_VERIFY_WITH_TIMEOUT(
      time.match(status->text()).hasMatch() && time.match(status->text()).captured(1).toInt() >= 1,
      20000);
  run->trigger();
  QTRY_COMPARE(time.match(status->text()).captured(0), time.match(timeline->text()).captured(0));
  QVERIFY2(!QRegularExpression(QString(R"(\d%1\d)").arg(QRegularExpression::escape(otherPoint)))
                .match(status->text())
                .hasMatch(),
           qPrintable(status->text()));
  // Both plots: no text cut short, ticks that say their values, in the language's format.
  auto* storyView = ballStoryDock(*window_)->findChild<QChartView*>();
  QVERIFY(storyView);
  for (const auto& [dockName, view] :
       {std::pair{"energyDock", energyView}, std::pair{"ballStoryDock", storyView}}) {
    auto* dock = window_->findChild<QDockWidget*>(dockName);
    QVERIFY(dock);
    dock->raise();
    keepPicture(dock, QString("%1-%2").arg(dockName, code));
    QTRY_VERIFY2(view->isVisible() && chartTexts(view).leftTicks.size() >= 3,
                 qPrintable(chartTexts(view).others.join(" | ")));
    const ChartTexts texts = chartTexts(view);
    const QString all = (texts.bottomTicks + texts.leftTicks + texts.others).join(" | ");
    QVERIFY2(!all.contains("...") && !all.contains(QChar(0x2026)), qPrintable(all));
    QVERIFY2(stepEvenly(texts.bottomTicks), qPrintable(texts.bottomTicks.join(" ")));
    QVERIFY2(stepEvenly(texts.leftTicks), qPrintable(texts.leftTicks.join(" ")));
    QVERIFY2(!all.contains(QRegularExpression(
                 QString(R"(\d%1\d)").arg(QRegularExpression::escape(otherPoint)))),
             qPrintable(all));
  }
}

QTEST_MAIN(TestLanguage)
#include "test_language.moc"
