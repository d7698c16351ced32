#include "commands_record.h"

#include "commands_record_pdo.h"
#include "commands_record_result.h"
#include "scope/pdodiscovery.h"
#include "scope/pollingsource.h"
#include "scope/recorder.h"
#include "stopsignals.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

namespace db::cli {

namespace {

constexpr double kDefaultWaitS = 30;
constexpr double kDefaultPostS = 1;
constexpr int kDefaultRateMs = 10;
constexpr int kDefaultEventMs = 10; // --configure-tpdo without --event-ms (and --rate-ms)

Error usage(const QString &text)
{
    return Error(Error::Kind::InvalidArgument, text);
}

// A number of seconds >= 0 from option `name`, or `fallback` when it is not given.
Result<double> seconds(Context &c, const QString &name, double fallback)
{
    if (!c.parser->isSet(name))
        return fallback;
    bool ok = false;
    const double v = c.parser->value(name).toDouble(&ok);
    if (!ok || !std::isfinite(v) || v < 0)
        return usage(Tr::tr("--%1 takes a number of seconds >= 0, not '%2'")
                         .arg(name, c.parser->value(name)));
    return v;
}

struct Settings
{
    QList<ObjectAddress> objects;
    int rateMs = kDefaultRateMs;
    double durationS = -1; // < 0: not given
    QString trigger;
    double preS = 0;
    double postS = kDefaultPostS;
    double waitS = kDefaultWaitS;
    qint64 capacity = scope::TraceBuffer::kDefaultCapacity;
    bool pdo = false; // --pdo or --configure-tpdo: passive PDO sampling instead of polling
    int configureTpdo = -1; // 0-based TPDO number to configure first; -1 = none
    int eventMs = kDefaultEventMs;
};

// A whole number in [min, max] from option `name`.
Result<int> integer(Context &c, const QString &name, int min, int max, const QString &what)
{
    bool ok = false;
    const int v = c.parser->value(name).toInt(&ok);
    if (!ok || v < min || v > max)
        return usage(Tr::tr("--%1 takes %2 (%3..%4), not '%5'")
                         .arg(name, what)
                         .arg(min)
                         .arg(max)
                         .arg(c.parser->value(name)));
    return v;
}

Result<Settings> parseSettings(Context &c)
{
    Settings s;
    // --obj names objects of the device at the URI, in its protocol's address format.
    const auto format = addressFormatFor(c.registry, c.args.at(0));
    if (!format)
        return format.error();
    for (const QString &text : c.parser->values(QStringLiteral("obj"))) {
        for (const QString &item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            const auto address = (*format)->parse(item.trimmed());
            if (!address)
                return address.error();
            if (s.objects.contains(*address))
                return usage(Tr::tr("--obj %1 given twice").arg((*format)->format(*address)));
            s.objects.append(*address);
        }
    }
    if (s.objects.isEmpty())
        return usage(Tr::tr("record needs at least one --obj ADDRESS (e.g. --obj %1)")
                         .arg((*format)->example()));
    if (c.output.isEmpty())
        return usage(Tr::tr("record needs -o FILE.csv"));
    if (c.parser->isSet(QStringLiteral("rate-ms"))) {
        bool ok = false;
        s.rateMs = c.parser->value(QStringLiteral("rate-ms")).toInt(&ok);
        if (!ok || s.rateMs < 0)
            return usage(Tr::tr("--rate-ms takes a number of ms >= 0 (0 = as fast as "
                                "the link allows)"));
    }
    if (c.parser->isSet(QStringLiteral("capacity"))) {
        bool ok = false;
        s.capacity = c.parser->value(QStringLiteral("capacity")).toLongLong(&ok);
        if (!ok || s.capacity < 1)
            return usage(Tr::tr("--capacity takes a number of samples >= 1"));
    }
    s.pdo = c.parser->isSet(QStringLiteral("pdo"));
    if (c.parser->isSet(QStringLiteral("configure-tpdo"))) {
        const auto n = integer(c, QStringLiteral("configure-tpdo"), 1,
                               canopen::PdoConfig::kMaxPerDirection, Tr::tr("a TPDO number"));
        if (!n)
            return n.error();
        s.configureTpdo = *n - 1;
        s.pdo = true;
        s.eventMs =
            c.parser->isSet(QStringLiteral("rate-ms")) && s.rateMs > 0 ? s.rateMs : kDefaultEventMs;
    }
    if (c.parser->isSet(QStringLiteral("event-ms"))) {
        if (s.configureTpdo < 0)
            return usage(Tr::tr("--event-ms goes with --configure-tpdo N"));
        const auto ms =
            integer(c, QStringLiteral("event-ms"), 1, 0xFFFF, Tr::tr("the event timer in ms"));
        if (!ms)
            return ms.error();
        s.eventMs = *ms;
    }
    const auto duration = seconds(c, QStringLiteral("duration"), -1);
    if (!duration)
        return duration.error();
    s.durationS = *duration;
    s.trigger = c.parser->value(QStringLiteral("trigger"));
    if (s.trigger.isEmpty()) {
        if (s.durationS <= 0)
            return usage(Tr::tr("record needs --duration S (> 0) or --trigger SPEC"));
        return s;
    }
    const auto pre = seconds(c, QStringLiteral("pre"), 0);
    const auto post =
        seconds(c, QStringLiteral("post"), s.durationS > 0 ? s.durationS : kDefaultPostS);
    const auto wait = seconds(c, QStringLiteral("wait"), kDefaultWaitS);
    for (const auto *r : { &pre, &post, &wait }) {
        if (!*r)
            return r->error();
    }
    s.preS = *pre;
    s.postS = *post;
    s.waitS = *wait;
    return s;
}

// QTimer takes an int of ms: long durations are capped at ~24 days.
int timerMs(double seconds)
{
    return int(std::min(std::ceil(seconds * 1000), 2.0e9));
}

} // namespace

QList<QCommandLineOption> recordOptions()
{
    return {
        { QStringLiteral("obj"),
          Tr::tr("record: an object to record, as the protocol writes addresses "
                 "(repeatable)."),
          QStringLiteral("address") },
        { QStringLiteral("rate-ms"),
          Tr::tr("record: sample period per object in ms (default 10; 0 = as fast as "
                 "the link allows)."),
          QStringLiteral("ms") },
        { QStringLiteral("duration"),
          Tr::tr("record: seconds to record (with --trigger: the default --post)."),
          QStringLiteral("s") },
        { QStringLiteral("trigger"),
          Tr::tr("record: CHANNEL,CONDITION, e.g. 6064:0,rising,100 or 6041:0,bit3,set."),
          QStringLiteral("spec") },
        { QStringLiteral("pre"), Tr::tr("record: seconds kept before the trigger."),
          QStringLiteral("s") },
        { QStringLiteral("post"), Tr::tr("record: seconds recorded after the trigger."),
          QStringLiteral("s") },
        { QStringLiteral("wait"), Tr::tr("record: longest wait for the trigger in s (default 30)."),
          QStringLiteral("s") },
        { QStringLiteral("capacity"),
          Tr::tr("record: most samples kept per object (default 10000000)."), QStringLiteral("n") },
        { QStringLiteral("pdo"),
          Tr::tr("record: CANopen: sample the objects passively from the TPDOs that "
                 "carry them (writes nothing).") },
        { QStringLiteral("configure-tpdo"),
          Tr::tr("record: CANopen: first map the objects into TPDO N (CHANGES the "
                 "device's PDO configuration), then sample it."),
          QStringLiteral("n") },
        { QStringLiteral("event-ms"),
          Tr::tr("record: event timer of --configure-tpdo in ms (default --rate-ms, "
                 "else 10)."),
          QStringLiteral("ms") },
    };
}

int record(Context &c)
{
    const auto settings = parseSettings(c);
    if (!settings)
        return fail(c, settings.error());
    const Settings &s = *settings;

    Session session(c.registry, c.options);
    if (auto opened = session.open(c.args.at(0)); !opened)
        return fail(c, opened.error());
    std::unique_ptr<scope::TraceSource> source;
    scope::PdoSource *pdoSource = nullptr;
    scope::PollingSource *pollingSource = nullptr;
    scope::PdoChannelPlan plan;
    if (s.pdo) {
        auto made =
            makePdoSource(c, session.connection(), { s.objects, s.configureTpdo, s.eventMs }, plan);
        if (!made)
            return fail(c, made.error());
        pdoSource = made->get();
        source = std::move(made).value();
    } else {
        auto polling = std::make_unique<scope::PollingSource>(session.connection());
        for (ObjectAddress address : s.objects) {
            if (auto added = polling->addChannel(address, s.rateMs); !added)
                return fail(c, added.error());
        }
        pollingSource = polling.get();
        source = std::move(polling);
    }
    scope::Recorder recorder;
    recorder.addSource(source.get());
    recorder.setCapacity(s.capacity);
    if (!s.trigger.isEmpty()) {
        QStringList ids;
        for (const scope::ChannelInfo &info : source->channels())
            ids.append(info.id);
        scope::Trigger base;
        base.preTriggerS = s.preS;
        base.postTriggerS = s.postS;
        const auto trigger =
            scope::Trigger::parse(s.trigger, ids, base, session.connection()->addressFormat());
        if (!trigger)
            return fail(c, trigger.error());
        recorder.setMode(scope::Recorder::Mode::Single);
        recorder.setTrigger(*trigger);
    }

    Error failure;
    bool triggerTimedOut = false;
    QEventLoop loop;
    QObject::connect(&recorder, &scope::Recorder::errorOccurred,
                     [&](const Error &e) { failure = e; });
    QObject::connect(&recorder, &scope::Recorder::stateChanged, &loop,
                     [&](scope::Recorder::State state) {
                         if (state == scope::Recorder::State::Stopped)
                             loop.quit();
                     });
    // --duration: the recorder ends the recording itself, on its own time base.
    QTimer deadline;
    deadline.setSingleShot(true);
    deadline.setTimerType(Qt::PreciseTimer);
    if (s.trigger.isEmpty()) {
        recorder.setDurationS(s.durationS);
    } else {
        QObject::connect(&deadline, &QTimer::timeout, &recorder, [&] {
            if (recorder.state() == scope::Recorder::State::Armed) {
                triggerTimedOut = true;
                recorder.stop();
            }
        });
        deadline.start(timerMs(s.waitS));
    }
    // --pdo: a bounded wait for the first frame, so that a silent node fails with its cause
    // (node not operational, ...).
    const int firstPdoMs = scope::firstPdoTimeoutMs(plan.found);
    QTimer firstPdo;
    firstPdo.setSingleShot(true);
    QObject::connect(&firstPdo, &QTimer::timeout, &recorder, [&] {
        if (pdoSource && pdoSource->framesSeen() == 0)
            recorder.stop();
    });
    if (pdoSource)
        firstPdo.start(firstPdoMs);
    // Ctrl-C and SIGTERM end the recording like --duration does: what was recorded is written.
    int stopSignal = 0;
    StopSignals stopSignals;
    QObject::connect(&stopSignals, &StopSignals::stopRequested, &recorder, [&](int received) {
        if (recorder.isRunning()) {
            stopSignal = received;
            recorder.stop();
        }
    });
    // On stderr: stdout stays the summary that scripts read.
    bool arriving = false;
    QObject::connect(source.get(), &scope::TraceSource::samplesReady, &loop, [&] {
        if (!std::exchange(arriving, true))
            c.err << Tr::tr("recording: samples arriving -> %1 (Ctrl-C stops and writes what "
                            "was recorded)")
                         .arg(c.output)
                  << Qt::endl;
    });
    recorder.start();
    if (recorder.isRunning()) {
        if (!s.trigger.isEmpty())
            c.out << "armed: waiting for " << s.trigger << " (at most " << s.waitS << " s)"
                  << Qt::endl;
        loop.exec();
    }
    const double elapsedS =
        std::isnan(recorder.stoppedAt()) ? recorder.now() : recorder.stoppedAt();
    if (pdoSource && pdoSource->framesSeen() == 0 && !failure.isError() && stopSignal == 0)
        return fail(
            c,
            noPdoError(c, session.connection(), plan,
                       std::min(firstPdoMs, timerMs(s.trigger.isEmpty() ? s.durationS : s.waitS))));
    return finishRecording(c,
                           { recorder, pollingSource, elapsedS, failure, stopSignal,
                             triggerTimedOut, s.trigger, s.waitS });
}

} // namespace db::cli
