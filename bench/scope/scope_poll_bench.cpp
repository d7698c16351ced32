// Scope benchmark: host polling with scope::PollingSource and the Recorder
// against the simulated MovingCap of `drivebench --demo` (app::DemoDrive), in this process, over
// RefGo (ASCII over TCP) and over CANopen SDO via SLCAN-over-TCP, both on loopback. Polls 1 and
// 4 objects as fast as the link allows (rate 0, one request in flight per object) and at a fixed
// period, and prints samples/s with the lost-sample count (which must be 0).
//
//   scope_poll_bench [--seconds S] [--rate-ms R] [--uri URI]...
//
// --uri (repeatable) polls those devices instead (they need the objects 6064:0, 6078:0, 606C:0
// and 6041:0, as a MovingCap or any CiA 402 drive has).

#include "common/demodrive.h"
#include "common/protocols.h"
#include "scope/pollingsource.h"
#include "scope/recorder.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QEventLoop>
#include <QLoggingCategory>
#include <QTimer>

#include <cstdio>

using namespace db;

namespace {

constexpr int kConnectMs = 5000;
const ObjectAddress kObjects[] = { { 0x6064, 0 }, { 0x6078, 0 }, { 0x606C, 0 }, { 0x6041, 0 } };

struct Figures
{
    qint64 samples = 0;
    qint64 lost = 0;
    double seconds = 0;
};

Result<Figures> run(const QString &uri, int objects, int rateMs, double seconds)
{
    auto made = app::protocolRegistry().create(uri);
    if (!made)
        return made.error();
    std::shared_ptr<DeviceConnection> connection = *made;
    if (auto opened = connection->openAndWait(kConnectMs); !opened)
        return opened.error();

    scope::PollingSource source(connection.get());
    for (int i = 0; i < objects; ++i) {
        if (auto added = source.addChannel(kObjects[i], rateMs); !added)
            return added.error();
    }
    scope::Recorder recorder;
    recorder.addSource(&source);
    Error failure;
    QObject::connect(&recorder, &scope::Recorder::errorOccurred,
                     [&](const Error &e) { failure = e; });
    QEventLoop wait;
    QTimer::singleShot(int(seconds * 1000), &wait, &QEventLoop::quit);
    QObject::connect(&recorder, &scope::Recorder::stateChanged, &wait,
                     [&](scope::Recorder::State s) {
                         if (s == scope::Recorder::State::Stopped)
                             wait.quit();
                     });
    recorder.start();
    wait.exec();
    const double elapsed = recorder.now();
    recorder.stop();
    if (failure.isError())
        return failure;
    Figures f;
    f.seconds = elapsed;
    for (int i = 0; i < recorder.channelCount(); ++i) {
        f.samples += recorder.buffer(i).size();
        f.lost += recorder.buffer(i).lostAtSource();
    }
    connection->close();
    return f;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("drivebench.*=false"));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Host polling samples/s against the "
                                                    "in-process simulated MovingCap."));
    parser.addHelpOption();
    const QCommandLineOption secondsOption(QStringLiteral("seconds"),
                                           QStringLiteral("Seconds per case (default 3)."),
                                           QStringLiteral("s"), QStringLiteral("3"));
    const QCommandLineOption rateOption(
        QStringLiteral("rate-ms"),
        QStringLiteral("Period of the fixed-rate cases in ms (default 10)."), QStringLiteral("ms"),
        QStringLiteral("10"));
    const QCommandLineOption uriOption(
        QStringLiteral("uri"),
        QStringLiteral("Poll this device instead of the in-process simulator (repeatable)."),
        QStringLiteral("uri"));
    parser.addOptions({ secondsOption, rateOption, uriOption });
    parser.process(app);
    const double seconds = std::max(0.2, parser.value(secondsOption).toDouble());
    const int rateMs = std::max(1, parser.value(rateOption).toInt());

    QList<std::pair<QString, QString>> links;
    for (const QString &uri : parser.values(uriOption))
        links.append({ uri.section(QLatin1Char(':'), 0, 0), uri });
    app::DemoDrive drive;
    if (links.isEmpty()) {
        if (!drive.startRefgo(0).ok() || !drive.startSlcan(0).ok()) {
            std::fprintf(stderr, "scope_poll_bench: cannot start the simulated drive\n");
            return 1;
        }
        links = { { QStringLiteral("refgo"), drive.refgoUri() },
                  { QStringLiteral("canopen+slcan"), drive.slcanUri() } };
    }
    std::printf("%-14s %-8s %-10s %12s %14s %6s\n", "link", "objects", "rate", "samples/s",
                "per object/s", "lost");
    int status = 0;
    for (const auto &[name, uri] : std::as_const(links)) {
        for (int objects : { 1, 4 }) {
            for (int rate : { 0, rateMs }) {
                const auto f = run(uri, objects, rate, seconds);
                if (!f) {
                    std::fprintf(stderr, "scope_poll_bench: %s: %s\n", qPrintable(uri),
                                 qPrintable(f.error().toString()));
                    return 1;
                }
                const double perSecond = double(f->samples) / f->seconds;
                const QString rateText =
                    rate == 0 ? QStringLiteral("max") : QStringLiteral("%1 ms").arg(rate);
                std::printf("%-14s %-8d %-10s %12.0f %14.0f %6lld\n", qPrintable(name), objects,
                            qPrintable(rateText), perSecond, perSecond / objects,
                            static_cast<long long>(f->lost));
                if (f->lost != 0)
                    status = 2;
            }
        }
    }
    return status;
}
