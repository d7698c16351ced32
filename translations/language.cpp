#include "language.h"

#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace db::i18n {

namespace {

// The translators live as long as the application (QCoreApplication does not own them).
QList<QTranslator *> &installed()
{
    static QList<QTranslator *> translators;
    return translators;
}

bool loadInto(QCoreApplication &app, const QString &file, const QStringList &dirs)
{
    for (const QString &dir : dirs) {
        auto *translator = new QTranslator(&app);
        if (translator->load(file, dir) && QCoreApplication::installTranslator(translator)) {
            installed().append(translator);
            return true;
        }
        delete translator;
    }
    return false;
}

} // namespace

QStringList languages()
{
    return { QStringLiteral("en"), QStringLiteral("de") };
}

QString languageFromLocaleName(const QString &name)
{
    QString text = name.trimmed();
    if (text.isEmpty())
        return {};
    // language[_territory][.codeset][@modifier]: QLocale reads "de_DE", not the codeset.
    text = text.section(QLatin1Char('@'), 0, 0).section(QLatin1Char('.'), 0, 0);
    if (text == u"C" || text == u"POSIX" || text.isEmpty())
        return QStringLiteral("en");
    const QLocale locale(text);
    if (locale.language() == QLocale::C)
        return QStringLiteral("en"); // not a language QLocale knows
    const QString code = QLocale::languageToCode(locale.language());
    return languages().contains(code) ? code : QStringLiteral("en");
}

QString languageFromEnvironment()
{
    QString locale;
    for (const char *variable : { "LC_ALL", "LC_MESSAGES", "LANG" }) {
        locale = qEnvironmentVariable(variable);
        if (!locale.isEmpty())
            break;
    }
    const QString base = locale.section(QLatin1Char('.'), 0, 0);
    if (base == u"C" || base == u"POSIX")
        return QStringLiteral("en"); // GNU ignores LANGUAGE in the C locale
    const QString fromLocale = languageFromLocaleName(locale);
    // LANGUAGE=de:en: the first entry we have a translation for.
    const QStringList preferred =
        qEnvironmentVariable("LANGUAGE").split(QLatin1Char(':'), Qt::SkipEmptyParts);
    for (const QString &entry : preferred) {
        const QString language = languageFromLocaleName(entry);
        if (language == u"en" && !entry.startsWith(u"en"))
            continue; // a language we do not speak: try the next one
        return language;
    }
    return fromLocale.isEmpty() ? QStringLiteral("en") : fromLocale;
}

QString languageArgument(const QStringList &arguments)
{
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        const QString &a = arguments.at(i);
        if (a == u"--")
            break;
        if (a == u"--lang" && i + 1 < arguments.size())
            return arguments.at(i + 1);
        if (a.startsWith(u"--lang="))
            return a.mid(7);
    }
    return {};
}

QString chooseLanguage(const QString &explicitChoice)
{
    for (const QString &choice : { explicitChoice, qEnvironmentVariable("DRIVEBENCH_LANG") }) {
        if (!choice.trimmed().isEmpty())
            return languageFromLocaleName(choice);
    }
    return languageFromEnvironment();
}

bool installTranslations(QCoreApplication &app, const QString &language)
{
    for (QTranslator *translator : std::as_const(installed())) {
        QCoreApplication::removeTranslator(translator);
        delete translator;
    }
    installed().clear();
    if (language == u"en" || !languages().contains(language))
        return language == u"en";
    // share/drivebench/translations beside bin/ (installed) or app/ (build tree), so that a
    // corrected .qm can be tried without rebuilding; else the one built into the program.
    const QString shared = QCoreApplication::applicationDirPath()
        + QStringLiteral("/../share/drivebench/translations");
    const bool ours = loadInto(app, QStringLiteral("drivebench_") + language,
                               { QDir::cleanPath(shared), QStringLiteral(":/i18n") });
    loadInto(app, QStringLiteral("qtbase_") + language,
             { QLibraryInfo::path(QLibraryInfo::TranslationsPath) });
    return ours;
}

} // namespace db::i18n
