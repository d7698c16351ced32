// drivebench-cli speaks the language of its environment: German for LANG=de_DE.UTF-8 (whether or
// not that locale is generated on the machine), English for LANG=C, and --lang / DRIVEBENCH_LANG
// choose explicitly. Checked on the error of a read from a port nobody listens on.
#include "clirun.h"
#include "englishtext.h"
#include "peers.h"

#include <QProcessEnvironment>
#include <QTest>

namespace {

db::test::CliRun runWith(const QStringList &args, const QList<QPair<QString, QString>> &vars,
                         const QString &program = QStringLiteral(DRIVEBENCH_CLI))
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : { "LC_ALL", "LC_MESSAGES", "LANG", "LANGUAGE", "DRIVEBENCH_LANG" })
        env.remove(QString::fromLatin1(name));
    for (const auto &[name, value] : vars)
        env.insert(name, value);
    QProcess p;
    p.setProcessEnvironment(env);
    QElapsedTimer clock;
    clock.start();
    p.start(program, args);
    p.waitForFinished(30000);
    return db::test::finishedRun(p, clock, 30000);
}

} // namespace

class TstCliLanguage : public QObject
{
    Q_OBJECT

private slots:
    void readErrorFollowsTheLanguage_data()
    {
        QTest::addColumn<QStringList>("extraArgs");
        QTest::addColumn<QStringList>("env"); // NAME=VALUE
        QTest::addColumn<bool>("german");
        QTest::newRow("LANG=de_DE.UTF-8")
            << QStringList() << QStringList { "LANG=de_DE.UTF-8" } << true;
        QTest::newRow("LANG=C") << QStringList() << QStringList { "LANG=C" } << false;
        QTest::newRow("nothing set") << QStringList() << QStringList() << false;
        QTest::newRow("LC_ALL=C beats LANG=de")
            << QStringList() << QStringList { "LANG=de_DE.UTF-8", "LC_ALL=C" } << false;
        QTest::newRow("LC_MESSAGES=de beats LANG=C")
            << QStringList() << QStringList { "LANG=C", "LC_MESSAGES=de_AT.UTF-8" } << true;
        QTest::newRow("--lang de")
            << QStringList { "--lang", "de" } << QStringList { "LANG=C" } << true;
        QTest::newRow("--lang=en")
            << QStringList { "--lang=en" } << QStringList { "LANG=de_DE.UTF-8" } << false;
        QTest::newRow("DRIVEBENCH_LANG=de")
            << QStringList() << QStringList { "LANG=C", "DRIVEBENCH_LANG=de" } << true;
    }
    void readErrorFollowsTheLanguage()
    {
        QFETCH(QStringList, extraArgs);
        QFETCH(QStringList, env);
        QFETCH(bool, german);
        const quint16 port = db::test::closedLoopbackPort();
        QVERIFY(port != 0);
        QList<QPair<QString, QString>> vars;
        for (const QString &v : env)
            vars.append({ v.section(u'=', 0, 0), v.section(u'=', 1) });
        const QString address = QStringLiteral("127.0.0.1:%1").arg(port);
        const auto run = runWith(extraArgs
                                     + QStringList { QStringLiteral("read"),
                                                     QStringLiteral("refgo://") + address,
                                                     QStringLiteral("6041:0") },
                                 vars);
        QCOMPARE(run.exitCode, 3); // connection
        const QString expected = german
            ? QStringLiteral("drivebench-cli: Verbindung abgelehnt: %1 hat die Verbindung "
                             "abgelehnt (an diesem Port lauscht niemand)\n")
                  .arg(address)
            : QStringLiteral("drivebench-cli: connection refused: %1 refused the connection "
                             "(nothing listens on that port)\n")
                  .arg(address);
        QCOMPARE(run.err, expected);
    }

    // Every usage error of the command line tool and the simulator is German for LANG=de: none
    // reads as an English sentence.
    void usageErrorsInGerman_data()
    {
        QTest::addColumn<QString>("program");
        QTest::addColumn<QStringList>("args");
        const QString cli = QStringLiteral(DRIVEBENCH_CLI);
        const QString sim = QStringLiteral(DRIVEBENCH_SIM);
        for (const char *command :
             { "read",     "write",  "refgo",     "scan",   "nmt",     "lss",  "pdo",
               "nm17x",    "dcf",    "eds-check", "backup", "restore", "diff", "dump",
               "morse",    "enable", "disable",   "reset",  "home",    "move", "jog",
               "velocity", "halt",   "stop",      "travel", "record",  "bogus" })
            QTest::newRow(command) << cli << QStringList { QString::fromLatin1(command) };
        QTest::newRow("nmt bad") << cli
                                 << QStringList { "nmt", "canopen+slcan://127.0.0.1:1?node=5",
                                                  "jump" };
        QTest::newRow("move bad") << cli
                                  << QStringList { "move", "refgo://127.0.0.1:1", "--abs", "x" };
        QTest::newRow("record no obj")
            << cli << QStringList { "record", "refgo://127.0.0.1:1", "--duration", "1" };
        QTest::newRow("sim no device") << sim << QStringList();
        QTest::newRow("sim bogus") << sim << QStringList { "bogus" };
        QTest::newRow("sim movingcap") << sim << QStringList { "movingcap" };
        QTest::newRow("sim movingcap port")
            << sim << QStringList { "movingcap", "--refgo-port", "x" };
        QTest::newRow("sim movingcap set")
            << sim << QStringList { "movingcap", "--refgo-port", "0", "--set", "zz" };
        QTest::newRow("sim canopen") << sim << QStringList { "canopen" };
        QTest::newRow("sim nm17x") << sim << QStringList { "nm17x" };
        QTest::newRow("sim acu") << sim << QStringList { "acu" };
        QTest::newRow("sim acu fail")
            << sim << QStringList { "acu", "--vabus-port", "0", "--fail", "x" };
        QTest::newRow("sim acu slave")
            << sim << QStringList { "acu", "--vabus-port", "0", "--slave", "99" };
    }
    void usageErrorsInGerman()
    {
        QFETCH(QString, program);
        QFETCH(QStringList, args);
        const auto run =
            runWith(args, { { QStringLiteral("LANG"), QStringLiteral("de_DE.UTF-8") } }, program);
        QVERIFY2(run.exitCode == 2, qPrintable(run.err));
        QVERIFY(!run.err.trimmed().isEmpty());
        for (const QString &line : run.err.split(u'\n', Qt::SkipEmptyParts))
            QVERIFY2(!db::test::readsAsEnglish(line), qPrintable(line));
    }

    // The help is translated too, and an unknown --lang is a usage error.
    void helpAndBadLanguage()
    {
        const auto help = runWith({ QStringLiteral("--help") },
                                  { { QStringLiteral("LANG"), QStringLiteral("de_DE.UTF-8") } });
        QCOMPARE(help.exitCode, 0);
        QVERIFY2(help.out.contains(QStringLiteral("Zeitlimit je Anfrage in ms")),
                 qPrintable(help.out));
        QVERIFY2(help.out.contains(QStringLiteral("ein Objekt lesen, z. B. read")),
                 qPrintable(help.out));
        const auto bad = runWith(
            { QStringLiteral("--lang"), QStringLiteral("fr"), QStringLiteral("list-protocols") },
            {});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains(QStringLiteral("--lang")), qPrintable(bad.err));
    }
};

QTEST_GUILESS_MAIN(TstCliLanguage)
#include "tst_cli_language.moc"
