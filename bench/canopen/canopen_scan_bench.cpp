// Time to scan node ids 1..127: NodeScanner (pipelined SDO probe of 1000h, then
// 1018h.1-4 and 1008h of each node found) against simulated test nodes behind an SlcanServer, over
// SLCAN-over-TCP on loopback, both in this process. The scan ends when the probes of the absent
// ids time out, so its time is about one SDO timeout; the figure shows how far above it we are.
//   canopen_scan_bench [--nodes 1,2,5,10,64] [--timeout MS] [--repeat N]
#include "canopen/device/simulatednode.h"
#include "canopen/nodemonitor.h"
#include "canopen/nodescanner.h"
#include "canopen/sdoclient.h"
#include "resources/builtindescriptions.h"
#include "transport/device/slcanserver.h"
#include "transport/slcanbus.h"
#include "transport/tcpstream.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLoggingCategory>

#include <cstdio>
#include <memory>
#include <vector>

using namespace db;
using namespace db::canopen;

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("drivebench.*=false")); // figures only
    QList<NodeId> ids { 1, 2, 5, 10, 64 };
    int timeoutMs = SdoClient::kDefaultTimeoutMs;
    int repeat = 3;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i + 1 < args.size(); ++i) {
        if (args.at(i) == u"--timeout")
            timeoutMs = args.at(i + 1).toInt();
        else if (args.at(i) == u"--repeat")
            repeat = args.at(i + 1).toInt();
        else if (args.at(i) == u"--nodes") {
            ids.clear();
            for (const QString &s : args.at(i + 1).split(QLatin1Char(',')))
                ids.append(NodeId(s.toUInt()));
        }
    }
    const auto dict = resources::builtinDescription(QStringLiteral("drivebench_testnode"));
    if (!dict) {
        std::fprintf(stderr, "%s\n", qPrintable(dict.error().toString()));
        return 1;
    }
    SlcanServer server;
    if (const auto ok = server.listen(0); !ok) {
        std::fprintf(stderr, "listen: %s\n", qPrintable(ok.error().toString()));
        return 1;
    }
    std::vector<std::unique_ptr<SimulatedNode>> nodes;
    for (const NodeId id : ids) {
        nodes.push_back(std::make_unique<SimulatedNode>(dict.value(), id));
        QObject::connect(&server, &SlcanServer::frameReceived, nodes.back().get(),
                         &SimulatedNode::receive);
        QObject::connect(nodes.back().get(), &SimulatedNode::transmit, &server, &SlcanServer::send);
        nodes.back()->start();
    }
    SlcanBus bus(new TcpStream(QStringLiteral("127.0.0.1"), server.port()));
    if (auto opened = bus.openAndWait(5000); !opened) {
        std::fprintf(stderr, "%s\n", qPrintable(opened.error().toString()));
        return 1;
    }
    SdoClient sdo(&bus);
    sdo.setTimeoutMs(timeoutMs);
    NodeMonitor monitor(&bus);
    NodeScanner scanner(&sdo, &monitor);
    std::printf("scan of ids 1..127 over %s, %d simulated nodes, SDO timeout %d ms\n",
                qPrintable(bus.name()), int(ids.size()), timeoutMs);
    for (int run = 0; run < repeat; ++run) {
        QEventLoop loop;
        QObject::connect(&scanner, &NodeScanner::finished, &loop, &QEventLoop::quit);
        qint64 lastFound = 0;
        QElapsedTimer clock;
        const auto c = QObject::connect(&scanner, &NodeScanner::nodeFound, &loop,
                                        [&] { lastFound = clock.elapsed(); });
        clock.start();
        scanner.start();
        loop.exec();
        const qint64 ms = clock.elapsed();
        QObject::disconnect(c);
        int complete = 0;
        for (const NodeInfo &n : scanner.nodes())
            complete += n.hasIdentity && !n.name.isEmpty();
        std::printf("  run %d: %lld ms total (%.2f x timeout), last node answered after %lld ms, "
                    "%d nodes listed with identity and name\n",
                    run + 1, ms, double(ms) / timeoutMs, lastFound, complete);
    }
    return 0;
}
