#include "demosimulators.h"

#include "common/demodrive.h"
#include "devices/bonfiglioli/simulatedacu.h"
#include "devices/nm17x/device/nm17xsim.h"

#include <QCoreApplication>
#include <QMetaObject>
#include <QObject>
#include <QThread>

namespace db::gui {

struct DemoSimulators::Private
{
    QThread thread;
    QObject context; // lives in the thread: what runs there is invoked on it
    // Built, used and destroyed only in the thread.
    std::unique_ptr<bonfiglioli::SimulatedAcu> acu;
    std::unique_ptr<app::DemoDrive> drive;
    std::unique_ptr<nm17x::Nm17xSim> displays;
    Started started;
    bool running = false;
};

DemoSimulators::DemoSimulators()
    : d(std::make_unique<Private>())
{
    d->thread.setObjectName(QStringLiteral("demo devices"));
}

DemoSimulators::~DemoSimulators()
{
    if (d->thread.isRunning()) {
        QMetaObject::invokeMethod(
            &d->context,
            [this] {
                d->displays.reset();
                d->drive.reset();
                d->acu.reset();
            },
            Qt::BlockingQueuedConnection);
        d->thread.quit();
        d->thread.wait();
    }
}

bool DemoSimulators::isRunning() const
{
    return d->running;
}

const DemoSimulators::Started &DemoSimulators::uris() const
{
    return d->started;
}

Result<DemoSimulators::Started> DemoSimulators::start()
{
    if (d->running)
        return d->started;
    if (!d->thread.isRunning()) {
        d->context.moveToThread(&d->thread);
        d->thread.start();
    }
    Result<void> result;
    Started started;
    QMetaObject::invokeMethod(
        &d->context,
        [this, &result, &started] {
            auto drive = std::make_unique<app::DemoDrive>();
            if (auto refgo = drive->startRefgo(0); !refgo) {
                result = refgo.error();
                return;
            }
            started.refgoUri = drive->refgoUri();
            if (auto slcan = drive->startSlcan(0); slcan)
                started.slcanUri = drive->slcanUri();
            else
                started.warnings << QCoreApplication::translate("main",
                                                                "Demo drive without CANopen: %1")
                                        .arg(slcan.error().toString());
            d->drive = std::move(drive);

            auto acu = std::make_unique<bonfiglioli::SimulatedAcu>();
            if (auto listening = acu->listen(0); listening) {
                started.acuUri = QStringLiteral("vabus://127.0.0.1:%1").arg(acu->port());
                d->acu = std::move(acu);
            } else {
                started.warnings << QCoreApplication::translate("main",
                                                                "Demo ACTIVE Cube not started: %1")
                                        .arg(listening.error().toString());
            }

            auto displays = std::make_unique<nm17x::Nm17xSim>();
            displays->create(
                nm17x::Nm17xSim::parseDevices(QStringLiteral("nm172@2,nm172@3,nm174@4"))
                    .valueOr({}));
            if (auto slcan = displays->startSlcan(0); slcan) {
                started.nm17xPort = displays->slcanPort();
                d->displays = std::move(displays);
            } else {
                started.warnings << QCoreApplication::translate(
                                        "main", "Demo NM17x displays not started: %1")
                                        .arg(slcan.error().toString());
            }
        },
        Qt::BlockingQueuedConnection);
    if (!result)
        return result.error();
    d->started = started;
    d->running = true;
    return started;
}

} // namespace db::gui
