#include "qtcanbus.h"

#include <QCanBus>
#include <QCoreApplication>
#include <QLoggingCategory>
#include <QVariant>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::transport)
};
} // namespace

namespace db {

namespace {
Q_LOGGING_CATEGORY(lcQtCan, "drivebench.transport.can")
Q_LOGGING_CATEGORY(lcQtCanRaw, "drivebench.transport.can.raw", QtWarningMsg)

QString joined(const QStringList &list)
{
    return list.isEmpty() ? QStringLiteral("none") : list.join(QStringLiteral(", "));
}
} // namespace

QtCanBus::QtCanBus(const QString &plugin, const QString &interfaceName, int bitrate,
                   QObject *parent)
    : CanBus(parent)
    , m_plugin(plugin)
    , m_interface(interfaceName)
    , m_bitrate(bitrate)
{ }

QtCanBus::~QtCanBus()
{
    if (m_device) {
        m_device->disconnect(this);
        m_device->disconnectDevice();
        delete m_device;
    }
}

QString QtCanBus::name() const
{
    return m_plugin + QLatin1Char(' ') + m_interface;
}

QStringList QtCanBus::availablePlugins()
{
    QStringList plugins = QCanBus::instance()->plugins();
    plugins.sort();
    return plugins;
}

QStringList QtCanBus::availableInterfaces(const QString &plugin, QString *errorMessage)
{
    QStringList names;
    const auto devices = QCanBus::instance()->availableDevices(plugin, errorMessage);
    for (const QCanBusDeviceInfo &info : devices)
        names.append(info.name());
    return names;
}

void QtCanBus::failLater(const Error &error)
{
    qCWarning(lcQtCan).noquote() << error.message();
    QMetaObject::invokeMethod(
        this,
        [this, error] {
            releaseDevice();
            setClosed(error);
        },
        Qt::QueuedConnection);
}

Result<void> QtCanBus::checkInterface(const QString &plugin, const QString &interfaceName)
{
    if (!QCanBus::instance()->plugins().contains(plugin))
        return Error(Error::Kind::NotSupported,
                     Tr::tr("no Qt CAN plugin '%1' for interface %2 (available plugins: %3)")
                         .arg(plugin, interfaceName, joined(availablePlugins())));
    QString listError;
    const QStringList interfaces = availableInterfaces(plugin, &listError);
    // A plugin that lists nothing may still take any name (socketcan before the interface is
    // up): then its open call says what is wrong.
    if (!interfaces.isEmpty() && !interfaces.contains(interfaceName))
        return Error(Error::Kind::HostNotFound,
                     Tr::tr("CAN interface '%1' does not exist for plugin %2 (available: %3)")
                         .arg(interfaceName, plugin, joined(interfaces)));
    return {};
}

void QtCanBus::doOpen()
{
    if (auto checked = checkInterface(m_plugin, m_interface); !checked) {
        failLater(checked.error());
        return;
    }
    QString createError;
    m_device = QCanBus::instance()->createDevice(m_plugin, m_interface, &createError);
    if (!m_device) {
        failLater(Error(
            Error::Kind::HostNotFound,
            Tr::tr("cannot create %1 interface '%2': %3 (available: %4)")
                .arg(m_plugin, m_interface, createError, joined(availableInterfaces(m_plugin)))));
        return;
    }
    // Some plugins refuse an interface already while creating the device and only note it in
    // the device's error state (virtualcan: "Invalid interface"); connecting would then open
    // another interface than the one asked for.
    if (m_device->error() != QCanBusDevice::NoError) {
        const QString why = m_device->errorString();
        releaseDevice();
        failLater(
            Error(Error::Kind::HostNotFound,
                  Tr::tr("cannot use %1 interface '%2': %3 (available: %4)")
                      .arg(m_plugin, m_interface, why, joined(availableInterfaces(m_plugin)))));
        return;
    }
    m_device->setParent(this);
    connect(m_device, &QCanBusDevice::stateChanged, this, &QtCanBus::onStateChanged);
    connect(m_device, &QCanBusDevice::errorOccurred, this, &QtCanBus::onError);
    connect(m_device, &QCanBusDevice::framesReceived, this, &QtCanBus::onFramesReceived);
    if (m_bitrate > 0)
        m_device->setConfigurationParameter(QCanBusDevice::BitRateKey, QVariant(m_bitrate));
    m_openError.clear();
    if (!m_device->connectDevice()) {
        // A plugin that fails at once (socketcan without the interface) has reported it from
        // inside connectDevice(), and onStateChanged() has released the device already.
        if (m_device)
            failLater(Error(Error::Kind::ConnectionRefused,
                            Tr::tr("cannot open %1 interface '%2': %3")
                                .arg(m_plugin, m_interface, m_device->errorString())));
        return;
    }
    if (m_device->state() == QCanBusDevice::ConnectedState)
        setOpened();
}

void QtCanBus::doClose()
{
    if (!m_device) {
        setClosed();
        return;
    }
    m_device->disconnectDevice();
    if (m_device && m_device->state() == QCanBusDevice::UnconnectedState) {
        releaseDevice();
        setClosed();
    }
}

void QtCanBus::doSend(const QCanBusFrame &frame)
{
    if (!m_device)
        return;
    if (!m_device->writeFrame(frame)) {
        Q_EMIT warning(Tr::tr("%1: frame %2 not sent: %3")
                           .arg(name(), frame.toString(), m_device->errorString()));
        return;
    }
    qCDebug(lcQtCanRaw).noquote() << name() << "tx" << frame.toString();
    reportSent(frame);
}

void QtCanBus::onStateChanged(QCanBusDevice::CanBusDeviceState state)
{
    if (state == QCanBusDevice::ConnectedState) {
        qCInfo(lcQtCan).noquote() << name() << "open";
        setOpened();
    } else if (state == QCanBusDevice::UnconnectedState) {
        const State was = CanBus::state();
        releaseDevice();
        if (was == State::Closing || was == State::Closed)
            setClosed();
        else if (was == State::Opening && !m_openError.isEmpty())
            setClosed(Error(Error::Kind::ConnectionRefused,
                            Tr::tr("cannot open %1 interface '%2': %3")
                                .arg(m_plugin, m_interface, m_openError)));
        else
            setClosed(
                Error(Error::Kind::Disconnected, Tr::tr("%1 closed unexpectedly").arg(name())));
    }
}

void QtCanBus::onError(QCanBusDevice::CanBusError error)
{
    const QString text = m_device ? m_device->errorString() : QString();
    switch (error) {
    case QCanBusDevice::NoError:
        return;
    case QCanBusDevice::ConnectionError:
        if (CanBus::state() == State::Opening) {
            m_openError = text;
            failLater(Error(
                Error::Kind::ConnectionRefused,
                Tr::tr("cannot open %1 interface '%2': %3").arg(m_plugin, m_interface, text)));
            return;
        }
        Q_EMIT warning(Tr::tr("%1: connection error: %2").arg(name(), text));
        return;
    case QCanBusDevice::ConfigurationError:
        Q_EMIT warning(Tr::tr("%1: configuration not applied (bit rate %2): %3")
                           .arg(name())
                           .arg(m_bitrate)
                           .arg(text));
        return;
    default:
        Q_EMIT warning(QStringLiteral("%1: %2").arg(name(), text));
        return;
    }
}

void QtCanBus::onFramesReceived()
{
    if (!m_device)
        return;
    qint64 dropped = 0;
    while (m_device->framesAvailable() > kMaxReceiveQueueFrames) {
        m_device->readFrame();
        ++dropped;
    }
    reportDropped(dropped);
    for (int i = 0; i < kReceiveSliceFrames && m_device && m_device->framesAvailable() > 0; ++i) {
        const QCanBusFrame frame = m_device->readFrame();
        if (frame.frameType() == QCanBusFrame::ErrorFrame) {
            Q_EMIT warning(
                Tr::tr("%1: error frame: %2").arg(name(), m_device->interpretErrorFrame(frame)));
            continue;
        }
        qCDebug(lcQtCanRaw).noquote() << name() << "rx" << frame.toString();
        deliver(frame);
    }
    if (m_device && m_device->framesAvailable() > 0)
        scheduleReceive(); // the rest after timers and sockets had their turn
}

void QtCanBus::scheduleReceive()
{
    if (m_receiveScheduled)
        return;
    m_receiveScheduled = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_receiveScheduled = false;
            onFramesReceived();
        },
        Qt::QueuedConnection);
}

void QtCanBus::releaseDevice()
{
    if (!m_device)
        return;
    m_device->disconnect(this);
    m_device->deleteLater();
    m_device = nullptr;
}

} // namespace db
