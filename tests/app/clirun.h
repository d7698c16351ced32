#pragma once

// Shared by the command-line tests: run a tool with a time limit, and start drivebench-sim and
// read the ports it announces. Header-only; every wait is bounded.
#include <QElapsedTimer>
#include <QEventLoop>
#include <QProcess>
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <QTimer>

namespace db::test {

struct CliRun
{
    int exitCode = -1; // -2: did not exit within the time limit (killed), -3: crashed
    QString out;
    QString err;
    qint64 ms = 0; // wall time of the run
};

// Runs program with args and waits at most timeoutMs for it to exit.
inline CliRun runProgram(const QString &program, const QStringList &args, int timeoutMs)
{
    QProcess p;
    QElapsedTimer clock;
    clock.start();
    p.start(program, args);
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        return { -2, {}, QStringLiteral("hang: no exit within %1 ms").arg(timeoutMs), 0 };
    }
    return { p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -3,
             QString::fromUtf8(p.readAllStandardOutput()),
             QString::fromUtf8(p.readAllStandardError()), clock.elapsed() };
}

// runProgram for a program that talks to a peer served by the test process itself: the event
// loop runs while waiting, so the peer answers. At most timeoutMs.
inline CliRun runProgramServing(const QString &program, const QStringList &args, int timeoutMs)
{
    QProcess p;
    QEventLoop loop;
    QObject::connect(&p, &QProcess::finished, &loop, &QEventLoop::quit);
    QObject::connect(&p, &QProcess::errorOccurred, &loop, [&loop](QProcess::ProcessError e) {
        if (e == QProcess::FailedToStart)
            loop.quit();
    });
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    QElapsedTimer clock;
    clock.start();
    p.start(program, args);
    loop.exec();
    if (p.state() != QProcess::NotRunning) {
        p.kill();
        p.waitForFinished();
        return { -2, {}, QStringLiteral("hang: no exit within %1 ms").arg(timeoutMs), 0 };
    }
    return { p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -3,
             QString::fromUtf8(p.readAllStandardOutput()),
             QString::fromUtf8(p.readAllStandardError()), clock.elapsed() };
}

// Starts a simulator and collects its standard output until it holds `lines` lines, it exits,
// or timeoutMs pass. Returns what was read (empty when it did not start).
inline QString startAndReadBanner(QProcess &process, const QString &program,
                                  const QStringList &args, int lines, int timeoutMs = 10000)
{
    process.start(program, args);
    if (!process.waitForStarted())
        return {};
    QString banner;
    QElapsedTimer clock;
    clock.start();
    while (banner.count(QLatin1Char('\n')) < lines && clock.elapsed() < timeoutMs) {
        if (!process.waitForReadyRead(100) && process.state() == QProcess::NotRunning)
            break;
        banner += QString::fromUtf8(process.readAllStandardOutput());
    }
    return banner;
}

// The port in "<what> listening on 127.0.0.1:PORT" (what may be empty: the first one); 0 if none.
inline quint16 listeningPort(const QString &banner, const QString &what = {})
{
    const QRegularExpression re(QRegularExpression::escape(what)
                                + QStringLiteral("\\s*listening on 127\\.0\\.0\\.1:(\\d+)"));
    const QRegularExpressionMatch m = re.match(banner);
    return m.hasMatch() ? quint16(m.captured(1).toUInt()) : quint16(0);
}

} // namespace db::test
