#include "demodrive.h"

#include "refgo/movingcaprefgohandler.h"
#include "refgo/refgoserver.h"
#include "resources/builtindescriptions.h"
#include "simulation/movingcapdrive.h"

namespace db::app {

struct DemoDrive::Private
{
    sim::MovingCapDrive drive{resources::movingCapDictionary()};
    refgo::MovingCapRefgoHandler handler{&drive};
    refgo::Server refgoServer{&handler};
};

DemoDrive::DemoDrive(QObject *parent)
    : QObject(parent)
    , d(std::make_unique<Private>())
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

sim::MovingCapDrive &DemoDrive::drive()
{
    return d->drive;
}

} // namespace db::app
