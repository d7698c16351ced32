#include "nmtanswer.h"

#include "nmtmaster.h"
#include "nodemonitor.h"
#include "transport/canbus.h"

#include <QCanBusFrame>
#include <QCoreApplication>

namespace db::canopen {

NmtAnswer::NmtAnswer(CanBus *bus, const NodeMonitor *monitor, NmtCommand command, NodeId node,
                     QObject *parent)
    : QObject(parent)
    , m_bus(bus)
    , m_node(node)
    , m_expected(expectedState(command))
{
    m_timer.setSingleShot(true);
    const bool heard = monitor && monitor->state(node) != NmtState::Unknown;
    if (!bus || !heard) {
        // Reported after the caller connected to finished().
        QTimer::singleShot(0, this, [this] {
            finish({}, tr("not confirmed: node %1 sends no heartbeat").arg(m_node));
        });
        return;
    }
    const int consumer = monitor->consumerTime(node);
    connect(bus, &CanBus::frameReceived, this, &NmtAnswer::onFrame);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        if (m_seen == NmtState::Unknown)
            finish(Error(Error::Kind::Timeout,
                         tr("no answer: node %1 sent no heartbeat within %2 ms")
                             .arg(m_node)
                             .arg(m_timer.interval())));
        else
            finish(Error(
                Error::Kind::Timeout,
                tr("node %1 did not follow: it stays %2").arg(m_node).arg(nmtStateName(m_seen))));
    });
    m_timer.start(consumer > 0 ? consumer : kDefaultWaitMs);
}

NmtState NmtAnswer::expectedState(NmtCommand command)
{
    switch (command) {
    case NmtCommand::Start:
        return NmtState::Operational;
    case NmtCommand::Stop:
        return NmtState::Stopped;
    case NmtCommand::EnterPreOperational:
        return NmtState::PreOperational;
    case NmtCommand::ResetNode:
    case NmtCommand::ResetCommunication:
        return NmtState::BootUp;
    }
    return NmtState::Unknown;
}

void NmtAnswer::onFrame(const QCanBusFrame &frame)
{
    if (m_finished || frame.hasExtendedFrameFormat() || frame.frameId() != 0x700u + m_node
        || frame.payload().size() < 1)
        return;
    // Bit 7 is the node guarding toggle bit; the state is in bits 6..0.
    m_seen = NmtState(quint8(frame.payload().at(0)) & 0x7F);
    if (m_seen == m_expected)
        finish({});
}

void NmtAnswer::finish(const Error &error, const QString &note)
{
    if (m_finished)
        return;
    m_finished = true;
    m_timer.stop();
    if (m_bus)
        disconnect(m_bus, nullptr, this, nullptr);
    m_confirmed = !error.isError() && note.isEmpty();
    m_note = error.isError() ? error.message() : note;
    Q_EMIT finished(error);
}

} // namespace db::canopen
