#include "ui/language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

namespace carom::ui {
namespace {

constexpr const char* kSettingsKey = "language";
// The translators installed last, found again by name to be replaced.
constexpr const char* kProgramTranslator = "caromTranslator";
constexpr const char* kQtTranslator = "qtTranslator";

void removeTranslator(QCoreApplication& app, const char* name) {
  if (auto* old = app.findChild<QTranslator*>(name, Qt::FindDirectChildrenOnly)) {
    QCoreApplication::removeTranslator(old);
    delete old;
  }
}

QTranslator* loadTranslator(QCoreApplication& app, const char* name, const QLocale& locale,
                            const QString& file, const QString& folder) {
  auto* translator = new QTranslator(&app);
  translator->setObjectName(name);
  if (translator->load(locale, file, "_", folder)) return translator;
  delete translator;
  return nullptr;
}

}  // namespace

QVector<Language> availableLanguages() {
  return {{QString(), QCoreApplication::translate("Language", "System Default")},
          {"en", "English"},
          {"ru", QString::fromUtf8("Русский")},
          {"de", "Deutsch"}};
}

QString chosenLanguage(const QStringList& arguments) {
  for (int i = 0; i < arguments.size(); ++i) {
    if (arguments[i] == "--lang" && i + 1 < arguments.size()) return arguments[i + 1];
    if (arguments[i].startsWith("--lang=")) return arguments[i].mid(7);
  }
  return QSettings().value(kSettingsKey).toString();
}

void saveLanguageChoice(const QString& code) {
  QSettings().setValue(kSettingsKey, code);
}

bool installTranslation(QCoreApplication& app, const QString& code) {
  removeTranslator(app, kProgramTranslator);
  removeTranslator(app, kQtTranslator);
  const QLocale wanted = code.isEmpty() ? QLocale::system() : QLocale(code);
  QTranslator* program = loadTranslator(app, kProgramTranslator, wanted, "carom", ":/i18n");
  // Without a translation the program speaks English, and its dates and Qt's buttons with it;
  // an English locale keeps its own country's formats.
  const QLocale spoken =
      program || wanted.language() == QLocale::English ? wanted : QLocale(QLocale::English);
  // English has a file too, for its plural forms alone.
  if (!program)
    program = loadTranslator(app, kProgramTranslator, QLocale(QLocale::English), "carom", ":/i18n");
  QLocale::setDefault(spoken);
  if (QTranslator* qt = loadTranslator(app, kQtTranslator, spoken, "qtbase",
                                       QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
    QCoreApplication::installTranslator(qt);
  if (program) QCoreApplication::installTranslator(program);
  return spoken.language() == wanted.language();
}

}  // namespace carom::ui
