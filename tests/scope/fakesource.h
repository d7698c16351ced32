#pragma once
// Test helper: a TraceSource whose samples the test pushes with explicit times.
#include "scope/tracesource.h"

namespace db::test {

class FakeSource : public scope::TraceSource
{
    Q_OBJECT
public:
    explicit FakeSource(QList<scope::ChannelInfo> channels, QObject *parent = nullptr)
        : TraceSource(parent)
        , m_channels(std::move(channels))
    { }
    QList<scope::ChannelInfo> channels() const override { return m_channels; }
    bool isRunning() const override { return m_running; }
    void start(const QElapsedTimer &) override
    {
        m_running = true;
        ++starts;
        Q_EMIT runningChanged(true);
    }
    void stop() override
    {
        if (!m_running)
            return;
        m_running = false;
        Q_EMIT runningChanged(false);
    }
    // Pushes (t, value) pairs for one channel, one signal per sample (as the polling source).
    void push(int channel, const QList<QPair<double, double>> &samples)
    {
        for (const auto &s : samples) {
            if (m_running)
                Q_EMIT samplesReady(channel, scope::TraceSamples { { s.first, s.second } });
        }
    }
    void lose(int channel, qint64 count)
    {
        if (m_running)
            Q_EMIT samplesLost(channel, count);
    }
    void failWith(const Error &error)
    {
        stop();
        Q_EMIT errorOccurred(error);
    }
    int starts = 0;

private:
    QList<scope::ChannelInfo> m_channels;
    bool m_running = false;
};

inline scope::ChannelInfo channel(quint16 index, quint8 sub, const QString &name,
                                  const QString &unit = {})
{
    scope::ChannelInfo c;
    c.address = { index, sub };
    c.id = c.address.toString();
    c.name = name;
    c.unit = unit;
    c.device = QStringLiteral("refgo://127.0.0.1:1");
    return c;
}

} // namespace db::test
