// The translations: every string the sources mark for translation is in translations/*.ts with a
// finished translation and nothing stale is left there (lupdate run on a copy), translations keep
// the placeholders of their source, the German .qm built into the programs loads, and the language
// follows --lang, DRIVEBENCH_LANG and the POSIX locale variables as text.
#include "core/objectdef.h"
#include "translations/language.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

namespace {

struct Message
{
    QString context;
    QString source;
    QString translation; // numerus forms joined by '\n'
    QString type; // "", "unfinished", "vanished", "obsolete"
};

QList<Message> readTs(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = file.errorString();
        return {};
    }
    QList<Message> messages;
    QXmlStreamReader xml(&file);
    QString context;
    Message current;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        if (xml.name() == u"name") {
            context = xml.readElementText();
        } else if (xml.name() == u"message") {
            current = Message { context, {}, {}, {} };
        } else if (xml.name() == u"source") {
            current.source = xml.readElementText();
        } else if (xml.name() == u"translation") {
            current.type = xml.attributes().value(QStringLiteral("type")).toString();
            current.translation =
                xml.readElementText(QXmlStreamReader::IncludeChildElements).trimmed();
            messages.append(current);
        }
    }
    if (xml.hasError())
        *error = QStringLiteral("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return messages;
}

QStringList tsFiles()
{
    QStringList files;
    const QDir dir(QStringLiteral(DRIVEBENCH_SOURCE_DIR "/translations"));
    for (const QString &name : dir.entryList({ QStringLiteral("drivebench_*.ts") }, QDir::Files))
        files << dir.filePath(name);
    return files;
}

QSet<QString> placeholders(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("%(?:L?[1-9]|n)"));
    QSet<QString> found;
    for (const auto &match : re.globalMatch(text))
        found.insert(match.captured().remove(u'L'));
    return found;
}

} // namespace

class TstTranslations : public QObject
{
    Q_OBJECT

private slots:
    void tsFilesExist() { QVERIFY2(!tsFiles().isEmpty(), "no translations/drivebench_*.ts"); }

    // lupdate on a copy: strings new in the sources come out "unfinished", strings gone from
    // the sources "vanished"; both, and unfinished ones already in the file, fail. lupdate's
    // warnings about tr() it cannot place (the runtime would look in another context) fail too.
    void tsCompleteAndCurrent_data()
    {
        QTest::addColumn<QString>("ts");
        for (const QString &ts : tsFiles())
            QTest::newRow(qPrintable(QFileInfo(ts).fileName())) << ts;
    }
    void tsCompleteAndCurrent()
    {
        QFETCH(QString, ts);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString copy = dir.filePath(QFileInfo(ts).fileName());
        QVERIFY(QFile::copy(ts, copy));
        QProcess lupdate;
        lupdate.setWorkingDirectory(QStringLiteral(DRIVEBENCH_SOURCE_DIR));
        QStringList args { QStringLiteral("-recursive"), QStringLiteral("-extensions"),
                           QStringLiteral("cpp,h"), QStringLiteral("-locations"),
                           QStringLiteral("none") };
        args += QStringLiteral(DRIVEBENCH_TRANSLATED_DIRS).split(u',', Qt::SkipEmptyParts);
        args << QStringLiteral("-ts") << copy;
        lupdate.start(QStringLiteral(DRIVEBENCH_LUPDATE), args);
        QVERIFY2(lupdate.waitForFinished(60000), "lupdate did not finish within 60 s");
        const QString log =
            QString::fromUtf8(lupdate.readAllStandardOutput() + lupdate.readAllStandardError());
        QCOMPARE(lupdate.exitCode(), 0);

        QStringList problems;
        for (const QString &line : log.split(u'\n')) {
            if (line.contains(u"lacks Q_OBJECT") || line.contains(u"Cannot invoke tr()")
                || line.contains(u"Discarding unconsumed"))
                problems << QStringLiteral("lupdate: ") + line.trimmed();
        }
        QString error;
        const QList<Message> messages = readTs(copy, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(!messages.isEmpty());
        int unfinished = 0;
        int stale = 0;
        for (const Message &m : messages) {
            if (m.type == u"unfinished" || (m.type.isEmpty() && m.translation.isEmpty())) {
                ++unfinished;
                problems << QStringLiteral("not translated [%1] %2").arg(m.context, m.source);
            } else if (m.type == u"vanished" || m.type == u"obsolete") {
                ++stale;
                problems
                    << QStringLiteral("no longer in the sources [%1] %2").arg(m.context, m.source);
            }
        }
        if (!problems.isEmpty()) {
            const int shown = 40;
            QString text = QStringLiteral("%1 of %2 messages not translated, %3 stale (update with "
                                          "`ninja drivebench_lupdate`, then translate):\n")
                               .arg(unfinished)
                               .arg(messages.size())
                               .arg(stale);
            text += problems.mid(0, shown).join(u'\n');
            if (problems.size() > shown)
                text += QStringLiteral("\n... and %1 more").arg(problems.size() - shown);
            QFAIL(qPrintable(text));
        }
    }

    // "%1 of %2" must not lose or invent a placeholder in translation.
    void placeholdersKept()
    {
        QStringList problems;
        for (const QString &ts : tsFiles()) {
            QString error;
            for (const Message &m : readTs(ts, &error)) {
                if (m.translation.isEmpty())
                    continue;
                if (placeholders(m.source) != placeholders(m.translation))
                    problems
                        << QStringLiteral("[%1] %2 -> %3").arg(m.context, m.source, m.translation);
            }
            QVERIFY2(error.isEmpty(), qPrintable(error));
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(u'\n')));
    }

    void builtInGermanLoads()
    {
        QVERIFY(db::i18n::installTranslations(*QCoreApplication::instance(), QStringLiteral("de")));
        QCOMPARE(QCoreApplication::translate("db::Error", "timeout"),
                 QStringLiteral("Zeitüberschreitung"));
        QCOMPARE(db::textLanguage(), QStringLiteral("de")); // device texts follow: German names
        QVERIFY(db::i18n::installTranslations(*QCoreApplication::instance(), QStringLiteral("en")));
        QCOMPARE(QCoreApplication::translate("db::Error", "timeout"), QStringLiteral("timeout"));
        QCOMPARE(db::textLanguage(), QStringLiteral("en"));
    }

    void languageFromLocaleName_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("language");
        QTest::newRow("de_DE.UTF-8") << "de_DE.UTF-8"
                                     << "de";
        QTest::newRow("de_AT@euro") << "de_AT@euro"
                                    << "de";
        QTest::newRow("de_CH.utf8") << "de_CH.utf8"
                                    << "de";
        QTest::newRow("de") << "de"
                            << "de";
        QTest::newRow("en_GB.UTF-8") << "en_GB.UTF-8"
                                     << "en";
        QTest::newRow("C") << "C"
                           << "en";
        QTest::newRow("C.UTF-8") << "C.UTF-8"
                                 << "en";
        QTest::newRow("POSIX") << "POSIX"
                               << "en";
        QTest::newRow("fr_FR (no translation)") << "fr_FR.UTF-8"
                                                << "en";
        QTest::newRow("garbage") << "xx_YY"
                                 << "en";
        QTest::newRow("empty") << ""
                               << "";
    }
    void languageFromLocaleName()
    {
        QFETCH(QString, name);
        QFETCH(QString, language);
        QCOMPARE(db::i18n::languageFromLocaleName(name), language);
    }

    void languageFromEnvironment_data()
    {
        QTest::addColumn<QString>("lcAll");
        QTest::addColumn<QString>("lcMessages");
        QTest::addColumn<QString>("lang");
        QTest::addColumn<QString>("languageList");
        QTest::addColumn<QString>("language");
        QTest::newRow("nothing set") << ""
                                     << ""
                                     << ""
                                     << ""
                                     << "en";
        QTest::newRow("LANG de") << ""
                                 << ""
                                 << "de_DE.UTF-8"
                                 << ""
                                 << "de";
        QTest::newRow("LANG C") << ""
                                << ""
                                << "C"
                                << ""
                                << "en";
        QTest::newRow("LC_MESSAGES over LANG") << ""
                                               << "en_US.UTF-8"
                                               << "de_DE.UTF-8"
                                               << ""
                                               << "en";
        QTest::newRow("LC_ALL over both") << "de_DE.UTF-8"
                                          << "C"
                                          << "C"
                                          << ""
                                          << "de";
        QTest::newRow("LC_ALL C over LANG de") << "C"
                                               << ""
                                               << "de_DE.UTF-8"
                                               << ""
                                               << "en";
        QTest::newRow("LANGUAGE first") << ""
                                        << ""
                                        << "en_US.UTF-8"
                                        << "de:en"
                                        << "de";
        QTest::newRow("LANGUAGE skips unknown") << ""
                                                << ""
                                                << "en_US.UTF-8"
                                                << "fr:de"
                                                << "de";
        QTest::newRow("LANGUAGE ignored in C") << ""
                                               << ""
                                               << "C.UTF-8"
                                               << "de"
                                               << "en";
    }
    void languageFromEnvironment()
    {
        QFETCH(QString, lcAll);
        QFETCH(QString, lcMessages);
        QFETCH(QString, lang);
        QFETCH(QString, languageList);
        QFETCH(QString, language);
        const QList<QPair<const char *, QString>> vars { { "LC_ALL", lcAll },
                                                         { "LC_MESSAGES", lcMessages },
                                                         { "LANG", lang },
                                                         { "LANGUAGE", languageList } };
        QList<QPair<const char *, QByteArray>> saved;
        for (const auto &[name, value] : vars) {
            saved.append({ name, qgetenv(name) });
            if (value.isEmpty())
                qunsetenv(name);
            else
                qputenv(name, value.toUtf8());
        }
        const QString found = db::i18n::languageFromEnvironment();
        for (const auto &[name, value] : saved) {
            if (value.isEmpty())
                qunsetenv(name);
            else
                qputenv(name, value);
        }
        QCOMPARE(found, language);
    }

    void explicitChoice()
    {
        const QByteArray saved = qgetenv("DRIVEBENCH_LANG");
        qputenv("DRIVEBENCH_LANG", "de");
        QCOMPARE(db::i18n::chooseLanguage(), QStringLiteral("de"));
        QCOMPARE(db::i18n::chooseLanguage(QStringLiteral("en")), QStringLiteral("en"));
        qputenv("DRIVEBENCH_LANG", saved);
        const QStringList args { QStringLiteral("drivebench-cli"), QStringLiteral("--hex"),
                                 QStringLiteral("--lang"), QStringLiteral("de"),
                                 QStringLiteral("read") };
        QCOMPARE(db::i18n::languageArgument(args), QStringLiteral("de"));
        QCOMPARE(db::i18n::languageArgument({ QStringLiteral("x"), QStringLiteral("--lang=en") }),
                 QStringLiteral("en"));
        QCOMPARE(db::i18n::languageArgument(
                     { QStringLiteral("x"), QStringLiteral("--"), QStringLiteral("--lang=de") }),
                 QString());
    }
};

QTEST_GUILESS_MAIN(TstTranslations)
#include "tst_translations.moc"
