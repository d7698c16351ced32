// VABus/TCP against the simulated ACU (bonfiglioli::SimulatedAcu in this process, loopback):
// parameter reads per second (one telegram in flight, as the protocol requires) and the time of
// a full backup (every data set of every storable parameter), and the scope's host polling of 4
// actual values through the block (17/19) and one read per channel. Median of --repeat runs.
//   vabus_bench [--repeat N] [--reads N] [--port P | --uri vabus://HOST[:PORT]]
// --port P measures a simulator already running on 127.0.0.1:P (drivebench-sim acu --vabus-port
// P), --uri any drive or simulator, instead of the in-process one.
#include "common/protocols.h"
#include "devices/bonfiglioli/simulatedacu.h"
#include "parameters/parameterrunner.h"
#include "scope/pollingsource.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLoggingCategory>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <memory>

using namespace db;

namespace {

double median(QList<double> values)
{
    std::sort(values.begin(), values.end());
    return values.at(values.size() / 2);
}

// Milliseconds for `count` reads of 372:2 queued at once, or -1 on a failure.
double timeReads(DeviceConnection *connection, int count)
{
    QList<Reply *> replies;
    int done = 0;
    bool failed = false;
    QEventLoop loop;
    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < count; ++i) {
        Reply *reply = connection->read(ObjectAddress(372, 2));
        QObject::connect(reply, &Reply::finished, &loop, [&, reply] {
            failed |= !reply->ok();
            if (++done == count)
                loop.quit();
        });
        replies.append(reply);
    }
    loop.exec();
    const double ms = double(clock.nsecsElapsed()) / 1e6;
    qDeleteAll(replies);
    return failed ? -1 : ms;
}

struct PollFigures
{
    double samplesPerS = 0;
    double exchangesPerS = 0;
    qint64 lost = 0;
};

// The scope's host polling of `objects` as fast as the link allows (rate 0) for `ms`, through
// the connection's block (together) or one read per channel.
PollFigures timePolling(DeviceConnection *connection, const QList<ObjectAddress> &objects,
                        bool together, int ms)
{
    scope::PollingSource source(connection);
    for (ObjectAddress address : objects)
        source.addChannel(address, 0);
    source.setReadTogether(together);
    QElapsedTimer timeBase;
    timeBase.start();
    source.start(timeBase);
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
    source.stop();
    const double s = double(timeBase.nsecsElapsed()) / 1e9;
    return { double(source.deliveredCount()) / s, double(source.readCount()) / s,
             source.lostCount() + source.failedCount() };
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("drivebench.*=false")); // figures only
    int repeat = 7;
    int reads = 2000;
    int port = -1;
    QString uri;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        if (args.at(i) == u"--repeat" && i + 1 < args.size())
            repeat = qMax(1, args.at(++i).toInt());
        else if (args.at(i) == u"--reads" && i + 1 < args.size())
            reads = qMax(1, args.at(++i).toInt());
        else if (args.at(i) == u"--port" && i + 1 < args.size())
            port = args.at(++i).toInt();
        else if (args.at(i) == u"--uri" && i + 1 < args.size())
            uri = args.at(++i);
        else {
            std::fprintf(stderr, "vabus_bench: unknown option %s\n", qPrintable(args.at(i)));
            return 2;
        }
    }
    std::unique_ptr<bonfiglioli::SimulatedAcu> acu;
    if (port < 0 && uri.isEmpty()) {
        acu = std::make_unique<bonfiglioli::SimulatedAcu>();
        if (auto ok = acu->listen(0); !ok) {
            std::fprintf(stderr, "%s\n", qPrintable(ok.error().toString()));
            return 1;
        }
        port = acu->port();
    }
    if (uri.isEmpty())
        uri = QStringLiteral("vabus://127.0.0.1:%1").arg(port);
    auto created = app::protocolRegistry().create(uri);
    if (!created) {
        std::fprintf(stderr, "%s\n", qPrintable(created.error().toString()));
        return 1;
    }
    const auto connection = created.value();
    if (auto opened = connection->openAndWait(5000); !opened) {
        std::fprintf(stderr, "%s\n", qPrintable(opened.error().toString()));
        return 1;
    }
    std::printf("VABus/TCP against the simulated ACU (%s), %d runs each, loopback\n",
                acu ? "in this process" : qPrintable(uri), repeat);

    QList<double> rates;
    for (int i = 0; i < repeat; ++i) {
        const double ms = timeReads(connection.get(), reads);
        if (ms < 0) {
            std::fprintf(stderr, "a read failed\n");
            return 1;
        }
        rates.append(reads * 1000.0 / ms);
    }
    std::sort(rates.begin(), rates.end());
    std::printf("reads of 372:2        %5d per run  median %8.0f reads/s  min %8.0f  max %8.0f\n",
                reads, median(rates), rates.first(), rates.last());

    QList<double> backups;
    int objects = 0;
    for (int i = 0; i < repeat; ++i) {
        ParameterBackup backup(connection.get());
        QEventLoop loop;
        QObject::connect(&backup, &ParameterBackup::finished, &loop, &QEventLoop::quit);
        QElapsedTimer clock;
        clock.start();
        backup.start();
        loop.exec();
        backups.append(double(clock.nsecsElapsed()) / 1e6);
        const auto set = backup.result();
        if (!set) {
            std::fprintf(stderr, "backup: %s\n", qPrintable(set.error().toString()));
            return 1;
        }
        objects = set->size();
    }
    std::sort(backups.begin(), backups.end());
    std::printf("full backup           %5d values   median %8.1f ms       min %8.1f  max %8.1f\n",
                objects, median(backups), backups.first(), backups.last());

    // Scope polling: 4 actual values, through the block (one telegram for all) and one by one.
    const QList<ObjectAddress> traced { { 210, 0 }, { 211, 0 }, { 213, 0 }, { 240, 0 } };
    for (const bool together : { true, false }) {
        QList<double> samples;
        QList<double> exchanges;
        qint64 lost = 0;
        for (int i = 0; i < repeat; ++i) {
            const PollFigures f = timePolling(connection.get(), traced, together, 1000);
            samples.append(f.samplesPerS);
            exchanges.append(f.exchangesPerS);
            lost += f.lost;
        }
        std::sort(samples.begin(), samples.end());
        std::sort(exchanges.begin(), exchanges.end());
        std::printf("scope 4 channels, %-6s median %8.0f samples/s  min %8.0f  max %8.0f  "
                    "(%6.0f telegrams/s, %lld lost)\n",
                    together ? "block" : "single", median(samples), samples.first(), samples.last(),
                    median(exchanges), static_cast<long long>(lost));
    }
    connection->close();
    return 0;
}
