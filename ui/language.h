#pragma once
// Which language the program speaks: --lang wins, then the choice saved from View > Language,
// else the system locale. Translations are built into the program under :/i18n.

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

// Installs the program's translation for `code` (empty: the system locale). Returns false when
// there is none for it, in which case the program speaks English.
bool installTranslation(QCoreApplication& app, const QString& code);

}  // namespace carom::ui
