// Time for a full parameter backup: ParameterBackup of every storable object of
// the MovingCap description against the simulated MovingCap (app::DemoDrive, in this process)
// over RefGo and over CANopen SDO on SLCAN-over-TCP, both on loopback. Target: < 1 s each.
//   params_backup_bench [--repeat N] [--pipeline D] [--all] [--uri URI]...
// --all reads every readable object (the CLI's dump) instead of the storable ones. --uri
// (repeatable) backs up those devices (any drivebench URI, e.g. refgo://HOST or
// canopen+slcan://HOST:PORT?node=N&eds=FILE) instead of the in-process simulator.
#include "common/demodrive.h"
#include "common/protocols.h"
#include "parameters/parameterrunner.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLoggingCategory>

#include <algorithm>
#include <cstdio>

using namespace db;

namespace {

std::shared_ptr<DeviceConnection> connect(const QString &uri)
{
    auto created = app::protocolRegistry().create(uri);
    if (!created) {
        std::fprintf(stderr, "%s\n", qPrintable(created.error().toString()));
        return {};
    }
    auto connection = created.value();
    if (auto opened = connection->openAndWait(5000); !opened) {
        std::fprintf(stderr, "%s\n", qPrintable(opened.error().toString()));
        return {};
    }
    return connection;
}

// Returns false when a backup fails; prints one line of figures.
bool measure(const QString &label, const QString &uri, int repeat, int depth,
             ParameterBackup::Scope scope)
{
    const auto connection = connect(uri);
    if (!connection)
        return false;
    QList<double> ms;
    int objects = 0;
    for (int i = 0; i < repeat; ++i) {
        ParameterBackup backup(connection.get());
        backup.setPipelineDepth(depth);
        backup.setScope(scope);
        QEventLoop loop;
        QObject::connect(&backup, &ParameterBackup::finished, &loop, &QEventLoop::quit);
        QElapsedTimer clock;
        clock.start();
        backup.start();
        loop.exec();
        ms.append(double(clock.nsecsElapsed()) / 1e6);
        const auto set = backup.result();
        if (!set) {
            std::fprintf(stderr, "%s: %s\n", qPrintable(label), qPrintable(set.error().toString()));
            return false;
        }
        objects = set->size();
    }
    std::sort(ms.begin(), ms.end());
    const double median = ms.at(ms.size() / 2);
    std::printf("%-22s %4d objects  median %7.1f ms  min %7.1f ms  max %7.1f ms  "
                "(%.3f ms/object, pipeline %d)  %s\n",
                qPrintable(label), objects, median, ms.first(), ms.last(), median / objects, depth,
                median < 1000.0 ? "< 1 s: ok" : ">= 1 s: MISSED");
    connection->close();
    return true;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("drivebench.*=false")); // figures only
    int repeat = 7;
    int depth = ParameterBackup::kDefaultPipelineDepth;
    auto scope = ParameterBackup::Scope::Storable;
    QStringList uris;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        if (args.at(i) == u"--repeat" && i + 1 < args.size())
            repeat = qMax(1, args.at(++i).toInt());
        else if (args.at(i) == u"--pipeline" && i + 1 < args.size())
            depth = args.at(++i).toInt();
        else if (args.at(i) == u"--all")
            scope = ParameterBackup::Scope::Readable;
        else if (args.at(i) == u"--uri" && i + 1 < args.size())
            uris.append(args.at(++i));
        else {
            std::fprintf(stderr, "params_backup_bench: unknown option %s\n",
                         qPrintable(args.at(i)));
            return 2;
        }
    }
    const char *what =
        scope == ParameterBackup::Scope::Storable ? "storable objects" : "all readable";
    if (!uris.isEmpty()) {
        std::printf("full backup (%s), %d runs each\n", what, repeat);
        for (const QString &uri : std::as_const(uris)) {
            if (!measure(uri, uri, repeat, depth, scope))
                return 1;
        }
        return 0;
    }
    app::DemoDrive demo;
    if (auto ok = demo.startRefgo(0); !ok) {
        std::fprintf(stderr, "%s\n", qPrintable(ok.error().toString()));
        return 1;
    }
    if (auto ok = demo.startSlcan(0); !ok) {
        std::fprintf(stderr, "%s\n", qPrintable(ok.error().toString()));
        return 1;
    }
    std::printf("full backup of the MovingCap (%s), %d runs each, loopback\n", what, repeat);
    const bool ok = measure(QStringLiteral("RefGo"), demo.refgoUri(), repeat, depth, scope)
        && measure(QStringLiteral("CANopen SDO over SLCAN"), demo.slcanUri(), repeat, depth, scope);
    return ok ? 0 : 1;
}
