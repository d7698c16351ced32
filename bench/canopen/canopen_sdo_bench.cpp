// SDO benchmark: the SdoClient against a SimulatedNode served by an
// SlcanServer, over SLCAN-over-TCP on loopback, both in this process. Prints expedited round
// trips per second with latency percentiles (a p99 near 40 ms would show Nagle/delayed-ACK
// stalls), and segmented and block throughput for a 100 kB domain, both directions.
//
//   canopen_sdo_bench [--count N] [--size BYTES]

#include "canopen/device/simulatednode.h"
#include "canopen/sdoclient.h"
#include "transport/device/slcanserver.h"
#include "transport/slcanbus.h"
#include "transport/tcpstream.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <algorithm>
#include <cstdio>

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

// Expedited uploads one after another, the next one sent from the previous one's finished().
void expedited(SdoClient &sdo, int count)
{
    QList<double> latencies;
    latencies.reserve(count);
    QEventLoop loop;
    QElapsedTimer total;
    QElapsedTimer one;
    int done = 0;
    int failed = 0;
    std::function<void()> next = [&] {
        one.start();
        Reply *r = sdo.upload(kNode, kValue, SdoClient::Mode::Expedited);
        QObject::connect(r, &Reply::finished, &loop, [&, r] {
            latencies.append(one.nsecsElapsed() / 1e6);
            failed += r->ok() ? 0 : 1;
            r->deleteLater();
            if (++done < count)
                next();
            else
                loop.quit();
        });
    };
    total.start();
    next();
    loop.exec();
    const double seconds = total.nsecsElapsed() / 1e9;
    std::sort(latencies.begin(), latencies.end());
    const auto pct = [&](double p) {
        return latencies.at(qMin(qsizetype(p * latencies.size()), latencies.size() - 1));
    };
    const auto stalls = std::count_if(latencies.cbegin(), latencies.cend(),
                                      [](double ms) { return ms >= kStallMs; });
    std::printf("expedited upload:   %d round trips in %.3f s = %.0f/s  (failed %d)\n", count,
                seconds, count / seconds, failed);
    std::printf("  latency ms: p50 %.3f  p90 %.3f  p99 %.3f  max %.3f  stalls >= %d ms: %ld\n",
                pct(0.5), pct(0.9), pct(0.99), latencies.last(), kStallMs, long(stalls));
}

void throughput(SdoClient &sdo, const char *name, SdoClient::Mode mode, const QByteArray &data)
{
    QElapsedTimer t;
    t.start();
    const auto w = await(sdo.download(kNode, kDomain, data, mode));
    const double down = t.nsecsElapsed() / 1e9;
    t.start();
    const auto r = await(sdo.upload(kNode, kDomain, mode));
    const double up = t.nsecsElapsed() / 1e9;
    const bool same = r.ok() && r->toByteArray() == data;
    std::printf("%-10s download %6lld B in %7.3f s = %8.1f kB/s %s\n", name, qlonglong(data.size()),
                down, data.size() / down / 1000.0, w.ok() ? "" : qPrintable(w.error().toString()));
    std::printf("%-10s upload   %6lld B in %7.3f s = %8.1f kB/s %s\n", name, qlonglong(data.size()),
                up, data.size() / up / 1000.0,
                same ? "(data verified)"
                     : qPrintable(r.ok() ? QStringLiteral("DATA DIFFERS") : r.error().toString()));
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    int count = 20000;
    int size = 100 * 1024;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i + 1 < args.size(); ++i) {
        if (args.at(i) == u"--count")
            count = args.at(i + 1).toInt();
        else if (args.at(i) == u"--size")
            size = args.at(i + 1).toInt();
    }

    SimulatedNode node(benchDictionary(), kNode);
    SlcanServer server;
    if (const auto ok = server.listen(0); !ok) {
        std::fprintf(stderr, "listen: %s\n", qPrintable(ok.error().toString()));
        return 1;
    }
    QObject::connect(&server, &SlcanServer::frameReceived, &node, &SimulatedNode::receive);
    QObject::connect(&node, &SimulatedNode::transmit, &server, &SlcanServer::send);
    node.start();

    SlcanBus bus(new TcpStream(QStringLiteral("127.0.0.1"), server.port()));
    if (auto opened = bus.openAndWait(5000); !opened) {
        std::fprintf(stderr, "%s\n", qPrintable(opened.error().toString()));
        return 1;
    }
    SdoClient sdo(&bus);
    std::printf("SDO over %s, node %d (simulated, same process)\n", qPrintable(bus.name()), kNode);

    // Warm-up (connection, allocations).
    if (const auto r = await(sdo.upload(kNode, kValue)); !r) {
        std::fprintf(stderr, "warm-up failed: %s\n", qPrintable(r.error().toString()));
        return 1;
    }
    expedited(sdo, count);

    QByteArray data(size, '\0');
    for (int i = 0; i < size; ++i)
        data[i] = char((i * 31 + 7) & 0xFF);
    throughput(sdo, "segmented", SdoClient::Mode::Segmented, data);
    throughput(sdo, "block", SdoClient::Mode::Block, data);
    return 0;
}
