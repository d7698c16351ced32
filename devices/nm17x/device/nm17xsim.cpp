#include "nm17xsim.h"

#include "simulatednm17x.h"

#include "transport/device/slcanserver.h"
#include "transport/qtcanbus.h"

#include <QCoreApplication>
#include <QTcpServer>
#include <QTcpSocket>

namespace db::nm17x {

namespace {
constexpr int kVirtualCanOpenMs = 3000;
constexpr int kMaxLineBytes = 1024;
} // namespace

struct Nm17xSim::Private
{
    QList<SimulatedNm17x *> devices; // owned by the Nm17xSim QObject
    std::unique_ptr<SlcanServer> slcan;
    std::unique_ptr<QtCanBus> virtualCan;
    std::unique_ptr<QTcpServer> control;
    int bitrate = 0; // of the SLCAN bus; 0 = any
    bool started = false;
};

Nm17xSim::Nm17xSim(QObject *parent)
    : QObject(parent)
    , d(std::make_unique<Private>())
{ }

Nm17xSim::~Nm17xSim()
{
    qDeleteAll(d->devices); // before the doors they are wired to
    d->devices.clear();
}

Result<QList<SimDeviceSpec>> Nm17xSim::parseDevices(const QString &text)
{
    QList<SimDeviceSpec> specs;
    for (const QString &raw : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString item = raw.trimmed();
        const qsizetype at = item.indexOf(QLatin1Char('@'));
        const auto variant = parseVariant(at < 0 ? item : item.left(at));
        bool ok = at < 0;
        const uint node = at < 0 ? kDeliveryNodeId : item.mid(at + 1).toUInt(&ok);
        if (!variant || !ok || node < 1 || node > 127)
            return Error(
                Error::Kind::InvalidArgument,
                tr("'%1' is not VARIANT@NODE (nm170, nm172 or nm174, node 1..127)").arg(item));
        specs.append({ *variant, canopen::NodeId(node) });
    }
    if (specs.isEmpty())
        return Error(Error::Kind::InvalidArgument,
                     tr("no displays given (e.g. nm172@127,nm174@5)"));
    return specs;
}

void Nm17xSim::create(const QList<SimDeviceSpec> &devices)
{
    quint32 serial = kFirstSerial;
    for (const SimDeviceSpec &spec : devices)
        d->devices.append(new SimulatedNm17x(spec.variant, serial++, spec.node, this));
}

QList<SimulatedNm17x *> Nm17xSim::devices() const
{
    return d->devices;
}

void Nm17xSim::startDevices()
{
    if (d->started)
        return;
    d->started = true;
    // One bus: every display hears what the others send (queued, as frames on a wire are).
    for (SimulatedNm17x *from : d->devices) {
        for (SimulatedNm17x *to : d->devices) {
            if (from != to)
                connect(from, &SimulatedNm17x::transmit, to, &SimulatedNm17x::receive,
                        Qt::QueuedConnection);
        }
    }
    for (SimulatedNm17x *device : d->devices)
        device->start();
}

void Nm17xSim::setBitrate(int bitsPerSecond)
{
    d->bitrate = bitsPerSecond;
}

Result<void> Nm17xSim::startSlcan(quint16 port)
{
    d->slcan = std::make_unique<SlcanServer>();
    d->slcan->setBusBitrate(d->bitrate);
    if (auto listening = d->slcan->listen(port); !listening)
        return listening;
    for (SimulatedNm17x *device : d->devices) {
        connect(d->slcan.get(), &SlcanServer::frameReceived, device, &SimulatedNm17x::receive);
        connect(device, &SimulatedNm17x::transmit, d->slcan.get(), &SlcanServer::send);
    }
    startDevices();
    return {};
}

quint16 Nm17xSim::slcanPort() const
{
    return d->slcan ? d->slcan->port() : 0;
}

Result<void> Nm17xSim::startVirtualCan(const QString &interfaceName)
{
    d->virtualCan = std::make_unique<QtCanBus>(QStringLiteral("virtualcan"), interfaceName);
    QtCanBus *bus = d->virtualCan.get();
    if (auto opened = bus->openAndWait(kVirtualCanOpenMs); !opened)
        return opened.error();
    for (SimulatedNm17x *device : d->devices) {
        connect(bus, &CanBus::frameReceived, device, &SimulatedNm17x::receive);
        connect(device, &SimulatedNm17x::transmit, bus, &CanBus::send);
    }
    startDevices();
    return {};
}

Result<void> Nm17xSim::startControl(quint16 port)
{
    d->control = std::make_unique<QTcpServer>();
    if (!d->control->listen(QHostAddress::LocalHost, port))
        return Error(Error::Kind::Io,
                     tr("control port %1: %2").arg(port).arg(d->control->errorString()));
    connect(d->control.get(), &QTcpServer::newConnection, this, [this] {
        while (QTcpSocket *socket = d->control->nextPendingConnection()) {
            connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
            connect(socket, &QTcpSocket::readyRead, socket, [this, socket] {
                while (socket->canReadLine()) {
                    const QString line = QString::fromUtf8(socket->readLine()).trimmed();
                    socket->write(execute(line).toUtf8() + '\n');
                }
                if (socket->bytesAvailable() > kMaxLineBytes) {
                    socket->write("error: line too long\n");
                    socket->disconnectFromHost();
                }
            });
        }
    });
    return {};
}

quint16 Nm17xSim::controlPort() const
{
    return d->control ? d->control->serverPort() : 0;
}

QString Nm17xSim::execute(const QString &line)
{
    const QStringList words = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    if (words.isEmpty())
        return QStringLiteral("error: ") + tr("empty command");
    const QString command = words.first();
    if (command == QLatin1String("list")) {
        QStringList lines;
        for (int i = 0; i < d->devices.size(); ++i) {
            SimulatedNm17x *dev = d->devices.at(i);
            lines.append(QStringLiteral("%1 %2 serial 0x%3 node %4 position %5 status 0x%6 "
                                        "errors 0x%7 addressing %8")
                             .arg(i + 1)
                             .arg(variantName(dev->variant()))
                             .arg(dev->serial(), 8, 16, QLatin1Char('0'))
                             .arg(dev->nodeId())
                             .arg(dev->position())
                             .arg(dev->statusWord(), 4, 16, QLatin1Char('0'))
                             .arg(dev->errorWord(), 4, 16, QLatin1Char('0'))
                             .arg(dev->inAddressingMode()
                                      ? QStringLiteral("offered %1").arg(dev->offeredNodeId())
                                      : QStringLiteral("no")));
        }
        lines.append(QStringLiteral("ok"));
        return lines.join(QLatin1Char('\n'));
    }
    bool ok = false;
    const int index = words.value(1).toInt(&ok);
    if (!ok || index < 1 || index > d->devices.size())
        return QStringLiteral("error: ") + tr("give a display index 1..%1").arg(d->devices.size());
    SimulatedNm17x *device = d->devices.at(index - 1);
    if (command == QLatin1String("turn") && words.size() == 3) {
        const double delta = words.at(2).toDouble(&ok);
        if (!ok)
            return QStringLiteral("error: ") + tr("'%1' is not a distance").arg(words.at(2));
        device->turnShaft(delta);
        return QStringLiteral("ok");
    }
    if (command == QLatin1String("key") && (words.size() == 3 || words.size() == 4)) {
        const QString side = words.at(2);
        const int ms = words.size() == 4 ? words.at(3).toInt(&ok) : 100;
        if ((side != QLatin1String("left") && side != QLatin1String("right")) || !ok || ms <= 0)
            return QStringLiteral("error: ") + tr("key INDEX left|right [MS]");
        device->pressKey(side == QLatin1String("right") ? 1 : -1, ms);
        return QStringLiteral("ok");
    }
    if (command == QLatin1String("fault") && words.size() == 3) {
        const QString what = words.at(2);
        static const QStringList kFaults = { QStringLiteral("motor"), QStringLiteral("sensor"),
                                             QStringLiteral("blocked"), QStringLiteral("wiring"),
                                             QStringLiteral("none") };
        if (!kFaults.contains(what))
            return QStringLiteral("error: ") + tr("fault INDEX motor|sensor|blocked|wiring|none");
        if (what == QLatin1String("sensor") && device->variant() != Variant::Nm174)
            return QStringLiteral("error: ") + tr("only an NM174 has an external sensor");
        Spindle &spindle = device->spindle();
        spindle.setMotorFault(what == QLatin1String("motor"));
        spindle.setShaftBlocked(what == QLatin1String("blocked"));
        spindle.setWiringReversed(what == QLatin1String("wiring"));
        if (what == QLatin1String("sensor") || what == QLatin1String("none"))
            spindle.setSensorFault(what == QLatin1String("sensor"));
        return QStringLiteral("ok");
    }
    if (command == QLatin1String("glitch") && (words.size() == 3 || words.size() == 4)) {
        bool stepsOk = false;
        const double steps = words.at(2).toDouble(&stepsOk);
        const int readings = words.size() == 4 ? words.at(3).toInt(&ok) : 1;
        if (!stepsOk || !ok || readings < 0)
            return QStringLiteral("error: ") + tr("glitch INDEX STEPS [READINGS]");
        device->disturbSensor(steps, readings);
        return QStringLiteral("ok");
    }
    if (command == QLatin1String("coast") && words.size() == 3) {
        const int ms = words.at(2).toInt(&ok);
        if (!ok || ms < 0 || ms > 10000)
            return QStringLiteral("error: ") + tr("coast INDEX MS (0..10000)");
        device->spindle().motor().coastMs = ms;
        return QStringLiteral("ok");
    }
    if (command == QLatin1String("input") && words.size() == 4) {
        const auto level = [](const QString &w) -> std::optional<bool> {
            if (w == QLatin1String("0") || w == QLatin1String("1"))
                return w == QLatin1String("1");
            return std::nullopt;
        };
        const auto f = level(words.at(2));
        const auto g = level(words.at(3));
        if (!f || !g)
            return QStringLiteral("error: ") + tr("input INDEX F G (each 0 or 1)");
        device->setInputs(*f, *g);
        return QStringLiteral("ok");
    }
    return QStringLiteral("error: ")
        + tr("unknown command '%1' (list, turn, key, fault, input, glitch, coast)").arg(line);
}

QString Nm17xSim::describe() const
{
    QStringList items;
    for (const SimulatedNm17x *device : d->devices)
        items.append(
            QStringLiteral("%1 node %2").arg(variantName(device->variant())).arg(device->nodeId()));
    return items.join(QLatin1String(", "));
}

} // namespace db::nm17x
