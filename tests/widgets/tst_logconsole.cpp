#include "widgets/logconsole.h"

#include <QApplication>
#include <QClipboard>
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
