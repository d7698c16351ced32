#include "app/gui/mainwindow.h"
#include "canopen/device/sdoserver.h"
#include "simulation/simulatedaxis.h"

void attach(db::DeviceConnection *connection)
{
    auto *refgo = qobject_cast<db::refgo::RefgoConnection *>(connection);
    (void)refgo;
    auto *device = qobject_cast<db::DeviceConnection *>(connection->parent());
    (void)device;
}
