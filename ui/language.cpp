#include "language.h"

#include <QCoreApplication>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

namespace carom::ui {
namespace {

constexpr const char* kSettingsKey = "language";

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
  auto* translator = new QTranslator(&app);
  const QLocale locale = code.isEmpty() ? QLocale() : QLocale(code);
  if (!translator->load(locale, "carom", "_", ":/i18n")) {
    delete translator;
    return false;
  }
  app.installTranslator(translator);
  return true;
}

}  // namespace carom::ui
