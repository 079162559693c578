#pragma once
// Which language the program speaks: --lang wins, then the choice saved from View > Language,
// else the system locale. Translations are built into the program under :/i18n; Qt's own
// (dialog buttons, file and colour dialogs) come from Qt's translations folder.

#include <QString>
#include <QStringList>
#include <QVector>

class QCoreApplication;

namespace carom::ui {

struct Language {
  QString code;        // "ru", "de", "en"; empty: follow the system
  QString nativeName;  // shown in the menu in its own language
};

QVector<Language> availableLanguages();

// The code from "--lang CODE" or "--lang=CODE" in `arguments`, else the saved choice, else empty.
QString chosenLanguage(const QStringList& arguments);
void saveLanguageChoice(const QString& code);

// Speaks `code` (empty: the system locale) from now on: replaces the program's and Qt's
// translations installed before, which sends every widget a LanguageChange, and makes the
// language's locale the default one, so dates and numbers follow it. Returns false when the
// program has no translation for it, in which case it speaks English with English dates.
bool installTranslation(QCoreApplication& app, const QString& code);

}  // namespace carom::ui
