#pragma once

// A DeviceConnection straight into an in-process simulated MovingCap (no transport): the level 2
// seam for the CiA 402 driver and the motion model. Failure modes: frozen (writes are accepted
// but ignored, so the drive never changes state) and goAway() (the link breaks).

#include "core/deviceconnection.h"
#include "devices/movingcap/movingcapdrive.h"

namespace db::test {

class SimConnection : public DeviceConnection
{
    Q_OBJECT
public:
    explicit SimConnection(sim::MovingCapDrive *drive, QObject *parent = nullptr)
        : DeviceConnection(ConnectionUri::parse(QStringLiteral("refgo://127.0.0.1")).value(),
                           parent)
        , m_drive(drive)
    {
        setDictionary(drive->dictionary());
    }

    QString protocolKey() const override { return QStringLiteral("sim"); }

    bool frozen = false;
    int writeCount = 0;

    void goAway()
    {
        setState(State::Disconnected,
                 Error(Error::Kind::Disconnected, QStringLiteral("simulated link broke")));
    }

protected:
    void doOpen() override { setState(State::Connected); }
    void doClose() override { setState(State::Disconnected); }
    void doRead(Reply *reply, const ObjectDef *) override
    {
        auto r = m_drive->read(reply->address());
        if (r)
            reply->finish(r.value());
        else
            reply->fail(r.error());
    }
    void doWrite(Reply *reply, const QVariant &raw, const ObjectDef *) override
    {
        ++writeCount;
        if (frozen) {
            reply->finish();
            return;
        }
        auto r = m_drive->write(reply->address(), raw);
        if (r)
            reply->finish();
        else
            reply->fail(r.error());
    }

private:
    sim::MovingCapDrive *m_drive;
};

} // namespace db::test
