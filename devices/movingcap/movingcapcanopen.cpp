#include "movingcapcanopen.h"

#include "canopen/sdoabort.h"
#include "movingcapdrive.h"
#include "movingcapfaults.h"

namespace db::canopen {

MovingCapCanopen::MovingCapCanopen(sim::MovingCapDrive *drive, QObject *parent)
    : QObject(parent)
    , m_drive(drive)
    , m_node(std::make_unique<SimulatedNode>(this, kNodeId))
{
    connect(m_node.get(), &SimulatedNode::transmit, this, &MovingCapCanopen::transmit);
    // movingcap.md 7.1 [R]: exactly the drive's 8 bytes (code LE, 1001h, five zeros).
    connect(m_drive, &sim::MovingCapDrive::emergency, this,
            [this](quint16 code, quint8, const QByteArray &data8) {
                if (!m_reportingLoss || code != sim::faults::AbortConnection)
                    m_node->sendEmergency(data8);
            });
    // CiA 402 6007h: the drive's reaction when its master stops guarding it. The node reports
    // the event itself (EMCY 8130h), so the fault of 6007h = 1 does not send it twice.
    connect(m_node.get(), &SimulatedNode::communicationLost, this, [this] {
        m_reportingLoss = true;
        m_drive->connectionLost();
        m_reportingLoss = false;
    });
    m_node->start();
}

MovingCapCanopen::~MovingCapCanopen()
{
    m_drive->disconnect(this);
}

void MovingCapCanopen::receive(const QCanBusFrame &frame)
{
    m_node->receive(frame);
}

const ObjectDictionary &MovingCapCanopen::dictionary() const
{
    return m_drive->dictionary();
}

Result<QVariant> MovingCapCanopen::read(ObjectAddress address)
{
    return m_drive->read(address);
}

Result<void> MovingCapCanopen::write(ObjectAddress address, const QVariant &raw)
{
    auto written = m_drive->write(address, raw);
    if (!written && (address == ObjectAddress(0x1010, 1) || address == ObjectAddress(0x1011, 1))
        && written.error().kind() == Error::Kind::InvalidArgument)
        return Error(Error::Kind::InvalidArgument, written.error().message(), abort::CannotStore);
    return written;
}

} // namespace db::canopen
