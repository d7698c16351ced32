#include "scriptedcanbus.h"

#include <QMetaObject>

namespace db::test {

QCanBusFrame ScriptedCanBus::frame(quint32 id, const char *hex)
{
    return QCanBusFrame(id, QByteArray::fromHex(QByteArray(hex).replace(' ', "")));
}

ScriptedCanBus::Line ScriptedCanBus::tx(quint32 id, const char *hex)
{
    return { true, frame(id, hex) };
}

ScriptedCanBus::Line ScriptedCanBus::rx(quint32 id, const char *hex)
{
    return { false, frame(id, hex) };
}

QList<QCanBusFrame> ScriptedCanBus::takeSent()
{
    const QList<QCanBusFrame> out = m_sent.mid(m_taken);
    m_taken = m_sent.size();
    return out;
}

void ScriptedCanBus::feedLater(const QCanBusFrame &frame)
{
    QMetaObject::invokeMethod(
        this, [this, frame] { deliver(frame); }, Qt::QueuedConnection);
}

void ScriptedCanBus::play(const QList<Line> &script)
{
    m_script = script;
    m_next = 0;
    m_errors.clear();
    deliverReplies();
}

void ScriptedCanBus::doOpen()
{
    if (m_refusal.isError()) {
        const Error error = std::exchange(m_refusal, {});
        setClosed(error);
        return;
    }
    setOpened();
}

void ScriptedCanBus::doSend(const QCanBusFrame &frame)
{
    m_sent.append(frame);
    reportSent(frame);
    Q_EMIT frameWritten(frame);
    if (m_next >= m_script.size()) {
        if (!m_script.isEmpty())
            m_errors.append(
                QStringLiteral("unexpected TX after the script: %1").arg(describe(frame)));
        return;
    }
    const Line &line = m_script.at(m_next);
    if (!line.tx) {
        m_errors.append(
            QStringLiteral("TX %1 while RX %2 was due").arg(describe(frame), describe(line.frame)));
        return;
    }
    if (line.frame.frameId() != frame.frameId() || line.frame.payload() != frame.payload())
        m_errors.append(QStringLiteral("line %1: expected TX %2, got %3")
                            .arg(m_next)
                            .arg(describe(line.frame), describe(frame)));
    ++m_next;
    deliverReplies();
}

void ScriptedCanBus::deliverReplies()
{
    while (m_next < m_script.size() && !m_script.at(m_next).tx)
        feedLater(m_script.at(m_next++).frame);
}

QString describe(const QCanBusFrame &frame)
{
    return QStringLiteral("%1 [%2] %3")
        .arg(frame.frameId(), 3, 16, QLatin1Char('0'))
        .arg(frame.payload().size())
        .arg(QString::fromLatin1(frame.payload().toHex(' ')).toUpper());
}

} // namespace db::test
