#pragma once

// Shared by the command-line tests: run a tool with a time limit, and start drivebench-sim and
// read the ports it announces. Header-only; every wait is bounded.
#include "wait.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QString>
#include <QStringList>

namespace db::test {

struct CliRun
{
    int exitCode = -1; // -2: did not exit within the time limit (killed), -3: crashed
    QString out;
    QString err;
    qint64 ms = 0; // wall time of the run
};

// The outcome of a run that was waited for: a program still running is killed (a hang), one
// that did not start is no exit code either.
inline CliRun finishedRun(QProcess &p, const QElapsedTimer &clock, int timeoutMs)
{
    if (p.error() == QProcess::FailedToStart)
        return {
            -2, {}, QStringLiteral("cannot start %1: %2").arg(p.program(), p.errorString()), 0
        };
    if (p.state() != QProcess::NotRunning) {
        p.kill();
        p.waitForFinished();
        return { -2, {}, QStringLiteral("hang: no exit within %1 ms").arg(timeoutMs), 0 };
    }
    return { p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -3,
             QString::fromUtf8(p.readAllStandardOutput()),
             QString::fromUtf8(p.readAllStandardError()), clock.elapsed() };
}

// Runs program with args and waits at most timeoutMs for it to exit.
inline CliRun runProgram(const QString &program, const QStringList &args, int timeoutMs)
{
    QProcess p;
    QElapsedTimer clock;
    clock.start();
    p.start(program, args);
    p.waitForFinished(timeoutMs);
    return finishedRun(p, clock, timeoutMs);
}

// Like runProgram, but the caller's event loop keeps turning while the program runs, so that
// peers living in the test process (peers.h) can serve it.
inline CliRun runServing(const QString &program, const QStringList &args, int timeoutMs)
{
    QProcess p;
    QElapsedTimer clock;
    clock.start();
    p.start(program, args);
    waitUntil(
        &p, &QProcess::stateChanged, [&p] { return p.state() == QProcess::NotRunning; }, timeoutMs);
    return finishedRun(p, clock, timeoutMs);
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
