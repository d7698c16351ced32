// SDO benchmark: the SdoClient against a SimulatedNode served by an
// SlcanServer, over SLCAN-over-TCP on loopback, both in this process. Prints expedited round
// trips per second with latency percentiles (a p99 near 40 ms would show Nagle/delayed-ACK
// stalls), and segmented and block throughput for a 100 kB domain, both directions.
//
//   canopen_sdo_bench [--count N] [--size BYTES] [--uri URI [--object I:S] [--domain I:S]]
//                     [--expedited-only]
//
// --uri measures a node on another bus or simulator instead (canopen+slcan://HOST:PORT?node=N,
// canopen+socketcan://IFACE?node=N, ...): expedited uploads of --object (default 1000:0, which
// every CANopen device has), and the throughput cases only with --domain, a writable domain or
// string object (its value is overwritten).

#include "canopen/canbusfactory.h"
#include "canopen/canopenconnection.h"
#include "canopen/device/simulatednode.h"
#include "canopen/sdoclient.h"
#include "transport/device/slcanserver.h"
#include "transport/slcanbus.h"
#include "transport/tcpstream.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLoggingCategory>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <memory>

using namespace db;
using namespace db::canopen;

namespace {

constexpr NodeId kNode = 50;
constexpr ObjectAddress kValue { 0x2000, 0 };
constexpr ObjectAddress kDomain { 0x2F00, 0 };
constexpr int kStallMs = 30; // a round trip this slow means a TCP stall, not the engine

ObjectDictionary benchDictionary()
{
    ObjectDictionary dict;
    ObjectDef v;
    v.address = kValue;
    v.name = QStringLiteral("bench value");
    v.type = DataType::Unsigned32;
    v.defaultValue = QVariant::fromValue<qulonglong>(0x12345678);
    dict.insert(v);
    ObjectDef d;
    d.address = kDomain;
    d.name = QStringLiteral("bench domain");
    d.type = DataType::Domain;
    dict.insert(d);
    ObjectDef type;
    type.address = ObjectAddress(0x1000, 0);
    type.name = QStringLiteral("Device type");
    type.access = Access::ReadOnly;
    dict.insert(type);
    return dict;
}

Result<QVariant> await(Reply *reply)
{
    return Reply::wait(reply, 120000);
}

// Expedited uploads one after another, the next one sent from the previous one's handler (no
// Reply per request, as fixed-rate polling reads).
void expedited(SdoClient &sdo, NodeId node, ObjectAddress object, int count)
{
    struct State
    {
        SdoClient *sdo = nullptr;
        NodeId node = 0;
        ObjectAddress object;
        int count = 0;
        QList<double> latencies;
        QEventLoop loop;
        QElapsedTimer one;
        int done = 0;
        int failed = 0;

        void next()
        {
            one.start();
            // The handler captures one pointer, so std::function holds it without allocating.
            sdo->upload(node, object,
                        Completion(&loop, [this](const Result<QVariant> &r) { finished(r); }),
                        SdoClient::Mode::Expedited);
        }
        void finished(const Result<QVariant> &result)
        {
            latencies.append(double(one.nsecsElapsed()) / 1e6);
            failed += result.ok() ? 0 : 1;
            if (++done < count)
                next();
            else
                loop.quit();
        }
    } state;
    state.sdo = &sdo;
    state.node = node;
    state.object = object;
    state.count = count;
    state.latencies.reserve(count);
    QElapsedTimer total;
    const std::clock_t cpuStart = std::clock();
    total.start();
    state.next();
    state.loop.exec();
    const double seconds = total.nsecsElapsed() / 1e9;
    const double cpuUs = double(std::clock() - cpuStart) * 1e6 / CLOCKS_PER_SEC / count;
    QList<double> &latencies = state.latencies;
    std::sort(latencies.begin(), latencies.end());
    const auto pct = [&](double p) {
        return latencies.at(qMin(qsizetype(p * latencies.size()), latencies.size() - 1));
    };
    const auto stalls = std::count_if(latencies.cbegin(), latencies.cend(),
                                      [](double ms) { return ms >= kStallMs; });
    std::printf("expedited upload:   %d round trips in %.3f s = %.0f/s, cpu %.1f us per round "
                "trip  (failed %d)\n",
                count, seconds, count / seconds, cpuUs, state.failed);
    std::printf("  latency ms: p50 %.3f  p90 %.3f  p99 %.3f  max %.3f  stalls >= %d ms: %ld\n",
                pct(0.5), pct(0.9), pct(0.99), latencies.last(), kStallMs, long(stalls));
}

void throughput(SdoClient &sdo, NodeId node, ObjectAddress domain, const char *name,
                SdoClient::Mode mode, const QByteArray &data)
{
    QElapsedTimer t;
    t.start();
    const auto w = await(sdo.download(node, domain, data, mode));
    const double down = t.nsecsElapsed() / 1e9;
    t.start();
    const auto r = await(sdo.upload(node, domain, mode));
    const double up = t.nsecsElapsed() / 1e9;
    const bool same = r.ok() && r->toByteArray() == data;
    std::printf("%-10s download %6lld B in %7.3f s = %8.1f kB/s %s\n", name, qlonglong(data.size()),
                down, data.size() / down / 1000.0, w.ok() ? "" : qPrintable(w.error().toString()));
    std::printf("%-10s upload   %6lld B in %7.3f s = %8.1f kB/s %s\n", name, qlonglong(data.size()),
                up, data.size() / up / 1000.0,
                same ? "(data verified)"
                     : qPrintable(r.ok() ? QStringLiteral("DATA DIFFERS") : r.error().toString()));
}

int fail(const QString &message)
{
    std::fprintf(stderr, "canopen_sdo_bench: %s\n", qPrintable(message));
    return 1;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("drivebench.*=false")); // figures only
    int count = 20000;
    int size = 100 * 1024;
    QString uriText;
    QString objectText;
    QString domainText;
    bool expeditedOnly = false;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        const bool hasValue = i + 1 < args.size();
        if (args.at(i) == u"--count" && hasValue)
            count = qMax(1, args.at(++i).toInt());
        else if (args.at(i) == u"--size" && hasValue)
            size = qMax(1, args.at(++i).toInt());
        else if (args.at(i) == u"--uri" && hasValue)
            uriText = args.at(++i);
        else if (args.at(i) == u"--object" && hasValue)
            objectText = args.at(++i);
        else if (args.at(i) == u"--domain" && hasValue)
            domainText = args.at(++i);
        else if (args.at(i) == u"--expedited-only")
            expeditedOnly = true;
        else
            return fail(QStringLiteral("unknown option %1").arg(args.at(i)));
    }

    NodeId node = kNode;
    ObjectAddress object = kValue;
    ObjectAddress domain = kDomain;
    std::unique_ptr<SimulatedNode> simulated;
    std::unique_ptr<SlcanServer> server;
    std::unique_ptr<CanBus> bus;
    if (uriText.isEmpty()) {
        simulated = std::make_unique<SimulatedNode>(benchDictionary(), kNode);
        server = std::make_unique<SlcanServer>();
        if (const auto ok = server->listen(0); !ok)
            return fail(ok.error().toString());
        QObject::connect(server.get(), &SlcanServer::frameReceived, simulated.get(),
                         &SimulatedNode::receive);
        QObject::connect(simulated.get(), &SimulatedNode::transmit, server.get(),
                         &SlcanServer::send);
        simulated->start();
        bus =
            std::make_unique<SlcanBus>(new TcpStream(QStringLiteral("127.0.0.1"), server->port()));
    } else {
        const auto uri = ConnectionUri::parse(uriText);
        if (!uri)
            return fail(uri.error().toString());
        const auto made = CanBusFactory::makeBus(*uri);
        if (!made)
            return fail(made.error().toString());
        bus.reset(*made);
        const auto id = CanopenConnection::nodeFromUri(*uri);
        if (!id)
            return fail(id.error().toString());
        node = *id;
        object = CanopenConnection::kDeviceType;
    }
    if (!objectText.isEmpty()) {
        const auto parsed = ObjectAddress::parse(objectText);
        if (!parsed)
            return fail(parsed.error().toString());
        object = *parsed;
    }
    if (!domainText.isEmpty()) {
        const auto parsed = ObjectAddress::parse(domainText);
        if (!parsed)
            return fail(parsed.error().toString());
        domain = *parsed;
    }
    const bool throughputCases = !expeditedOnly && (simulated || !domainText.isEmpty());

    if (auto opened = bus->openAndWait(5000); !opened)
        return fail(opened.error().toString());
    SdoClient sdo(bus.get());
    std::printf("SDO over %s, node %d (%s), object %s\n", qPrintable(bus->name()), node,
                simulated ? "simulated, same process" : "external", qPrintable(object.toString()));

    // Warm-up (connection, allocations).
    if (const auto r = await(sdo.upload(node, object)); !r)
        return fail(QStringLiteral("warm-up failed: %1").arg(r.error().toString()));
    expedited(sdo, node, object, count);
    if (!throughputCases)
        return 0;

    QByteArray data(size, '\0');
    for (int i = 0; i < size; ++i)
        data[i] = char((i * 31 + 7) & 0xFF);
    throughput(sdo, node, domain, "segmented", SdoClient::Mode::Segmented, data);
    throughput(sdo, node, domain, "block", SdoClient::Mode::Block, data);
    return 0;
}
