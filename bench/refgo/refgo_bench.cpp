// RefGo benchmark: object reads (OR6041,0) one after another, the next one sent when the
// previous one has finished, through the RefgoClient (the engine: a handler per request, as
// fixed-rate polling reads, and a Reply per request) and through the RefGo DeviceConnection
// (what the CLI, the scope and the parameter runner use), against the simulated MovingCap of
// `drivebench --demo` in this process over loopback. Prints round trips per second with latency
// percentiles.
//
//   refgo_bench [--count N] [--uri refgo://HOST[:PORT]] [--object I:S] [--engine-only]
//               [--connection-only]
//
// --uri measures another drive or simulator instead (e.g. drivebench-sim movingcap
// --refgo-port 0); --object is read (default 6041:0, the statusword). --engine-only measures
// the engine with handlers only, --connection-only the connection only.
#include "common/demodrive.h"
#include "common/protocols.h"
#include "core/connectionuri.h"
#include "refgo/refgoclient.h"
#include "refgo/refgoconnection.h"
#include "transport/tcpstream.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLoggingCategory>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>

using namespace db;

namespace {

constexpr int kConnectMs = 5000;

int fail(const QString &message)
{
    std::fprintf(stderr, "refgo_bench: %s\n", qPrintable(message));
    return 1;
}

Result<void> open(ByteStream &stream)
{
    Error failure;
    QEventLoop loop;
    QObject::connect(&stream, &ByteStream::opened, &loop, &QEventLoop::quit);
    QObject::connect(&stream, &ByteStream::closed, &loop, [&](const Error &error) {
        failure = error;
        loop.quit();
    });
    stream.setConnectTimeoutMs(kConnectMs);
    stream.open();
    if (stream.state() == ByteStream::State::Opening)
        loop.exec();
    if (stream.isOpen())
        return {};
    return failure.isError()
        ? failure
        : Error(Error::Kind::Disconnected, QStringLiteral("closed while opening"));
}

// One request: sends it and has `done` called with its result.
using Issue = std::function<void(Completion done)>;

// `count` requests made by `issue`, each sent when the previous one finished; prints one line
// of figures under `label`. False when a request failed.
bool roundTrips(const char *label, int count, const Issue &issue, bool print = true)
{
    struct State
    {
        QList<double> latencies;
        QEventLoop loop;
        QElapsedTimer one;
        int count = 0;
        int done = 0;
        QString failure;
        const Issue *issue = nullptr;

        void next()
        {
            one.start();
            // The handler captures one pointer, so std::function holds it without allocating.
            (*issue)(Completion(&loop, [this](const Result<QVariant> &r) { finished(r); }));
        }
        void finished(const Result<QVariant> &result)
        {
            latencies.append(double(one.nsecsElapsed()) / 1e6);
            if (!result.ok() && failure.isEmpty())
                failure = result.error().toString();
            if (++done < count && failure.isEmpty())
                next();
            else
                loop.quit();
        }
    } state;
    state.latencies.reserve(count);
    state.count = count;
    state.issue = &issue;
    QElapsedTimer total;
    const std::clock_t cpuStart = std::clock();
    total.start();
    state.next();
    state.loop.exec();
    const double seconds = double(total.nsecsElapsed()) / 1e9;
    const double cpuUs = double(std::clock() - cpuStart) * 1e6 / CLOCKS_PER_SEC / count;
    if (!state.failure.isEmpty()) {
        std::fprintf(stderr, "refgo_bench: %s: %s\n", label, qPrintable(state.failure));
        return false;
    }
    if (!print)
        return true;
    QList<double> &latencies = state.latencies;
    std::sort(latencies.begin(), latencies.end());
    const auto pct = [&](double p) {
        return latencies.at(qMin(qsizetype(p * double(latencies.size())), latencies.size() - 1));
    };
    std::printf("%-18s %d round trips in %.3f s = %.0f/s, cpu %.1f us per round trip\n", label,
                count, seconds, count / seconds, cpuUs);
    std::printf("  latency ms: p50 %.3f  p90 %.3f  p99 %.3f  max %.3f\n", pct(0.5), pct(0.9),
                pct(0.99), latencies.last());
    return true;
}

// Requests through an API that returns a Reply: its finished() hands the result on. Each reply
// is deleted when the next one has finished (its finished() has returned by then), which saves a
// deferred-delete event per round trip.
struct ViaReply
{
    std::function<Reply *()> make;
    std::shared_ptr<std::unique_ptr<Reply>> previous = std::make_shared<std::unique_ptr<Reply>>();

    void operator()(Completion done) const
    {
        Reply *r = make();
        QObject::connect(r, &Reply::finished, r,
                         [r, previous = previous.get(), done = std::move(done)]() mutable {
                             const Result<QVariant> result = r->result();
                             previous->reset(r);
                             done.complete(result);
                         });
    }
};

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("drivebench.*=false")); // figures only
    int count = 20000;
    QString uriText;
    ObjectAddress object(0x6041, 0);
    bool engineOnly = false;
    bool connectionOnly = false;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        const bool hasValue = i + 1 < args.size();
        if (args.at(i) == u"--count" && hasValue) {
            count = qMax(1, args.at(++i).toInt());
        } else if (args.at(i) == u"--uri" && hasValue) {
            uriText = args.at(++i);
        } else if (args.at(i) == u"--object" && hasValue) {
            const auto parsed = ObjectAddress::parse(args.at(++i));
            if (!parsed)
                return fail(parsed.error().toString());
            object = *parsed;
        } else if (args.at(i) == u"--engine-only") {
            engineOnly = true;
        } else if (args.at(i) == u"--connection-only") {
            connectionOnly = true;
        } else {
            return fail(QStringLiteral("unknown option %1").arg(args.at(i)));
        }
    }

    std::unique_ptr<app::DemoDrive> demo;
    if (uriText.isEmpty()) {
        demo = std::make_unique<app::DemoDrive>();
        if (auto ok = demo->startRefgo(0); !ok)
            return fail(ok.error().toString());
        uriText = demo->refgoUri();
    }
    const auto uri = app::protocolRegistry().parseUri(uriText);
    if (!uri)
        return fail(uri.error().toString());
    if (uri->scheme() != QLatin1String("refgo"))
        return fail(QStringLiteral("%1 is not a refgo:// URI").arg(uriText));
    std::printf("RefGo reads of %s at %s (%s)\n", qPrintable(object.toString()),
                qPrintable(uri->toString()), demo ? "simulated, same process" : "external");

    if (!connectionOnly) {
        TcpStream stream(uri->host(), quint16(uri->portOr(refgo::RefgoConnection::kDefaultPort)));
        if (auto opened = open(stream); !opened)
            return fail(opened.error().toString());
        refgo::RefgoClient client(&stream);
        const Issue viaHandler = [&](Completion done) {
            client.objectRead(object, std::move(done));
        };
        const Issue viaReply = ViaReply { [&] {
            return client.objectRead(object);
        } };
        if (!roundTrips("warm-up", 1, viaHandler, false)
            || !roundTrips("engine objectRead", count, viaHandler)
            || (!engineOnly && !roundTrips("engine Reply", count, viaReply)))
            return 1;
        stream.close();
    }
    if (engineOnly)
        return 0;

    auto made = app::protocolRegistry().create(uri->toString());
    if (!made)
        return fail(made.error().toString());
    const std::shared_ptr<DeviceConnection> connection = *made;
    if (auto opened = connection->openAndWait(kConnectMs); !opened)
        return fail(opened.error().toString());
    const bool ok = roundTrips("connection read", count, ViaReply { [&] {
                                   return connection->read(object);
                               } });
    connection->close();
    return ok ? 0 : 1;
}
