#include "axisfactory.h"

#include "bonfiglioli/acuaxis.h"
#include "cia402/modes.h"
#include "motion/cia402axis.h"
#include "movingcap/movingcapaxis.h"

#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(devices)
};
} // namespace

namespace db::devices {

Result<std::unique_ptr<motion::AxisInterface>> makeAxis(DeviceConnection *connection)
{
    if (!connection)
        return Error(Error::Kind::InvalidArgument, Tr::tr("no connection"));
    if (connection->protocolKey() == QLatin1String("vabus"))
        return std::unique_ptr<motion::AxisInterface>(
            std::make_unique<bonfiglioli::AcuAxis>(connection));
    const ObjectDictionary &dict = connection->dictionary();
    if (dict.contains(cia402::obj::PositionActual)) {
        auto axis = std::make_unique<motion::Cia402Axis>(connection);
        movingcap::applyAxisQuirks(*axis, dict);
        return std::unique_ptr<motion::AxisInterface>(std::move(axis));
    }
    return Error(Error::Kind::NotSupported,
                 Tr::tr("this device has no axis: %1 describes no CiA 402 drive (no 6064h; give "
                        "?eds=FILE) and is no ACTIVE Cube")
                     .arg(connection->uri().toString()));
}

} // namespace db::devices
