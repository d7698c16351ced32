#pragma once

// The simulated MovingCap's CANopen face (movingcap.md 4): node 50 over the drive's own objects,
// so SDO on the SLCAN door sees the same values and the same axis as the RefGo door. EMCY
// frames carry exactly the bytes of movingcap.md 7.1 on COB-ID 0x0B2, from
// MovingCapDrive::emergency. NMT and heartbeat behave as a standard CiA 301 node (the manual
// does not say whether the drive supports them; 4.1); the description has no PDO objects.
// Life guarding (100Ch/100Dh, the XDD's objects of 4.4; no 1016h consumer) ends in the
// drive's abort connection reaction (6007h).

#include "canopen/device/simulatednode.h"

namespace db::sim {
class MovingCapDrive;
}

namespace db::canopen {

class MovingCapCanopen : public QObject, public ObjectAccess
{
    Q_OBJECT
public:
    static constexpr NodeId kNodeId = 50; // movingcap.md 4.1

    // The drive must outlive this object. The node starts at once (boot-up, Pre-operational).
    explicit MovingCapCanopen(sim::MovingCapDrive *drive, QObject *parent = nullptr);
    ~MovingCapCanopen() override;

    SimulatedNode &node() { return *m_node; }
    // Every frame seen on the bus; answers come from transmit().
    void receive(const QCanBusFrame &frame);

    // ObjectAccess over the drive: its checks and side effects (6040h moves the state machine,
    // 1010h.1 "save" stores); a wrong save/load signature gives abort 08000020.
    const ObjectDictionary &dictionary() const override;
    Result<QVariant> read(ObjectAddress address) override;
    Result<void> write(ObjectAddress address, const QVariant &raw) override;

Q_SIGNALS:
    void transmit(const QCanBusFrame &frame);

private:
    sim::MovingCapDrive *m_drive;
    std::unique_ptr<SimulatedNode> m_node;
    bool m_reportingLoss = false; // inside the drive's reaction to a life guarding event
};

} // namespace db::canopen
