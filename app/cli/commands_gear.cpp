// gear URI --ratio N:D --time MS [--acc A --dec D] | gear URI --out [--dec D]
#include "commands_motion_p.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QElapsedTimer>

namespace {
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

namespace db::cli {

using namespace motion;
using namespace motioncmd;

namespace {

const QString kRatio = QStringLiteral("ratio");
const QString kOut = QStringLiteral("out");
const QString kGearAcc = QStringLiteral("acc");
const QString kGearDec = QStringLiteral("dec");
const QString kGearTime = QStringLiteral("time");

// "N:D" -> numerator, denominator (a negative numerator turns the slave the other way).
Result<std::pair<int, int>> parseRatio(const QString &text)
{
    const QStringList parts = text.split(QLatin1Char(':'));
    bool okN = false;
    bool okD = false;
    const int n = parts.size() == 2 ? parts.at(0).trimmed().toInt(&okN) : 0;
    const int d = parts.size() == 2 ? parts.at(1).trimmed().toInt(&okD) : 0;
    if (!okN || !okD)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("--ratio takes NUMERATOR:DENOMINATOR (e.g. 3:2), not '%1'").arg(text));
    if (n == 0 || d < 1)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("--ratio %1: the numerator must not be 0 and the denominator must be "
                            "at least 1")
                         .arg(text));
    return std::pair { n, d };
}

// The ramps given with --acc / --dec (0: the drive's own).
Result<void> ramps(Context &c, MoveParams &p)
{
    for (const auto &[name, field] :
         { std::pair { kGearAcc, &p.acceleration }, { kGearDec, &p.deceleration } }) {
        if (!c.parser->isSet(name))
            continue;
        const auto v = number(c, name);
        if (!v || *v < 0)
            return Error(Error::Kind::InvalidArgument,
                         Tr::tr("--%1 takes a ramp >= 0 (units/s²)").arg(name));
        *field = *v;
    }
    return {};
}

int refusedOrFailed(Context &c, const MotionCommand &command)
{
    if (command.refusal() != Refusal::None) {
        c.err << "drivebench-cli: " << command.error().message() << Qt::endl;
        return ExitDeviceError;
    }
    return fail(c, command.error());
}

} // namespace

QList<QCommandLineOption> gearOptions()
{
    return {
        QCommandLineOption(kRatio,
                           Tr::tr("gear: slave turns per master turn, NUMERATOR:DENOMINATOR."),
                           QStringLiteral("n:d")),
        QCommandLineOption(kOut, Tr::tr("gear: uncouple a gear started elsewhere.")),
    };
}

// MC_GearIn with the ratio and ramps, waits for "in gear", keeps the gear for --time ms, then
// MC_GearOut (the drive brakes the slave to a stop); --out only uncouples.
int gear(Context &c)
{
    const bool out = c.parser->isSet(kOut);
    if (out == c.parser->isSet(kRatio))
        return fail(c,
                    Error(Error::Kind::InvalidArgument,
                          Tr::tr("gear takes --ratio N:D --time MS, or --out")));
    std::pair<int, int> ratio { 1, 1 };
    double timeMs = 0;
    if (!out) {
        const auto r = parseRatio(c.parser->value(kRatio));
        if (!r)
            return fail(c, r.error());
        ratio = r.value();
        const auto t = c.parser->isSet(kGearTime)
            ? number(c, kGearTime)
            : Result<double>(Error(Error::Kind::InvalidArgument,
                                   Tr::tr("gear --ratio needs --time MS: how "
                                          "long the axis follows its master")));
        if (!t || *t < 0)
            return fail(c,
                        t ? Error(Error::Kind::InvalidArgument, Tr::tr("--time takes ms >= 0"))
                          : t.error());
        timeMs = *t;
    }
    MoveParams p;
    p.gearNumerator = ratio.first;
    p.gearDenominator = ratio.second;
    if (auto given = ramps(c, p); !given)
        return fail(c, given.error());
    auto opened = openAxis(c);
    if (!opened)
        return fail(c, opened.error());
    Axis &axis = *opened.value();
    const auto supervision = superviseDrive(c, axis);
    const RestoreSupervision restore { supervision.get(), c };

    if (!out) {
        MotionCommand gearIn(axis.model.get(), CommandKind::GearIn);
        gearIn.setParams(p);
        QElapsedTimer coupling;
        coupling.start();
        if (const int rc = runToEnd(c, axis, gearIn); rc != ExitOk)
            return rc;
        c.out << Tr::tr("in gear %1:%2 after %3 ms")
                     .arg(ratio.first)
                     .arg(ratio.second)
                     .arg(coupling.elapsed())
              << Qt::endl;
        const QDeadlineTimer until { qint64(timeMs) };
        waitUntil(
            axis,
            [&] {
                return until.hasExpired() || gearIn.status() == MotionCommand::Status::Error
                    || gearIn.status() == MotionCommand::Status::CommandAborted;
            },
            int(timeMs) + 1000);
        if (gearIn.status() == MotionCommand::Status::Error
            || gearIn.status() == MotionCommand::Status::CommandAborted)
            return refusedOrFailed(c, gearIn);
    }
    MotionCommand gearOut(axis.model.get(), CommandKind::GearOut);
    gearOut.setParams(p);
    gearOut.setExecute(true);
    if (!waitUntil(
            axis, [&] { return gearOut.isFinished(); }, axis.waitMs)) {
        axis.model->stopNow();
        return fail(c,
                    Error(Error::Kind::Timeout,
                          Tr::tr("MC_GearOut: the axis did not stop within %1 ms (--wait); "
                                 "quick stop")
                              .arg(axis.waitMs)));
    }
    if (gearOut.status() != MotionCommand::Status::Done)
        return refusedOrFailed(c, gearOut);
    printPosition(c, axis);
    return ExitOk;
}

} // namespace db::cli
