// drivebench-cli prints text from parameter files and devices without letting their control
// characters reach the terminal: hostile names, values, file names and device answers come out
// as visible escapes ("\x1b[2J"), never as raw ESC, CR or NUL bytes. Against drivebench-sim and
// a scripted RefGo peer, both on OS-chosen loopback ports.
#include "clirun.h"

#include <QHostAddress>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

namespace {

// The bytes a terminal acts on: ESC (and with it every CSI/OSC sequence), CR, NUL, BEL, BS, DEL,
// C1 controls (as UTF-8), bidi overrides.
QString rawControls(const QString &text)
{
    static const QRegularExpression re(QStringLiteral(
        "[\\x00-\\x09\\x0b-\\x1f\\x7f-\\x9f\\x{202a}-\\x{202e}\\x{2066}-\\x{2069}]"));
    const QRegularExpressionMatch m = re.match(text);
    return m.hasMatch() ? QStringLiteral("raw U+%1 at %2 in: %3")
                              .arg(m.captured(0).at(0).unicode(), 4, 16, QLatin1Char('0'))
                              .arg(m.capturedStart())
                              .arg(text.toHtmlEscaped())
                        : QString();
}

} // namespace

class TestCliEscape : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void hostileNamesInDiffAndRestore();
    void hostileFileContentsInErrors_data();
    void hostileFileContentsInErrors();
    void hostileRefgoAnswers_data();
    void hostileRefgoAnswers();

private:
    using Run = db::test::CliRun;
    Run cli(const QStringList &args);
    QString file(const QString &name) const { return m_dir.filePath(name); }
    QByteArray backup();
    void writeFile(const QString &path, const QByteArray &bytes);

    QTemporaryDir m_dir;
    QProcess m_sim;
    QString m_refgo;
};

TestCliEscape::Run TestCliEscape::cli(const QStringList &args)
{
    return db::test::runProgram(QStringLiteral(DRIVEBENCH_CLI), args, 20000);
}

QByteArray TestCliEscape::backup()
{
    const QString path = file(QStringLiteral("backup.dbp"));
    if (!QFile::exists(path)) {
        const Run r = cli({ QStringLiteral("backup"), m_refgo, QStringLiteral("-o"), path });
        if (r.exitCode != 0)
            return {};
    }
    QFile in(path);
    return in.open(QIODevice::ReadOnly) ? in.readAll() : QByteArray();
}

void TestCliEscape::writeFile(const QString &path, const QByteArray &bytes)
{
    QFile out(path);
    QVERIFY(out.open(QIODevice::WriteOnly));
    QCOMPARE(out.write(bytes), bytes.size());
}

void TestCliEscape::initTestCase()
{
    QVERIFY(m_dir.isValid());
    const QString banner = db::test::startAndReadBanner(
        m_sim, QStringLiteral(DRIVEBENCH_SIM),
        { QStringLiteral("movingcap"), QStringLiteral("--refgo-port"), QStringLiteral("0"),
          QStringLiteral("--slcan-port"), QStringLiteral("0") },
        2);
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("\\((refgo://[^)]+)\\)")).match(banner);
    QVERIFY2(m.hasMatch(), qPrintable(banner));
    m_refgo = m.captured(1);
}

void TestCliEscape::cleanupTestCase()
{
    if (m_sim.state() != QProcess::NotRunning) {
        m_sim.terminate();
        if (!m_sim.waitForFinished(3000))
            m_sim.kill();
    }
}

void TestCliEscape::hostileNamesInDiffAndRestore()
{
    QByteArray text = backup();
    QVERIFY(!text.isEmpty());
    // A name that would clear the screen and overwrite its line with "OK" (the file format
    // carries CR as the escape "\r"; ESC, BEL and the right-to-left override are written raw).
    const QByteArray name = "\"Profile\x1b[2J\x1b[H acceleration\\rOK \x07\xe2\x80\xae\"";
    QVERIFY(text.contains("6083:0 \"Profile acceleration\" "));
    text.replace("6083:0 \"Profile acceleration\" ", "6083:0 " + name + ' ');
    const QString hostile = file(QStringLiteral("hostile.dbp"));
    writeFile(hostile, text);
    const QString expected =
        QStringLiteral("Profile\\x1b[2J\\x1b[H acceleration\\rOK \\x07\\u202e");

    // diff of two files names the rows by the first file's names; make 6083:0 differ.
    QByteArray changed = text;
    const qsizetype at = changed.indexOf("6083:0 ");
    changed.insert(changed.indexOf(" UNSIGNED32 ", at) + 12, "1");
    const QString other = file(QStringLiteral("hostile-changed.dbp"));
    writeFile(other, changed);
    const Run d = cli({ QStringLiteral("diff"), hostile, other });
    QCOMPARE(d.exitCode, 1);
    QVERIFY2(rawControls(d.out + d.err).isEmpty(), qPrintable(rawControls(d.out + d.err)));
    QVERIFY2(d.out.contains(QStringLiteral("changed 6083:0  ") + expected + u':'),
             qPrintable(d.out));

    // restore names the rows the device knows by the device's names, the others by the file's.
    QVERIFY(text.contains("3300:4 \"motor_imbalance_amplitude\" "));
    text.replace("3300:4 \"motor_imbalance_amplitude\" ", "2FFF:0 " + name + ' ');
    const QString unknown = file(QStringLiteral("hostile-unknown.dbp"));
    writeFile(unknown, text);
    const Run r = cli({ QStringLiteral("restore"), m_refgo, unknown, QStringLiteral("--only"),
                        QStringLiteral("6083:0,2FFF:0") });
    QVERIFY2(r.exitCode == 1, qPrintable(r.out + r.err));
    QVERIFY2(rawControls(r.out + r.err).isEmpty(), qPrintable(rawControls(r.out + r.err)));
    const QStringList lines = r.out.trimmed().split(QLatin1Char('\n'));
    QCOMPARE(lines.size(), 3);
    QVERIFY2(lines.at(2).startsWith(QStringLiteral("  skipped   2FFF:0 ") + expected + u':'),
             qPrintable(r.out));
}

void TestCliEscape::hostileFileContentsInErrors_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<QByteArray>("from");
    QTest::addColumn<QByteArray>("to");
    QTest::addColumn<QString>("fileName");
    QTest::addColumn<QString>("message");
    QTest::newRow("type token") << QStringLiteral("restore") << QByteArray(" UNSIGNED32 ")
                                << QByteArray(" \x1b[2J\x1b[1;1HOK") + '\0' + "\xc2\x9b "
                                << QStringLiteral("type.dbp")
                                << QStringLiteral(
                                       "unknown type '\\x1b[2J\\x1b[1;1HOK\\x00\\u009b'");
    QTest::newRow("product name") << QStringLiteral("restore") << QByteArray("product 0x")
                                  << QByteArray("product 0x") << QStringLiteral("product.dbp")
                                  << QStringLiteral("@PRODUCT@");
    QTest::newRow("file name") << QStringLiteral("diff") << QByteArray("\nend") << QByteArray("\n")
                               << QStringLiteral("x\x1b]0;owned\x07\rOK.dbp")
                               << QStringLiteral("x\\x1b]0;owned\\x07\\rOK.dbp:");
}

void TestCliEscape::hostileFileContentsInErrors()
{
    QFETCH(QString, command);
    QFETCH(QByteArray, from);
    QFETCH(QByteArray, to);
    QFETCH(QString, fileName);
    QFETCH(QString, message);
    QByteArray text = backup();
    QVERIFY(!text.isEmpty());
    const qsizetype at = text.indexOf(from, text.indexOf("entries "));
    if (message == QLatin1String("@PRODUCT@")) {
        // The product name the set is for, quoted in the refusal against the device's own.
        const qsizetype product = text.indexOf("product 0x");
        const qsizetype open = text.indexOf('"', product);
        text.insert(open + 1, "\x1b[31m\r");
        message = QStringLiteral("is a set for '\\x1b[31m\\r");
    } else {
        QVERIFY(at > 0 || from == "\nend");
        const qsizetype where = from == "\nend" ? text.lastIndexOf(from) : at;
        text.replace(where, from.size(), to);
    }
    const QString path = file(fileName);
    writeFile(path, text);
    const QStringList args = command == QLatin1String("diff")
        ? QStringList { command, path, path }
        : QStringList { command, m_refgo, path };
    const Run r = cli(args);
    QVERIFY2(r.exitCode == 2 || r.exitCode == 5, qPrintable(QString::number(r.exitCode) + r.err));
    QVERIFY2(rawControls(r.out + r.err).isEmpty(), qPrintable(rawControls(r.out + r.err)));
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QCOMPARE(r.err.count(QLatin1Char('\n')), 1);
}

void TestCliEscape::hostileRefgoAnswers_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("expected");
    // "refgo" prints the answer's result lines: one line each, escaped.
    QTest::newRow("raw command") << QStringList { QStringLiteral("refgo"), QStringLiteral("@URI@"),
                                                  QStringLiteral("TS") }
                                 << 0 << QStringLiteral("\\x1b[2J\\x1b[HOK \\u009b31m\\x07\n");
    // "read" quotes the line it cannot use in its error.
    QTest::newRow("read") << QStringList { QStringLiteral("read"), QStringLiteral("@URI@"),
                                           QStringLiteral("6041:0") }
                          << 6 << QStringLiteral("\\x1b[2J\\x1b[HOK \\u009b31m\\x07");
}

// A RefGo peer (spec 3.1: echo, result lines, prompt) whose every result line is hostile.
void TestCliEscape::hostileRefgoAnswers()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    QFETCH(QString, expected);
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    QList<QTcpSocket *> peers;
    connect(&server, &QTcpServer::newConnection, this, [&] {
        while (QTcpSocket *peer = server.nextPendingConnection()) {
            peers.append(peer);
            auto *buffer = new QByteArray;
            connect(peer, &QObject::destroyed, this, [buffer] { delete buffer; });
            connect(peer, &QTcpSocket::readyRead, peer, [peer, buffer] {
                buffer->append(peer->readAll());
                qsizetype end;
                while ((end = buffer->indexOf('\r')) >= 0) {
                    const QByteArray request = buffer->left(end).trimmed();
                    buffer->remove(0, end + 1);
                    if (!request.isEmpty())
                        peer->write(request
                                    + "\r\n\x1b[2J\x1b[HOK \x9b"
                                      "31m\x07\r\n>");
                }
            });
        }
    });
    args.replaceInStrings(QStringLiteral("@URI@"),
                          QStringLiteral("refgo://127.0.0.1:%1").arg(server.serverPort()));
    QProcess cliProcess;
    QSignalSpy finished(&cliProcess, &QProcess::finished);
    cliProcess.start(QStringLiteral(DRIVEBENCH_CLI), args);
    QVERIFY(finished.wait(20000)); // the peer answers from this event loop
    const QString out = QString::fromUtf8(cliProcess.readAllStandardOutput());
    const QString err = QString::fromUtf8(cliProcess.readAllStandardError());
    QVERIFY2(cliProcess.exitCode() == exitCode, qPrintable(out + err));
    QVERIFY2(rawControls(out + err).isEmpty(), qPrintable(rawControls(out + err)));
    QVERIFY2((exitCode == 0 ? out : err).contains(expected), qPrintable(out + err));
    qDeleteAll(peers);
}

QTEST_GUILESS_MAIN(TestCliEscape)
#include "tst_cli_escape.moc"
