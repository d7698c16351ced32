#pragma once

#include "canbus.h"

#include <QCanBusDevice>
#include <QPointer>

namespace db {

// A CanBus over any Qt CAN plugin (socketcan, virtualcan, peakcan, ...), through QCanBusDevice.
//
// open() creates the device and connects it; a missing plugin or interface, or a refused
// connection, ends in closed() with an error naming plugin and interface and listing what is
// available. Error frames and non-fatal device errors become warning(); a device that drops
// while open closes the bus with Error::Kind::Disconnected. Failures are reported from the
// event loop, never from inside open().
//
// Received frames are taken from the plugin's queue CanBus::kReceiveSliceFrames per event-loop
// pass; when more than CanBus::kMaxReceiveQueueFrames wait there, the oldest are dropped and
// reported (the plugin's queue itself is unbounded).
class QtCanBus : public CanBus
{
    Q_OBJECT
public:
    // bitrate <= 0: leave the interface's bit rate as it is (virtualcan ignores it anyway; on
    // socketcan setting it needs libsocketcan and privileges).
    QtCanBus(const QString &plugin, const QString &interfaceName, int bitrate = 0,
             QObject *parent = nullptr);
    ~QtCanBus() override;

    QString name() const override; // "virtualcan can0"
    QString plugin() const { return m_plugin; }
    QString interfaceName() const { return m_interface; }
    int bitrate() const { return m_bitrate; }

    // Installed Qt CAN plugins, sorted.
    static QStringList availablePlugins();
    // Interfaces the plugin reports (empty where the plugin cannot list them).
    static QStringList availableInterfaces(const QString &plugin, QString *errorMessage = nullptr);
    // Whether `plugin` is installed and, where the plugin lists its interfaces, has
    // `interfaceName`: the error names both and what is available (NotSupported for a missing
    // plugin, HostNotFound for a missing interface). Cheap: nothing is opened.
    static Result<void> checkInterface(const QString &plugin, const QString &interfaceName);

protected:
    void doOpen() override;
    void doClose() override;
    void doSend(const QCanBusFrame &frame) override;

private:
    void failLater(const Error &error);
    void onStateChanged(QCanBusDevice::CanBusDeviceState state);
    void onError(QCanBusDevice::CanBusError error);
    void onFramesReceived();
    void releaseDevice();
    void scheduleReceive();

    QString m_plugin;
    QString m_interface;
    int m_bitrate;
    QPointer<QCanBusDevice> m_device;
    QString m_openError; // what the device said while it was being opened
    bool m_receiveScheduled = false;
};

} // namespace db
