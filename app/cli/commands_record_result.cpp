#include "commands_record_result.h"

#include "scope/csv.h"
#include "scope/pollingsource.h"
#include "scope/recorder.h"
#include "stopsignals.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

namespace db::cli {

namespace {

qint64 totalLost(const scope::Recorder &r)
{
    qint64 n = 0;
    for (int i = 0; i < r.channelCount(); ++i)
        n += r.buffer(i).lostAtSource();
    return n;
}

QString interrupted(int signal)
{
    return Tr::tr("interrupted by %1").arg(StopSignals::name(signal));
}

struct Cause
{
    QString text;
    int exitCode = ExitFailure;
};

// Why a recording holds no sample.
Cause whyEmpty(const RecordOutcome &o)
{
    if (o.signal != 0)
        return { interrupted(o.signal), ExitSignalBase + o.signal };
    if (o.failure.isError())
        return { o.failure.toString(), exitCodeFor(o.failure) };
    if (o.polling && o.polling->failedCount() > 0) {
        const Error &e = o.polling->lastReadError();
        return { Tr::tr("all %1 reads failed, the last: %2")
                     .arg(o.polling->failedCount())
                     .arg(e.toString()),
                 exitCodeFor(e) };
    }
    if (o.polling && o.polling->unansweredAtStop().channel >= 0) {
        const auto unanswered = o.polling->unansweredAtStop();
        const Error e(Error::Kind::Timeout,
                      Tr::tr("the read of %1 got no answer in %2 s")
                          .arg(o.recorder.channelInfo(unanswered.channel).id)
                          .arg(unanswered.waitedS, 0, 'f', 2));
        return { e.toString(), exitCodeFor(e) };
    }
    return { Tr::tr("no sample arrived"), ExitFailure };
}

int report(Context &c, const QString &text, int exitCode)
{
    c.err << "drivebench-cli: " << text << Qt::endl;
    return exitCode;
}

} // namespace

int finishRecording(Context &c, const RecordOutcome &o)
{
    const bool nothingDelivered = o.polling && o.polling->deliveredCount() == 0;
    if (o.triggerTimedOut && !nothingDelivered)
        return fail(c,
                    Error(Error::Kind::Timeout,
                          Tr::tr("trigger %1 did not fire within %2 s; nothing written")
                              .arg(o.trigger)
                              .arg(o.waitS)));
    const scope::Recording rec = o.recorder.recording();
    qint64 samples = 0;
    for (const scope::RecordedChannel &ch : rec.channels)
        samples += ch.buffer.size();
    if (samples == 0 || o.triggerTimedOut) {
        const Cause cause = whyEmpty(o);
        return report(c,
                      Tr::tr("no sample recorded in %1 s, nothing written: %2")
                          .arg(o.elapsedS, 0, 'f', 2)
                          .arg(cause.text),
                      cause.exitCode);
    }
    if (auto saved = scope::csv::save(c.output, rec); !saved)
        return fail(c, saved.error());
    const qint64 lost = totalLost(o.recorder);
    c.out << "recorded " << samples << " samples of " << rec.channels.size() << " objects over "
          << QString::number(rec.endTime() - rec.startTime(), 'f', 3) << " s";
    if (rec.hasTriggerTime())
        c.out << ", triggered at " << QString::number(rec.triggerTime, 'f', 6) << " s";
    c.out << ", " << lost << " lost -> " << c.output << Qt::endl;

    const QString early = Tr::tr("recording stopped early (%1 written)").arg(c.output);
    if (o.signal != 0)
        return report(c, early + QStringLiteral(": ") + interrupted(o.signal),
                      ExitSignalBase + o.signal);
    if (o.failure.isError())
        return fail(c, o.failure.prefixed(early));
    if (o.polling && o.polling->failedCount() > 0) {
        const Error &e = o.polling->lastReadError();
        return report(c,
                      Tr::tr("%1 of %2 reads failed (%3 samples lost in all, gaps are "
                             "marked in %4), the last: %5")
                          .arg(o.polling->failedCount())
                          .arg(o.polling->failedCount() + o.polling->deliveredCount())
                          .arg(lost)
                          .arg(c.output, e.toString()),
                      exitCodeFor(e));
    }
    if (lost > 0) {
        c.err << Tr::tr("drivebench-cli: %1 samples were lost (%2); gaps are marked in %3")
                     .arg(lost)
                     .arg(o.polling ? Tr::tr("the link is slower than --rate-ms asks")
                                    : Tr::tr("PDOs missed their expected period"),
                          c.output)
              << Qt::endl;
        return ExitFailure;
    }
    return ExitOk;
}

} // namespace db::cli
