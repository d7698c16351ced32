#include "widgets/common/logconsole.h"

#include <QApplication>
#include <QClipboard>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>

using db::widgets::LogConsole;

class TestLogConsole : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void linesAreTimestampedAndColouredByLevel()
    {
        LogConsole console;
        console.info(QStringLiteral("connected"));
        console.warning(QStringLiteral("slow answer"));
        console.error(QStringLiteral("connection lost"));
        QCOMPARE(console.lineCount(), 3);
        const QStringList lines = console.toPlainText().split(QLatin1Char('\n'));
        QVERIFY(QRegularExpression(QStringLiteral("^\\d\\d:\\d\\d:\\d\\d\\.\\d{3} connected$"))
                    .match(lines.at(0))
                    .hasMatch());
        const auto colourAtEnd = [&](int line) {
            const QTextBlock block = console.document()->findBlockByNumber(line);
            return block.begin().fragment().isValid()
                ? (--block.end()).fragment().charFormat().foreground().color()
                : QColor();
        };
        QVERIFY(colourAtEnd(1) != colourAtEnd(2));
        QVERIFY(colourAtEnd(0) != colourAtEnd(2));
    }

    // Lines quote device answers: an ESC sequence, CR, NUL, a bidi override or a paragraph
    // separator must neither act nor start a line of its own, and stays visible as an escape.
    void controlCharactersAreEscaped()
    {
        LogConsole console;
        console.warning(QString(u"< \x1b[2J\rOK\u202eKO\0\u0085 x\u2029ERROR y\nz"_qs));
        QCOMPARE(console.lineCount(), 1);
        const QString text = console.toPlainText();
        QVERIFY2(text.endsWith(u" < \\x1b[2J\\rOK\\u202eKO\\x00\\u0085 x\\u2029ERROR y\\nz"_qs),
                 qPrintable(text));
        console.info(u"Drehzahl 3000 min⁻¹, Temperatur 40 °C, Weg 12 µm, Größe"_qs);
        QVERIFY(console.toPlainText().endsWith(
            u" Drehzahl 3000 min⁻¹, Temperatur 40 °C, Weg 12 µm, Größe"_qs));
    }

    void oldLinesAreDropped()
    {
        LogConsole console;
        QCOMPARE(console.maxLines(), LogConsole::kDefaultMaxLines);
        console.setMaxLines(100);
        for (int i = 0; i < 250; ++i)
            console.info(QStringLiteral("line %1").arg(i));
        QCOMPARE(console.lineCount(), 100);
        QVERIFY(console.toPlainText().endsWith(QStringLiteral("line 249")));
        QVERIFY(!console.toPlainText().contains(QStringLiteral("line 149\n")));
    }

    void trafficIsKeptOnlyWhenAskedFor()
    {
        LogConsole console;
        console.traffic(QStringLiteral("> OR6041,0"));
        QCOMPARE(console.lineCount(), 0);
        console.setShowTraffic(true);
        console.traffic(QStringLiteral("> OR6041,0"));
        QCOMPARE(console.lineCount(), 1);
    }

    void clearAndCopy()
    {
        LogConsole console;
        console.info(QStringLiteral("hello"));
        console.copyAll();
        QVERIFY(QApplication::clipboard()->text().endsWith(QStringLiteral("hello")));
        console.clear();
        QCOMPARE(console.lineCount(), 0);
    }

    // Changes, events, problems, traffic and debug lines: the filter shows each kind apart, and
    // what is kept (all but traffic and debug) comes back when the filter widens again.
    void filterSeparatesChangesEventsTrafficAndDebug()
    {
        LogConsole console;
        console.info(QStringLiteral("connected"));
        console.change(QStringLiteral("write 6083:0 1000 -> 2000: ok"));
        console.warning(QStringLiteral("slow answer"));
        console.traffic(QStringLiteral("> OR6041,0")); // not shown: not kept
        console.debug(QStringLiteral("internal")); // not shown: not kept
        QCOMPARE(console.lineCount(), 3);

        console.setFilter(LogConsole::Filter::Changes);
        QCOMPARE(console.lineCount(), 1);
        QVERIFY(console.toPlainText().endsWith(QStringLiteral("write 6083:0 1000 -> 2000: ok")));
        console.setFilter(LogConsole::Filter::Problems);
        QCOMPARE(console.lineCount(), 1);
        QVERIFY(console.toPlainText().endsWith(QStringLiteral("slow answer")));

        console.setFilter(LogConsole::Filter::Everything);
        QCOMPARE(console.lineCount(), 3);
        console.traffic(QStringLiteral("> OR6041,0"));
        console.debug(QStringLiteral("internal"));
        QCOMPARE(console.lineCount(), 5);
        QVERIFY(console.showTraffic());
        console.setFilter(LogConsole::Filter::WithTraffic); // debug lines are dropped
        QCOMPARE(console.lineCount(), 4);
        QVERIFY(!console.toPlainText().contains(QStringLiteral("internal")));
        console.setFilter(LogConsole::Filter::Events); // and traffic too
        QCOMPARE(console.lineCount(), 3);
        console.setFilter(LogConsole::Filter::WithTraffic);
        QCOMPARE(console.lineCount(), 3);
    }

    void saveWritesTheShownLinesWithDateAndKind()
    {
        QTemporaryDir dir;
        LogConsole console;
        console.info(QStringLiteral("connected"));
        console.change(QStringLiteral("enable: ok"));
        console.setFilter(LogConsole::Filter::Changes);
        const QString path = dir.filePath(QStringLiteral("log.txt"));
        QCOMPARE(console.save(path), QString());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        QVERIFY2(
            QRegularExpression(
                QStringLiteral(
                    "^\\d{4}-\\d\\d-\\d\\d \\d\\d:\\d\\d:\\d\\d\\.\\d{3} CHANGE enable: ok\n$"))
                .match(text)
                .hasMatch(),
            qPrintable(text));
        // A folder is not a file: the cause, and the folder untouched.
        const QString problem = console.save(dir.path());
        QVERIFY(!problem.isEmpty());
        QVERIFY(problem.contains(QFileInfo(dir.path()).fileName()));
    }

    void clearForgetsHiddenLinesToo()
    {
        LogConsole console;
        console.info(QStringLiteral("connected"));
        console.setFilter(LogConsole::Filter::Changes);
        console.clear();
        console.setFilter(LogConsole::Filter::Events);
        QCOMPARE(console.lineCount(), 0);
    }

    void qtWarningsReachTheConsole()
    {
        LogConsole console;
        console.installMessageHandler();
        qWarning("something odd");
        QTRY_VERIFY(console.toPlainText().contains(QStringLiteral("something odd")));
    }
};

QTEST_MAIN(TestLogConsole)
#include "tst_logconsole.moc"
