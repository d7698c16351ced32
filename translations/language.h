#pragma once

#include <QString>
#include <QStringList>

class QCoreApplication;

namespace db::i18n {

// The languages the programs speak: "en" (the source texts) and "de".
QStringList languages();

// "de_DE.UTF-8", "de_AT@euro", "de" -> "de"; "C", "POSIX", "en_GB.UTF-8" -> "en"; a language
// without a translation -> "en"; "" -> "" (says nothing). Parsed as text, so a locale that is not
// generated on this machine still chooses the language.
QString languageFromLocaleName(const QString &name);

// The language of messages as POSIX and GNU gettext choose it: LC_ALL, else LC_MESSAGES, else
// LANG names the locale; unless that is "C"/"POSIX", GNU's LANGUAGE list (de:en) comes first.
// "en" when nothing is set.
QString languageFromEnvironment();

// The value of "--lang X" or "--lang=X" in a program's arguments (before a lone "--"), or "".
// Read before QCommandLineParser runs, because the help texts themselves are translated.
QString languageArgument(const QStringList &arguments);

// The language a program uses: the first non-empty of explicit (--lang, a setting), the
// DRIVEBENCH_LANG environment variable and the environment's locale (languageFromEnvironment()).
// Unknown languages give "en".
QString chooseLanguage(const QString &explicitChoice = {});

// Installs the translators for language on the application: ours (drivebench_LANG.qm, from
// share/drivebench/translations beside the program, else the copy built into the program) and
// Qt's own (qtbase_LANG.qm, when Debian's qt6-translations-l10n is installed). "en" installs
// none. Returns false when our translation for language cannot be loaded.
bool installTranslations(QCoreApplication &app, const QString &language);

} // namespace db::i18n
