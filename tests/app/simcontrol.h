#pragma once

// The control console of `drivebench-sim movingcap --control`, for the fail-safe tests: one
// command per line on its standard input, answers on its standard output. Times and positions
// in the answers come from the simulated drive's own clock and axis, so test and pipe latencies
// are not part of the figures. Header-only; every wait is bounded.
#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QString>

namespace db::test {

class SimControl
{
public:
    struct Sample
    {
        bool ok = false;
        qint64 ms = 0; // the drive's clock
        double position = 0;
        double velocity = 0;
        int statusword = 0;
        QString line;
    };

    explicit SimControl(QProcess &sim)
        : m_sim(sim)
    { }

    // Sends one console command and returns the first answer line starting with `answer` (or
    // "error:"); empty when none came within timeoutMs.
    QString ask(const QString &command, const QString &answer, int timeoutMs = 3000)
    {
        m_sim.write(command.toUtf8() + '\n');
        QElapsedTimer clock;
        clock.start();
        for (;;) {
            qsizetype nl;
            while ((nl = m_pending.indexOf('\n')) >= 0) {
                const QString line = QString::fromUtf8(m_pending.left(nl)).trimmed();
                m_pending.remove(0, nl + 1);
                if (line.startsWith(answer) || line.startsWith(QLatin1String("error:")))
                    return line;
            }
            const qint64 left = timeoutMs - clock.elapsed();
            if (left <= 0 || m_sim.state() != QProcess::Running)
                return {};
            m_sim.waitForReadyRead(int(left));
            m_pending += m_sim.readAllStandardOutput();
        }
    }

    // "state T position P velocity V statusword 0xSSSS", "standstill T position P",
    // "dropped N T position P velocity V".
    Sample sample(const QString &command, const QString &answer, int timeoutMs = 3000)
    {
        Sample s;
        s.line = ask(command, answer, timeoutMs);
        static const QRegularExpression re(
            QStringLiteral("^\\w+ (?:\\d+ )?(\\d+) position (-?[\\d.]+)(?: velocity (-?[\\d.]+))?"
                           "(?: statusword 0x([0-9A-F]{4}))?$"));
        const auto m = re.match(s.line);
        if (!m.hasMatch())
            return s;
        s.ok = true;
        s.ms = m.captured(1).toLongLong();
        s.position = m.captured(2).toDouble();
        s.velocity = m.captured(3).toDouble();
        s.statusword = m.captured(4).toInt(nullptr, 16);
        return s;
    }
    Sample state() { return sample(QStringLiteral("state"), QStringLiteral("state")); }
    Sample standstill(int timeoutMs = 5000)
    {
        return sample(QStringLiteral("standstill"), QStringLiteral("standstill"), timeoutMs);
    }

private:
    QProcess &m_sim;
    QByteArray m_pending; // output not consumed yet
};

} // namespace db::test
