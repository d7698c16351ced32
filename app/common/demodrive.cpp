#include "demodrive.h"

#include "devices/movingcap/movingcapcanopen.h"
#include "devices/movingcap/movingcapdrive.h"
#include "devices/movingcap/movingcaprefgohandler.h"
#include "refgo/device/refgoserver.h"
#include "resources/builtindescriptions.h"
#include "transport/device/slcanserver.h"

namespace db::app {

namespace {
sim::MovingCapOptions options(const QHash<ObjectAddress, QVariant> &initialValues)
{
    sim::MovingCapOptions o;
    o.initialValues = initialValues;
    o.axisModel.velocityNoise = 2.0; // 606Ch ripples while moving, as a real drive's does (scope)
    return o;
}
} // namespace

struct DemoDrive::Private
{
    explicit Private(const QHash<ObjectAddress, QVariant> &initialValues)
        : drive(resources::movingCapDictionary(), options(initialValues))
    {
        QObject::connect(&slcanServer, &SlcanServer::frameReceived, &canopen,
                         [this](const QCanBusFrame &frame) {
                             if (!silent)
                                 canopen.receive(frame);
                         });
        QObject::connect(&canopen, &canopen::MovingCapCanopen::transmit, &slcanServer,
                         [this](const QCanBusFrame &frame) {
                             if (!silent)
                                 slcanServer.send(frame);
                         });
    }
    sim::MovingCapDrive drive;
    refgo::MovingCapRefgoHandler handler { &drive };
    refgo::Server refgoServer { &handler };
    canopen::MovingCapCanopen canopen { &drive };
    SlcanServer slcanServer;
    bool silent = false;
};

DemoDrive::DemoDrive(const QHash<ObjectAddress, QVariant> &initialValues, QObject *parent)
    : QObject(parent)
    , d(std::make_unique<Private>(initialValues))
{
    d->drive.startRealTime();
}

DemoDrive::~DemoDrive() = default;

Result<void> DemoDrive::startRefgo(quint16 port)
{
    return d->refgoServer.listen(port);
}

quint16 DemoDrive::refgoPort() const
{
    return d->refgoServer.port();
}

QString DemoDrive::refgoUri() const
{
    return QStringLiteral("refgo://127.0.0.1:%1").arg(refgoPort());
}

Result<void> DemoDrive::startSlcan(quint16 port)
{
    return d->slcanServer.listen(port);
}

quint16 DemoDrive::slcanPort() const
{
    return d->slcanServer.port();
}

QString DemoDrive::slcanUri() const
{
    return QStringLiteral("canopen+slcan://127.0.0.1:%1?node=%2")
        .arg(slcanPort())
        .arg(canopen::MovingCapCanopen::kNodeId);
}

sim::MovingCapDrive &DemoDrive::drive()
{
    return d->drive;
}

int DemoDrive::dropClients()
{
    return d->refgoServer.dropClients() + d->slcanServer.dropClients();
}

void DemoDrive::setSilent(bool on)
{
    d->silent = on;
    d->refgoServer.setSilent(on);
}

void DemoDrive::setHeartbeatSilenced(bool on)
{
    d->canopen.node().setHeartbeatSilenced(on);
}

} // namespace db::app
