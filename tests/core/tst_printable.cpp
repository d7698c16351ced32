// printable(): text quoted from devices and files, escaped for terminals, consoles and reports.
#include "core/error.h"
#include "core/printable.h"
#include "parameters/parameterrunner.h"

#include <QTest>

using namespace db;

class TestPrintable : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void escapesText_data();
    void escapesText();
    void keepsLineFeedsWhenAsked();
    void escapesBytes_data();
    void escapesBytes();
    void isIdempotent_data();
    void isIdempotent();
    void completeUtf8Prefix_data();
    void completeUtf8Prefix();
    void errorMessagesAreEscaped();
    void restoreReportLinesStayLines();
};

void TestPrintable::escapesText_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");
    QTest::newRow("plain") << u"Position actual value"_qs << u"Position actual value"_qs;
    QTest::newRow("umlauts, micro, degree")
        << u"Größe Übertemperatur µm 90°"_qs << u"Größe Übertemperatur µm 90°"_qs;
    QTest::newRow("CJK and emoji") << u"驱动器 \U0001F527"_qs << u"驱动器 \U0001F527"_qs;
    QTest::newRow("clear screen") << u"name\x1b[2J\x1b[H"_qs << u"name\\x1b[2J\\x1b[H"_qs;
    QTest::newRow("CR fake OK") << u"4711\rOK        "_qs << u"4711\\rOK        "_qs;
    QTest::newRow("line feed") << u"a\nOK"_qs << u"a\\nOK"_qs;
    QTest::newRow("CRLF") << u"a\r\n"_qs << u"a\\r\\n"_qs;
    QTest::newRow("NUL") << QString(u"ab\0cd"_qs) << u"ab\\x00cd"_qs;
    QTest::newRow("BEL BS TAB") << u"\a\b\t"_qs << u"\\x07\\x08\\t"_qs;
    QTest::newRow("DEL") << u"x\x7fy"_qs << u"x\\x7fy"_qs;
    QTest::newRow("C1 CSI") << u"a\u009b2Jb"_qs << u"a\\u009b2Jb"_qs;
    QTest::newRow("C1 NEL, U+0080") << u"\u0085\u0080\u009f"_qs << u"\\u0085\\u0080\\u009f"_qs;
    QTest::newRow("right-to-left override") << u"abc\u202eKO"_qs << u"abc\\u202eKO"_qs;
    QTest::newRow("bidi embeddings and isolates")
        << u"\u202a\u202b\u202c\u202d\u2066\u2067\u2068\u2069"_qs
        << u"\\u202a\\u202b\\u202c\\u202d\\u2066\\u2067\\u2068\\u2069"_qs;
    QTest::newRow("paragraph separator") << u"a\u2029OK"_qs << u"a\\u2029OK"_qs;
    QTest::newRow("unpaired surrogate") << QString(QChar(0xD800)) + u"x"_qs << u"\\ud800x"_qs;
    QTest::newRow("backslash unchanged") << u"C:\\dir\\n"_qs << u"C:\\dir\\n"_qs;
    QTest::newRow("empty") << QString() << QString();
}

void TestPrintable::escapesText()
{
    QFETCH(QString, text);
    QFETCH(QString, expected);
    QCOMPARE(printable(text), expected);
    QCOMPARE(isPrintable(text), text == expected);
}

void TestPrintable::keepsLineFeedsWhenAsked()
{
    QCOMPARE(printable(u"line 1\nline 2\r\x1b[2J"_qs, LineBreaks::Keep),
             u"line 1\nline 2\\r\\x1b[2J"_qs);
    QVERIFY(isPrintable(u"a\nb"_qs, LineBreaks::Keep));
    QVERIFY(!isPrintable(u"a\nb"_qs));
}

void TestPrintable::escapesBytes_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("expected");
    QTest::newRow("ascii") << QByteArray("OR6041,0") << u"OR6041,0"_qs;
    QTest::newRow("utf-8 umlauts, micro, degree")
        << QByteArray("\xc3\xa4\xc3\xb6\xc3\xbc \xc2\xb5m 90\xc2\xb0") << u"äöü µm 90°"_qs;
    QTest::newRow("4-byte utf-8") << QByteArray("\xf0\x9f\x94\xa7") << u"\U0001F527"_qs;
    QTest::newRow("ESC") << QByteArray("\x1b[31mOK") << u"\\x1b[31mOK"_qs;
    QTest::newRow("NUL") << QByteArray("a\0b", 3) << u"a\\x00b"_qs;
    QTest::newRow("C1 as utf-8") << QByteArray("\xc2\x9b") << u"\\u009b"_qs;
    QTest::newRow("RLO as utf-8") << QByteArray("\xe2\x80\xae") << u"\\u202e"_qs;
    QTest::newRow("latin-1 byte") << QByteArray("Gr\xf6\xdf") << u"Gr\\xf6\\xdf"_qs;
    QTest::newRow("lone continuation") << QByteArray("\x80x") << u"\\x80x"_qs;
    QTest::newRow("overlong slash") << QByteArray("\xc0\xaf") << u"\\xc0\\xaf"_qs;
    QTest::newRow("overlong 3-byte") << QByteArray("\xe0\x80\xaf") << u"\\xe0\\x80\\xaf"_qs;
    QTest::newRow("utf-8 surrogate") << QByteArray("\xed\xa0\x80") << u"\\xed\\xa0\\x80"_qs;
    QTest::newRow("above U+10FFFF") << QByteArray("\xf4\x90\x80\x80") << u"\\xf4\\x90\\x80\\x80"_qs;
    QTest::newRow("truncated at end") << QByteArray("ab\xe2\x82") << u"ab\\xe2\\x82"_qs;
    QTest::newRow("truncated before ascii") << QByteArray("\xe2\x82x") << u"\\xe2\\x82x"_qs;
    QTest::newRow("0xff") << QByteArray("\xff") << u"\\xff"_qs;
}

void TestPrintable::escapesBytes()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QString, expected);
    QCOMPARE(printable(QByteArrayView(bytes)), expected);
}

void TestPrintable::isIdempotent_data()
{
    escapesText_data();
}

void TestPrintable::isIdempotent()
{
    QFETCH(QString, text);
    const QString once = printable(text);
    QCOMPARE(printable(once), once);
    QVERIFY(isPrintable(once));
}

void TestPrintable::completeUtf8Prefix_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<int>("prefix");
    QTest::newRow("empty") << QByteArray() << 0;
    QTest::newRow("ascii") << QByteArray("abc") << 3;
    QTest::newRow("complete 2-byte") << QByteArray("a\xc3\xa4") << 3;
    QTest::newRow("half of 2-byte") << QByteArray("a\xc3") << 1;
    QTest::newRow("2 of 3") << QByteArray("a\xe2\x82") << 1;
    QTest::newRow("3 of 4") << QByteArray("\xf0\x9f\x94") << 0;
    QTest::newRow("complete 4-byte") << QByteArray("\xf0\x9f\x94\xa7") << 4;
    QTest::newRow("invalid lead is not held") << QByteArray("a\xff") << 2;
    QTest::newRow("stray continuations") << QByteArray("a\x80\x80\x80\x80") << 5;
}

void TestPrintable::completeUtf8Prefix()
{
    QFETCH(QByteArray, bytes);
    QFETCH(int, prefix);
    QCOMPARE(db::completeUtf8Prefix(bytes), qsizetype(prefix));
}

void TestPrintable::errorMessagesAreEscaped()
{
    const Error e(Error::Kind::DeviceError, u"drive refused 'OR1008,0': \x1b[2J\rOK"_qs);
    QCOMPARE(e.message(), u"drive refused 'OR1008,0': \\x1b[2J\\rOK"_qs);
    const Error prefixed = e.prefixed(u"reading set\n\x1b]0;title\a.dbp"_qs);
    QCOMPARE(prefixed.message(),
             u"reading set\\n\\x1b]0;title\\x07.dbp: drive refused 'OR1008,0': \\x1b[2J\\rOK"_qs);
    QVERIFY(isPrintable(prefixed.toString()));
}

void TestPrintable::restoreReportLinesStayLines()
{
    RestoreReport report;
    RestoreRow failed;
    failed.address = ObjectAddress(0x6083, 0);
    failed.name = u"Profile\x1b[2J acceleration\nverified  6083:0 OK"_qs;
    failed.outcome = RestoreOutcome::Failed;
    failed.reason = u"drive said \x1b[32mOK\r"_qs;
    report.rows.append(failed);
    report.notes.append(u"note from \u202efile"_qs);
    const QStringList lines = report.summary().split(QLatin1Char('\n'));
    QCOMPARE(lines.size(), 3);
    QCOMPARE(lines.at(1),
             u"  failed    6083:0 Profile\\x1b[2J acceleration\\nverified  6083:0 OK: drive said "
             "\\x1b[32mOK\\r"_qs);
    QCOMPARE(lines.at(2), u"note: note from \\u202efile"_qs);
}

QTEST_GUILESS_MAIN(TestPrintable)
#include "tst_printable.moc"
