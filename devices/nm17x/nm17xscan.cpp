#include "nm17xscan.h"

#include "canopen/cannetworkpool.h"
#include "canopen/sdoclient.h"
#include "transport/canbus.h"

#include <QCoreApplication>
#include <QTimer>

namespace db::nm17x {

namespace {
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(Nm17x)
};
} // namespace

struct BitrateScan::Private
{
    ConnectionUri uri;
    QList<int> bitrates;
    int openMs = kDefaultOpenMs;
    int sdoMs = kDefaultSdoMs;
    int index = -1;
    bool running = false;
    // Kept until the scan ends: a bus closes after its look, its network goes with the scan.
    std::vector<std::shared_ptr<canopen::CanNetwork>> networks;
    std::unique_ptr<Nm17xLine> line;
    QTimer openTimer;
    QList<BitrateResult> results;
};

BitrateScan::BitrateScan(const ConnectionUri &uri, const QList<int> &bitrates, QObject *parent)
    : QObject(parent)
    , d(std::make_unique<Private>())
{
    d->uri = uri;
    d->bitrates = bitrates;
    d->openTimer.setSingleShot(true);
}

BitrateScan::~BitrateScan()
{
    d->line.reset();
    for (const auto &network : d->networks)
        QObject::disconnect(network.get(), nullptr, this, nullptr);
}

void BitrateScan::setTimeouts(int openMs, int sdoMs)
{
    d->openMs = openMs;
    d->sdoMs = sdoMs;
}

bool BitrateScan::isRunning() const
{
    return d->running;
}

QList<BitrateResult> BitrateScan::results() const
{
    return d->results;
}

QList<int> BitrateScan::answeringBitrates() const
{
    QList<int> rates;
    for (const BitrateResult &r : d->results) {
        if (!r.displays.isEmpty())
            rates.append(r.bitrate);
    }
    return rates;
}

QList<int> BitrateScan::defaultBitrates()
{
    return { 125000, 250000 };
}

Result<QList<int>> BitrateScan::parseBitrates(const QString &text)
{
    QList<int> rates;
    for (const QString &item : text.split(u',', Qt::SkipEmptyParts)) {
        bool ok = false;
        const int b = item.trimmed().toInt(&ok);
        if (!ok || b <= 0)
            return Error(
                Error::Kind::InvalidArgument,
                Tr::tr("'%1' is not a bit rate in bit/s (e.g. 125000,250000)").arg(item.trimmed()));
        rates.append(b);
    }
    if (rates.isEmpty())
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("no bit rate given (e.g. 125000,250000)"));
    return rates;
}

void BitrateScan::start()
{
    if (d->running || d->index >= 0)
        return;
    d->running = true;
    next();
}

void BitrateScan::next()
{
    d->line.reset();
    if (!d->networks.empty() && d->index >= 0)
        d->networks.back()->release();
    if (++d->index >= d->bitrates.size()) {
        d->running = false;
        Q_EMIT finished();
        return;
    }
    BitrateResult result;
    result.bitrate = d->bitrates.at(d->index);
    ConnectionUri at = d->uri;
    at.setQueryValue(QStringLiteral("bitrate"), QString::number(result.bitrate));
    canopen::CanNetworkPool pool; // a pool of its own: the bus is one of this scan's
    auto network = pool.networkFor(at);
    if (!network) {
        result.problem = network.error().message();
        d->results.append(result);
        Q_EMIT bitrateDone(result.bitrate, 0);
        QTimer::singleShot(0, this, &BitrateScan::next);
        return;
    }
    std::shared_ptr<canopen::CanNetwork> net = network.value();
    d->networks.push_back(net);
    net->sdo()->setTimeoutMs(d->sdoMs);
    // The look at one bit rate: open the bus, find the displays, record them.
    const auto look = [this, net, result]() {
        d->openTimer.stop();
        QObject::disconnect(net.get(), nullptr, this, nullptr);
        d->line = std::make_unique<Nm17xLine>(net.get());
        Reply *reply = d->line->findDisplays();
        connect(reply, &Reply::finished, this, [this, reply, result] {
            reply->deleteLater();
            BitrateResult done = result;
            done.displays = reply->value().value<QList<DisplayState>>();
            if (d->line)
                done.problem = d->line->problems().join(QLatin1String("; "));
            d->results.append(done);
            Q_EMIT bitrateDone(done.bitrate, int(done.displays.size()));
            QTimer::singleShot(0, this, &BitrateScan::next);
        });
    };
    const auto giveUp = [this, net, result](const QString &why) {
        d->openTimer.stop();
        QObject::disconnect(net.get(), nullptr, this, nullptr);
        BitrateResult failed = result;
        failed.problem = why;
        d->results.append(failed);
        Q_EMIT bitrateDone(failed.bitrate, 0);
        QTimer::singleShot(0, this, &BitrateScan::next);
    };
    connect(net.get(), &canopen::CanNetwork::opened, this, look);
    connect(net.get(), &canopen::CanNetwork::closed, this,
            [giveUp](const Error &error) { giveUp(error.message()); });
    d->openTimer.disconnect();
    connect(&d->openTimer, &QTimer::timeout, this,
            [this, giveUp] { giveUp(Tr::tr("the bus did not open within %1 ms").arg(d->openMs)); });
    d->openTimer.start(d->openMs);
    net->acquire();
    if (net->isOpen())
        look();
}

} // namespace db::nm17x
